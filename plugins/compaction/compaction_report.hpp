#pragma once
// What the compaction analyzer reports at the end of a run, from the series of its frames:
// the fits of Eqs. (3) and (4) over the fit range, the steady state with its power
// spectrum, and the ageing squared differences with one Eq. (6) fit per waiting time.
#include <cstdint>
#include <vector>

#include "frame_measure.hpp"
#include "granpipe/log.hpp"
#include "granpipe/results.hpp"

namespace granpipe::compaction {

// One entry per frame, in the order of the frames (taps increasing).
struct Series {
  std::vector<double> tap, z_mean, phi_b, phi_c;
  void add(const FramePoint& p);
  bool empty() const { return tap.empty(); }
};

struct ReportSettings {
  double fit_from = 0.0;
  double fit_to = -1.0;       // negative: the last tap
  double steady_from = -1.0;  // negative: half the last tap
  std::vector<std::int64_t> waiting_times;
};

// `series` not empty.
void report_compaction(const Series& series, const ReportSettings& settings, Results& results,
                       Log& log);

}  // namespace granpipe::compaction
