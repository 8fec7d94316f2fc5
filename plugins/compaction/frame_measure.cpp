#include "frame_measure.hpp"

#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe::compaction {

double mean_height_in_radii(const Frame& frame) {
  if (frame.size() == 0) return std::nan("");
  const int v = frame.dim - 1;
  const double bottom = frame.container.wall_at(v, 0);
  return (frame.position().col(v).mean() - bottom) / frame.radius().mean();
}

namespace {

// The taps given since the packing was made: the time axis of every law and spectrum here.
std::int64_t tap_of(const Frame& frame, const std::string& where) {
  const std::string expected =
      ": expected the observable \"tap\" (frames of a tapping source "
      "such as spheres3d_tap), got ";
  const Column* column = frame.observables.find("tap");
  if (!column) throw InputError(where + expected + "a frame without it");
  const auto tap = frame.integer_observable("tap");
  if (!tap) {
    throw InputError(where + expected + "one of type " + to_string(column->property().type) +
                     " with " + std::to_string(column->property().components) +
                     " component(s) (a tap is one integer)");
  }
  if (*tap < 0) throw InputError(where + expected + "tap " + std::to_string(*tap) + " (below 0)");
  return *tap;
}

}  // namespace

FramePoint measure_frame(const Frame& frame, const StereologySettings& settings,
                         const std::string& where) {
  const std::int64_t tap = tap_of(frame, where);
  const GlobalFractions g = global_fractions(frame, settings);
  FramePoint p;
  p.tap = static_cast<double>(tap);
  p.z_mean = mean_height_in_radii(frame);
  p.phi_b = g.phi_b;
  p.phi_c = g.phi_c;
  p.height_c = g.radius > 0.0 ? g.height_c / g.radius : std::nan("");
  if (frame.size() > 0) p.undefined = undefined_fractions(g, settings);
  return p;
}

}  // namespace granpipe::compaction
