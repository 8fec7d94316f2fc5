#include "compaction_analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::compaction {

namespace {
// Fig. 5 draws four; a list of 1e6 passed and wrote a warning per missing tap (70 MB of
// run.log) after the run had been asked to stop.
constexpr std::size_t kMostWaitingTimes = 1000;
}  // namespace

Schema schema() {
  Schema s;
  declare_stereology_settings(s);
  s.real("fit_from", 0.0, "first tap of the fits of Eqs. (3) and (4)").min(0.0).unit("taps");
  s.real("fit_to", -1.0, "last tap of the fits; negative or past it: the last frame's")
      .unit("taps");
  s.real("steady_from", -1.0,
         "the steady state (mean, sigma, power spectrum) starts at this tap; negative: half "
         "the last frame's")
      .unit("taps");
  s.integers("waiting_times", std::vector<std::int64_t>{10, 100, 1000},
             "t_w of the ageing squared differences (<Z>(t_w) - <Z>(t_w + t))^2; a t_w that is "
             "no frame's tap is left out with a warning")
      .min(0)
      .max_length(kMostWaitingTimes);
  return s;
}

namespace {

std::string frame_name(long index, const Frame& frame) {
  return "compaction: frame " + std::to_string(index) + " (step " + std::to_string(frame.step) +
         ")";
}

// The fits and the spectrum need the taps in order.
void check_tap_follows(const std::string& where, double tap, const Series& series) {
  if (series.empty() || tap > series.tap.back()) return;
  std::ostringstream m;
  m << where << ": expected a tap after the previous frame's " << series.tap.back() << ", got "
    << tap;
  throw InputError(m.str());
}

// A t_w given twice would enter the ageing table and its fit twice, shrinking the error bars.
void refuse_repeated(std::vector<std::int64_t> taps, const std::string& param) {
  std::sort(taps.begin(), taps.end());
  const auto twice = std::adjacent_find(taps.begin(), taps.end());
  if (twice != taps.end()) {
    throw InputError(param + ": expected distinct waiting times, got " + std::to_string(*twice) +
                     " more than once");
  }
}

}  // namespace

CompactionAnalyzer::CompactionAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      per_frame_(ctx.stream_table(
          "per_frame", Table({"frame", "tap", "z_mean", "phi_b", "phi_c", "height_c"},
                             "per-frame <Z> (mean centre height above the bottom), phi_b, "
                             "<phi^c> and the top of <phi^c>'s zone, in mean radii R",
                             {"", "", "R", "", "", "R"}))) {
  const Params& p = ctx.params;
  stereology_ = stereology_settings(p, ctx.param("perturbed_factor"));
  report_.fit_from = p.real("fit_from");
  report_.fit_to = p.real("fit_to");
  report_.steady_from = p.real("steady_from");
  report_.waiting_times = p.integers("waiting_times");
  refuse_repeated(report_.waiting_times, ctx.param("waiting_times"));
  if (report_.fit_to >= 0.0 && report_.fit_to <= report_.fit_from) {
    std::ostringstream m;
    m << ctx.param("fit_to") << ": expected a tap after fit_from (" << report_.fit_from
      << ") or a negative value (the last frame's), got " << report_.fit_to;
    throw InputError(m.str());
  }
}

// The laws, the steady state and the ageing are of one epsilon: a ramp's frames made a
// "steady state" of four epsilons and its spectrum, exit 0. The deposition (tap 0, epsilon
// 0) is no tap of the run.
void CompactionAnalyzer::check_one_epsilon(const Frame& frame, double tap,
                                           const std::string& where) {
  const std::optional<double> epsilon = frame.real_observable("epsilon");
  if (!epsilon || tap == 0.0) return;
  if (!epsilon_) {
    epsilon_ = epsilon;
    epsilon_frame_ = "frame " + std::to_string(frames_) + " (tap " + format_number(tap) + ")";
    return;
  }
  if (std::abs(*epsilon - *epsilon_) <= 1e-12 * std::abs(*epsilon_)) return;
  throw InputError(where + ": expected the epsilon of " + epsilon_frame_ + ", " +
                   format_number(*epsilon_) + ", got " + format_number(*epsilon) +
                   " (compaction measures a run at one epsilon; a ramp's steps: stereology's "
                   "by_leg table)");
}

void CompactionAnalyzer::consume(const Frame& frame, FrameCache&) {
  const std::string where = frame_name(frames_, frame);
  const FramePoint p = measure_frame(frame, stereology_, where);
  check_tap_follows(where, p.tap, series_);
  check_one_epsilon(frame, p.tap, where);
  if (!p.undefined.empty()) undefined_.warn(log_, where + ": " + p.undefined);
  series_.add(p);
  per_frame_.add_row({static_cast<double>(frames_), p.tap, p.z_mean, p.phi_b, p.phi_c, p.height_c});
  ++frames_;
}

void CompactionAnalyzer::finish(Results& results) {
  results.add_table("per_frame", per_frame_.table());
  results.add_plot("per_frame", {.table = "per_frame",
                                 .x = "tap",
                                 .y = {"phi_b", "phi_c"},
                                 .xlabel = "tap",
                                 .ylabel = "packing fraction",
                                 .title = "compaction (the paper's Fig. 2)"});
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
  if (series_.empty()) return;  // nothing to fit
  report_compaction(series_, report_, results, log_);
}

}  // namespace granpipe::compaction
