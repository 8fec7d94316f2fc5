#pragma once
// The `dem` source: the engine run from a pipeline. It starts from a saved frame (the
// particles, their species and the container, whose walls become the engine's walls),
// takes the materials per species and species pair, the walls' material, the drive and
// the time step from its parameters, checks dt against the shortest contact time before
// anything runs, and emits a frame (with the contact table) every `save_every` steps.
#include <memory>
#include <optional>

#include "engine.hpp"
#include "granpipe/params.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe::dem {

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

 private:
  Log& log_;
  Progress& progress_;
  std::unique_ptr<Engine> engine_;
  std::int64_t total_steps_ = 0, save_every_ = 1;
  bool emitted_initial_ = false;
};

}  // namespace granpipe::dem
