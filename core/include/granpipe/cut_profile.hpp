#pragma once
// Stereology: the area fraction of cuts through a packing, perpendicular to one axis. In
// 2D a cut is a line and its fraction is the sum of the chord lengths over the width; in
// 3D a plane whose fraction is the sum of the disc areas over the cross-section. The mean
// of the cut fraction over a range of the axis is the volume fraction of the slab between
// (the stereological result the tapping papers rest on), which bin_fractions gives exactly.
#include <vector>

#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"

namespace granpipe {

// Fractions of the cuts perpendicular to `axis` at x0 + (k + 1/2) step, k = 0..count-1,
// within the region's extent along the other axes (its extent along `axis` is not used).
// Cut particles, and periodic images along periodic axes, are counted exactly.
std::vector<double> cut_fractions(const Frame& frame, const Region& region, int axis, double x0,
                                  double step, int count);

// The mean cut fraction over each bin [x0 + k step, x0 + (k + 1) step), k = 0..count-1,
// exactly: the particle volume (2D: area) in the bin, within the region's extent along the
// other axes, over the bin's volume. What cut_fractions tends to as its cuts get dense.
std::vector<double> bin_fractions(const Frame& frame, const Region& region, int axis, double x0,
                                  double step, int count);

}  // namespace granpipe
