#pragma once
// The lowest point of a bed's free surface. A tapped bed can stand heaped, its surface
// inclined by several diameters across the box; a region that ends below the highest
// particle then still reaches into the surface on the low side. Below the lowest point
// of the surface it does not.
#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"

namespace granpipe::packing {

// Splits the horizontal extent of `columns` (its lo..hi along every axis of the frame but
// the vertical one) into equal columns, as many as fit `width` wide (at least one), takes
// in each the highest particle top over the particles whose footprint (interval in 2D,
// disc in 3D) meets the column's interior, periodic images included, and returns the
// lowest of these. A column no particle covers, or an extent of no width, gives `base`.
double lowest_surface(const Frame& frame, const Region& columns, double width, double base);

}  // namespace granpipe::packing
