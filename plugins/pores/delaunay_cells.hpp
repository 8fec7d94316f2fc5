#pragma once
// The 3D Delaunay triangulation of a frame's particle centres (CGAL, exact predicates),
// kept while a frame is measured so that images can be added to it. Its finite cells as
// the pores and the Voronoi cells read them: each cell's circumsphere and whether it is
// flat.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dual_cell.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct DelaunayCell : DualCell {
  double radius = 0.0;  // of the circumsphere
  // A bound on how far the centre (and radius) may be from the circumsphere of the corners
  // as they were before their coordinates were rounded to doubles, the computation's own
  // rounding included: a thin cell's is large. (In the padding after the flags.)
  float uncertainty = 0.0F;
  // Its smallest height (distance from a corner to the plane of the other three) is below
  // the length given: its four centres are in one plane at that precision.
  bool flat = false;
  // False for a cell of unequal spheres left out of the pores (tangent_cells).
  bool pore = true;
  // Two of its corners are closer than the length given.
  bool close_corners = false;
};

// Throws InputError after `where` naming the two particles of the first cell whose
// corners are closer than `length` (tolerance R): a particle given twice with rounding,
// whose cells no tolerance tells apart. Nearest centres share an edge of some finite cell,
// so the cells' flags find every such pair.
void refuse_close_centres(const std::vector<DelaunayCell>& cells, const Centres& centres,
                          const Frame& frame, double length, const std::string& where);

class DelaunayTriangulation {
 public:
  // Of `centres` (the frame names their particles). Throws InputError after `where` for two
  // particles at one position (naming both) and centres that span no volume (all coplanar
  // or collinear).
  DelaunayTriangulation(const Centres& centres, const Frame& frame, const std::string& where);
  ~DelaunayTriangulation();
  DelaunayTriangulation(const DelaunayTriangulation&) = delete;
  DelaunayTriangulation& operator=(const DelaunayTriangulation&) = delete;

  // The finite cells in the triangulation's order (cgal_cells.hpp); a cell's neighbours
  // are indices into the same vector. Flat: lower than `length`.
  std::vector<DelaunayCell> cells(double length, int threads);
  // The rows of the points on the hull, whose cells are unbounded.
  std::vector<std::uint32_t> hull() const;
  // Adds points, numbered on from the rows already triangulated (images of a wider skin).
  void insert(const std::vector<Eigen::Vector3d>& points);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granpipe::pores
