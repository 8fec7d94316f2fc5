#pragma once
// The 3D regular triangulation of the particle centres weighted by their squared radii
// (CGAL, exact predicates): the dual of the power (Laguerre) diagram, whose cells are the
// particles' Laguerre cells. For spheres of unequal radii; equal ones have the Delaunay
// triangulation as theirs.
#include <cstdint>
#include <memory>
#include <vector>

#include "dual_cell.hpp"

namespace granpipe::pores {

class RegularTriangulation {
 public:
  // Points and their weights, rows 0, 1, ... in order.
  RegularTriangulation(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& weights);
  ~RegularTriangulation();
  RegularTriangulation(const RegularTriangulation&) = delete;
  RegularTriangulation& operator=(const RegularTriangulation&) = delete;

  // The finite cells in the triangulation's order (cgal_cells.hpp), centred on their power
  // centres; neighbours index the same vector.
  std::vector<DualCell> cells(int threads);
  // The rows of the points on the hull, whose cells are unbounded.
  std::vector<std::uint32_t> hull() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granpipe::pores
