#pragma once
// The `arches` analyzer: mutual stability, arches and support coordination of 2D
// pseudo-dynamics packings (Sections II and III of the 2D tapping paper), per frame and
// averaged over frames. Memory does not grow with the number of frames, apart from one
// short row of per-frame values.
#include <filesystem>
#include <utility>
#include <vector>

#include "granpipe/log.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/ramp_means.hpp"
#include "mutual_stability.hpp"
#include "span_histogram.hpp"

namespace granpipe::arches {

Schema schema();

class ArchesAnalyzer : public Analyzer {
 public:
  explicit ArchesAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override { return {.dim = 2, .columns = {supports_property()}}; }
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;
  std::vector<Property> publishes() const override { return {arch_property()}; }
  void publish(PropertyTable& columns) override { columns.get<IndexArray>("arch") = arch_of_; }

 private:
  void add_size_distribution(const std::vector<Eigen::Index>& n, double disks);
  void warn_undefined() const;

  Log& log_;
  OutputFiles files_;       // arches_<tap>.svg, under the analyzer's name in the pipeline
  std::string provenance_;  // the run's, for the pictures
  double tolerance_;
  FirstFrameWarning coarse_;       // positions rounded coarser than the contact tolerance
  FirstFrameWarning no_contacts_;  // frames whose disks touch nothing
  double span_bin_;
  long svg_frames_;

  long frames_ = 0;           // frames consumed
  long measured_frames_ = 0;  // frames with at least one disk
  long drawn_ = 0;
  RunningMean arches_per_particle_, p1_, p2_, z_eq4_, z_direct_, z_difference_, base_fraction_,
      missing_supports_, non_supporting_, detached_;
  std::vector<RunningMean> n_per_particle_;  // index s
  std::vector<std::pair<long, SpanHistogram>> span_by_size_;
  SpanHistogram span_all_;
  StreamedTable per_frame_;
  IndexArray arch_of_;  // of the last frame consumed, for publish()
  RampMeans by_ramp_{{"z_support_eq4", "z_support_direct", "arches_per_particle"}};
};

}  // namespace granpipe::arches
