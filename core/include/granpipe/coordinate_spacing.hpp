#pragma once
// How finely a frame's positions are known: the spacing of doubles at its largest
// coordinate. A length or a centre computed from positions errs by a few of it, so a frame
// moved far from the origin loses the ties and the faces its values sat on exactly; the
// analyzers that compare such values allow a few spacings (or say when their tolerance is
// finer).
#include <cmath>
#include <string>

#include "granpipe/frame.hpp"

namespace granpipe {

// The largest |coordinate| of the particles' centres; 0 for a frame without particles.
inline double largest_coordinate(const Frame& f) {
  return f.size() > 0 ? f.position().abs().maxCoeff() : 0.0;
}

// The distance from x (>= 0) to the next larger double.
inline double double_spacing(double x) { return std::nextafter(x, HUGE_VAL) - x; }

// An allowance for rounding must stay far below the lengths it separates: at 1e14 from the
// origin 64 spacings are a whole diameter, and packing's centre count and mst's ties
// went wrong with exit 0.
inline constexpr double kFinestResolved = 1e-3;

// Throws InputError starting with `where` when `allowance` spacings at `farthest` (the
// largest coordinate that matters, largest_coordinate(f) or more) exceed kFinestResolved of
// `length` (named `length_name` in the message).
void require_fine_positions(double farthest, double allowance, double length,
                            const std::string& length_name, const std::string& where);

}  // namespace granpipe
