#pragma once
// The pores of unequal spheres that no Delaunay cell of their centres gives. A pore is a
// vertex of the spheres' additively weighted Voronoi diagram: a sphere tangent to four
// spheres that overlaps no other. The Delaunay cells of the centres are the candidates
// (tangent_cells); where radii differ much, a cell's tangent sphere can overlap a fifth
// sphere, and the diagram has other vertices there. Up to a radius ratio of
// kSearchedRadiusRatio they are found by enumeration around each such cell: every
// quadruple of the spheres whose surface comes within the mean radius of the cell's
// tangent sphere is solved (tangent_sphere), and a tangent sphere that overlaps no sphere
// and is no cell's pore is a vertex — complete as tested against a brute force over every
// quadruple of spheres, not by proof (docs/notes/pores-apollonius.md: why this reach, and
// which cells are searched). Beyond that ratio the enumeration misses some, and the
// vertices come from the lifted triangulation (lifted_vertices), exact by construction and
// some fifty times slower.
#include <vector>

#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"
#include "merge_cells.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

// Largest over smallest radius up to which the enumeration was tested complete.
constexpr double kSearchedRadiusRatio = 4.0;

// `left_out`: the cells whose tangent sphere overlaps a fifth sphere; only those within
// reach of `primary` are searched around. A quadruple already a pore (a cell with
// cell.pore) is not found again, nor a sphere a cell's pore or another quadruple already
// gives (within `length`: five or more spheres on one); overlaps within `length` do not
// count. Each vertex once,
// its radius the tangent sphere's plus `mean_radius` (as tangent_cells), cells 0; in the
// order of its spheres' rows, whatever the number of threads.
std::vector<Pore> missing_vertices(const std::vector<DelaunayCell>& cells,
                                   const std::vector<std::size_t>& left_out, const Centres& centres,
                                   const Frame& frame, const Region& primary, double mean_radius,
                                   double length, int threads);

}  // namespace granpipe::pores
