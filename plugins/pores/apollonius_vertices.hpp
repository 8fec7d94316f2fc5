#pragma once
// The pores of unequal spheres that no Delaunay cell of their centres gives. A pore is a
// vertex of the spheres' additively weighted Voronoi diagram: a sphere tangent to four
// spheres that overlaps no other. The Delaunay cells of the centres are the candidates
// (tangent_cells); where radii differ much, a cell's tangent sphere can overlap a fifth
// sphere, and the diagram has other vertices there. They come from the lifted
// triangulation (lifted_vertices), every vertex by construction. (An enumeration around
// the cells left out, tested complete up to a radius ratio of 4, missed vertices there
// too: docs/notes/pores-apollonius.md.)
#include <vector>

#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"
#include "merge_cells.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

// The vertices no cell gives, for a frame with cells left out (their tangent sphere
// overlaps a fifth sphere). A quadruple already a pore (a cell with cell.pore) is not
// given again, nor a sphere a cell's pore or another quadruple already gives (within
// `length`: five or more spheres on one); overlaps within `length` do not count; only
// vertices inside the container's box, and along periodic axes inside `primary`.
// Each vertex once, its radius the tangent sphere's plus `mean_radius` (as tangent_cells),
// cells 0, in the order of its spheres' rows.
std::vector<Pore> missing_vertices(const std::vector<DelaunayCell>& cells, const Centres& centres,
                                   const Frame& frame, const Region& primary, double mean_radius,
                                   double length);

}  // namespace granpipe::pores
