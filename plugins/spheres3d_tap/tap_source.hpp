#pragma once
// `spheres3d_tap`: tapped hard spheres in a box with a flat bottom and walls or periodic
// sides (Pugnaloni, Valluzzi & Valluzzi, "Numerical model for granular compaction under
// vertical tapping"). The spheres are deposited sequentially (steepest descent to three
// supports); each tap dilates the packing, z -> z (1 + epsilon), and redeposits it by
// gravity-biased Monte Carlo until the mean height settles.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "deposit.hpp"
#include "epsilon_protocol.hpp"
#include "granpipe/plugin.hpp"
#include "redeposition.hpp"
#include "saved_packing.hpp"
#include "tap_schedule.hpp"

namespace granpipe::spheres3d_tap {

Schema schema();

class TapSource : public Source {
 public:
  explicit TapSource(const PluginContext& ctx);

  FrameContent content() const override;
  bool next(Frame& frame) override;
  Work work() const override { return {static_cast<double>(protocol_.taps()), "taps", true}; }
  void finish(Results& results) override;

 private:
  void start();
  void check_saved_tap(const SavedPacking& saved) const;
  void check_saved_protocol(const SavedPacking& saved) const;
  void check_stopping_rule(double mean_height) const;
  void to_frame(Frame& frame, const TapStats& stats, const EpsilonAt& e) const;
  void record(const TapStats& stats, const EpsilonAt& e);

  Progress& progress_;
  TapBox box_;
  RandomStream deposition_rng_;
  FastRandomStream tap_rng_;
  Redeposition redeposition_;
  SaveSchedule schedule_;
  EpsilonProtocol protocol_;
  bool continue_count_ = false, started_ = false;
  Seeds seeds_;
  // The packing of initial_file, read and checked when the source is made (so that
  // `granpipe validate` refuses a bad one), taken as the start at the first frame.
  std::optional<SavedPacking> saved_;
  std::int64_t n_ = 0, tap_ = 0, unconverged_ = 0;
  std::string eta_param_;  // "source.params.eta", for messages
  std::vector<Eigen::Vector3d> centres_;
  StreamedTable per_tap_;
  double seconds_ = 0.0, trials_ = 0.0;
};

}  // namespace granpipe::spheres3d_tap
