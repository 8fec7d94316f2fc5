#include "frame_measure.hpp"

#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe::compaction {

double mean_height_in_radii(const Frame& frame) {
  if (frame.size() == 0) return std::nan("");
  const int v = frame.dim - 1;
  const double bottom = frame.container.lo[v] + frame.container.wall_offset[v];
  return (frame.position().col(v).mean() - bottom) / frame.radius().mean();
}

FramePoint measure_frame(const Frame& frame, const StereologySettings& settings,
                         const std::string& where) {
  const auto tap = frame.integer_observable("tap");
  if (!tap) {
    throw InputError(where +
                     ": expected the observable \"tap\" (frames of a tapping source such as "
                     "spheres3d_tap), got a frame without it");
  }
  const GlobalFractions g = global_fractions(frame, settings);
  FramePoint p;
  p.tap = static_cast<double>(*tap);
  p.z_mean = mean_height_in_radii(frame);
  p.phi_b = g.phi_b;
  p.phi_c = g.phi_c;
  p.height_c = g.radius > 0.0 ? g.height_c / g.radius : std::nan("");
  if (frame.size() > 0) p.undefined = undefined_fractions(g, settings);
  return p;
}

}  // namespace granpipe::compaction
