#pragma once
// The `dem` source: the engine run from a pipeline. It starts from a saved frame (the
// particles, their species and the container, whose walls become the engine's walls) or
// from a generated loose bed in a cylinder, takes the materials per species and species
// pair, the walls' material, the drive and the time step from its parameters, checks dt
// against the shortest contact time before anything runs, and emits a frame (with the
// contact table) every `save_every` steps, ending early once a stopped bed has relaxed.
#include <memory>

#include "engine.hpp"
#include "granpipe/params.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/property_table.hpp"
#include "time_step.hpp"

namespace granpipe::dem {

inline ChoiceNames<InstructionSet> choice_names(InstructionSet) {
  return {{name_of(InstructionSet::Auto), InstructionSet::Auto},
          {name_of(InstructionSet::Baseline), InstructionSet::Baseline},
          {name_of(InstructionSet::Avx2), InstructionSet::Avx2},
          {name_of(InstructionSet::Avx512), InstructionSet::Avx512}};
}

inline ChoiceNames<ContactLaw> choice_names(ContactLaw) {
  return {{"linear", ContactLaw::Linear}, {"hertz", ContactLaw::Hertz}};
}
inline ChoiceNames<Drive::Form> choice_names(Drive::Form) {
  return {{"sine", Drive::Form::Sine}, {"one_minus_cos", Drive::Form::OneMinusCos}};
}

Schema schema();

class DemSource : public Source {
 public:
  explicit DemSource(const PluginContext& ctx);
  FrameContent content() const override;
  Work work() const override;
  bool next(Frame& frame) override;
  void finish(Results& results) override;

 private:
  // Refuses dt above the documented fraction of the shortest contact time, warns below it.
  void check_dt(const PluginContext& ctx, const ContactTime& shortest);
  // Steps of the run and of its frames, and the relaxation that may end it early.
  void read_schedule(const PluginContext& ctx, const Drive& drive);
  // Advances to the next step at which a frame is due, reporting progress as it goes.
  void run_to(std::int64_t step);
  void report_progress(std::int64_t steps, double seconds);
  void record_timing(std::int64_t steps, double seconds, const StepProfile& before);
  std::int64_t next_frame_step() const;
  // True once the container has stopped and the particles have come to rest (the
  // relaxed_kinetic_energy parameter).
  bool at_rest() const;

  Log& log_;
  Progress& progress_;
  std::unique_ptr<Engine> engine_;
  std::int64_t total_steps_ = 0, save_every_ = 1, first_saved_step_ = 0;
  std::int64_t end_step_ = 0;  // total_steps_, or the step after relaxation was seen
  IndexArray ids_;             // the start's particle ids, kept in every frame
  bool relaxed_ = false;
  double relaxed_kinetic_energy_ = 0.0;
  double kinetic_energy_bound_ = 0.0;  // above it the run has blown up
  StreamedTable timing_;
  bool started_ = false;
};

}  // namespace granpipe::dem
