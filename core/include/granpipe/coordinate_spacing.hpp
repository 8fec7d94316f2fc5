#pragma once
// How finely a frame's positions are known: the spacing of doubles at its largest
// coordinate. A length or a centre computed from positions errs by a few of it, so a frame
// moved far from the origin loses the ties and the faces its values sat on exactly; the
// analyzers that compare such values allow a few spacings (or say when their tolerance is
// finer).
#include <cmath>

#include "granpipe/frame.hpp"

namespace granpipe {

// The largest |coordinate| of the particles' centres; 0 for a frame without particles.
inline double largest_coordinate(const Frame& f) {
  return f.size() > 0 ? f.position().abs().maxCoeff() : 0.0;
}

// The distance from x (>= 0) to the next larger double.
inline double double_spacing(double x) { return std::nextafter(x, HUGE_VAL) - x; }

}  // namespace granpipe
