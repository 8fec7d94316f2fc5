#pragma once
// Stereology: the area fraction of horizontal cuts through a packing. In 2D a cut is a
// line and its fraction is the sum of the chord lengths over the width; in 3D a plane
// whose fraction is the sum of the disc areas over the cross-section. The mean of the
// cut fraction over heights is the volume fraction of the slab between them.
#include <vector>

#include "granpipe/frame.hpp"
#include "region.hpp"

namespace granpipe::packing {

// Fractions of the cuts at heights y0 + (k + 1/2) step, k = 0..count-1, within the
// region's lateral extent (its vertical extent is not used). Cut particles, and periodic
// images along periodic axes, are counted exactly.
std::vector<double> cut_fractions(const Frame& frame, const Region& lateral, double y0, double step,
                                  int count);

}  // namespace granpipe::packing
