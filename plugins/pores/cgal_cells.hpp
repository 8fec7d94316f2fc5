#pragma once
// What the CGAL triangulations of this plugin share: the kernel, and the numbering of the
// finite cells in their info so that a cell's neighbours can be named by index.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Core>
#include <cstdint>

#include "dual_cell.hpp"

namespace granpipe::pores::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

inline Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Numbers the finite cells 0, 1, ... in iteration order, the infinite ones kHull.
template <class Triangulation>
void number_cells(const Triangulation& t) {
  std::uint32_t next = 0;
  for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c)
    c->info() = t.is_infinite(c) ? kHull : next++;
}

// The vertices' rows and the neighbours' numbers of a finite cell (numbered).
template <class CellHandle>
void fill_dual_cell(const CellHandle& c, DualCell& cell) {
  for (int k = 0; k < 4; ++k) {
    cell.vertices[k] = c->vertex(k)->info();
    cell.neighbours[k] = c->neighbor(k)->info();
  }
}

}  // namespace granpipe::pores::cgal
