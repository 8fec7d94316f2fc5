#pragma once
// What the compaction analyzer reads off one frame: its tap and the paper's three global
// values, <Z> (Sec. III: the mean potential energy, i.e. the mean centre height) and the
// stereological fractions phi_b and <phi^c> of the core (stereology.hpp).
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/stereology.hpp"

namespace granpipe::compaction {

struct FramePoint {
  double tap = 0.0;
  double z_mean = 0.0;  // mean centre height above the bottom, in mean radii
  double phi_b = 0.0;   // NaN: undefined for this frame (stereology.hpp)
  double phi_c = 0.0;
  double height_c = 0.0;  // top of phi_c's zone above the bottom, in mean radii
  std::string undefined;  // why phi_b or phi_c is NaN, for a warning ("" when both are defined)
};

// <Z> in mean radii R above the container's bottom (its base, where a driven base
// currently is); NaN for a frame without particles.
double mean_height_in_radii(const Frame& frame);

// Throws InputError naming `where` for a frame without the observable `tap`.
FramePoint measure_frame(const Frame& frame, const StereologySettings& settings,
                         const std::string& where);

}  // namespace granpipe::compaction
