#pragma once
// What a frame's container must be for anything to be measured in it, checked with every
// frame a source gives (Frame::check): numbers that are numbers, and walls that exist for
// the contacts naming them. Files from other tools and edited files broke both: an edge of
// inf made every packing fraction 0, a wall offset of NaN every height NaN, and a contact
// with "x_low" in a box open there was counted as a wall contact, all with exit 0.
#include <string>

#include "granpipe/container.hpp"

namespace granpipe {

// InputError starting with `where` unless lo, hi, the wall offset and velocity are finite
// along the first `dim` axes with lo < hi, and a cylinder's centre is finite and its radius
// finite and > 0.
void check_container_values(const Container& container, int dim, const std::string& where);

// Whether `w` is a wall of the container in `dim` dimensions: a solid side of a box along
// its first dim axes (a 2D frame's z sides are none), the z sides of a cylinder container
// where solid, or its cylinder (the x and y sides of a cylinder container only bound its
// cell grid).
bool has_wall(const Container& container, int dim, Wall w);

// "" when the container's walls are at rest along its first `dim` axes (no wall offset, no
// wall velocity), else what is not: "its walls displaced by (0, 1.5)", "its walls moving at
// (0, 0, 0.5)", to 17 digits. For a source whose model has fixed walls and starts from a
// saved frame (a driven base read as one at rest left the spheres floating).
std::string walls_not_at_rest(const Container& container, int dim);

}  // namespace granpipe
