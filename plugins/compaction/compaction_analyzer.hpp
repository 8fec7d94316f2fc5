#pragma once
// `compaction`: the global compaction dynamics of one tapping run (the 3D tapping paper,
// Sec. III). Each frame gives a row of <Z>, phi_b and <phi^c> against its tap; the run's
// end gives the fits of Eqs. (3) and (4), the steady state and its power spectrum, and the
// ageing squared differences of Eq. (5). It keeps four numbers per frame (the fits need
// the whole series), never a frame.
#include <optional>
#include <string>

#include "compaction_report.hpp"
#include "granpipe/log.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/stereology.hpp"

namespace granpipe::compaction {

Schema schema();

class CompactionAnalyzer : public Analyzer {
 public:
  explicit CompactionAnalyzer(const PluginContext& ctx);
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  void check_one_epsilon(const Frame& frame, double tap, const std::string& where);

  StereologySettings stereology_;
  ReportSettings report_;
  Log& log_;
  long frames_ = 0;
  FirstFrameWarning undefined_;  // NaN is never a silent answer
  // The first tapped frame's epsilon (and that frame, "frame 1 (tap 1)"), which every later
  // frame must share.
  std::optional<double> epsilon_;
  std::string epsilon_frame_;
  Series series_;
  StreamedTable per_frame_;
};

}  // namespace granpipe::compaction
