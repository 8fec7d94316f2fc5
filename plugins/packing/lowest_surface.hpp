#pragma once
// The lowest point of a bed's free surface. A tapped bed can stand heaped, its surface
// inclined by several diameters across the box; a region that ends below the highest
// particle then still reaches into the surface on the low side. Below the lowest point
// of the surface it does not.
#include "granpipe/frame.hpp"
#include "region.hpp"

namespace granpipe::packing {

// Splits the horizontal extent of `columns` (its lo..hi along every axis but the
// vertical one; columns.dim is used) into columns at least `width` wide, takes in each
// the highest particle top over the particles whose footprint (interval in 2D, disc in
// 3D) overlaps the column, periodic images included, and returns the lowest of these.
// A column no particle covers has its surface at `base`.
double lowest_surface(const Frame& frame, const Region& columns, double width, double base);

}  // namespace granpipe::packing
