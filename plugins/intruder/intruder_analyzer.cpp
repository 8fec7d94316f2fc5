#include "intruder_analyzer.hpp"

namespace granpipe::intruder {

BedState measure_bed(const Frame& f, const std::string& where) {
  const Eigen::Index n = f.size();
  if (n < 2) {
    throw InputError(where + ": expected an intruder and a bed (2 particles or more), got " +
                     std::to_string(n));
  }
  Eigen::Index big = 0;
  f.radius().maxCoeff(&big);
  const double base = f.container.lo[2] + f.container.wall_offset[2];
  // Centre of mass of the bed: mass ∝ density r³; the frame carries no density, and the
  // bed's particles share one species in the scenes this serves, so r³ weights them.
  const Eigen::ArrayXd weight = f.radius().cube();
  const double total = weight.sum() - weight[big];
  const double moment = (weight * f.position().col(2)).sum() - weight[big] * f.position()(big, 2);
  BedState s;
  s.intruder_height = f.position()(big, 2) - base;
  s.bed_height = moment / total - base;
  Eigen::Index pairs = 0;
  if (f.contacts) pairs = (f.contact_j() >= 0).count();
  s.coordination = 2.0 * static_cast<double>(pairs) / static_cast<double>(n);
  return s;
}

IntruderAnalyzer::IntruderAnalyzer(const PluginContext& ctx)
    : per_frame_(ctx.stream_table(
          "per_frame", Table({"frame", "time", "intruder_height", "bed_height", "coordination"},
                             "intruder and bed centre-of-mass heights above the base, mean "
                             "coordination number, per frame"))) {}

void IntruderAnalyzer::consume(const Frame& frame, FrameCache&) {
  const BedState s = measure_bed(frame, "frame " + std::to_string(frames_));
  per_frame_.add_row({static_cast<double>(frames_), frame.time, s.intruder_height, s.bed_height,
                      s.coordination});
  ++frames_;
}

void IntruderAnalyzer::finish(Results& results) {
  results.add_table("per_frame", per_frame_.table());
  results.add_plot("heights", {.table = "per_frame", .x = "time",
                               .y = {"intruder_height", "bed_height"}, .xlabel = "time",
                               .ylabel = "height above the base",
                               .title = "intruder and bed centre of mass"});
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
}

}  // namespace granpipe::intruder
