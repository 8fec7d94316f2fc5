#pragma once
// `stereology`: the 3D tapping paper's packing fractions from exact cuts, per frame and
// over the run: phi_b, phi_c, the vertical and transversal profiles, the lateral and
// central fractions and their increases over the first frame, and the Eq. (7) fit of
// the vertical profile (profile_measure.hpp says what each is).
#include <optional>
#include <vector>

#include "granpipe/log.hpp"
#include "granpipe/mean_profile.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/ramp_means.hpp"
#include "profile_measure.hpp"

namespace granpipe::stereology {

Schema schema();

class StereologyAnalyzer : public Analyzer {
 public:
  explicit StereologyAnalyzer(const PluginContext& ctx);
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  void warn_undefined(const Frame& frame, const ProfileMeasurement& m);
  void add_profiles(Results& results) const;
  void add_mean_fit(Results& results) const;

  ProfileSettings settings_;
  Log& log_;
  long frames_ = 0;
  FirstFrameWarning undefined_;
  double transversal_step_ = 0.0;
  std::optional<ProfileMeasurement> first_;
  GlobalFractions last_;
  std::vector<double> last_vertical_, last_transversal_;
  RunningMean phi_b_, phi_c_, lateral_, central_;
  MeanProfile vertical_, transversal_;
  RampMeans by_leg_{{"phi_b", "phi_c"}, "epsilon", "leg"};
  StreamedTable per_frame_;
};

}  // namespace granpipe::stereology
