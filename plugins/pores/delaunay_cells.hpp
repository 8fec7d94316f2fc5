#pragma once
// The 3D Delaunay triangulation of a frame's particle centres (CGAL, exact predicates),
// kept while a frame is measured so that the pores and the Voronoi cells share it. Its
// finite cells as the pores read them: each cell's circumsphere and its height, the
// smallest distance from a vertex to the plane of the other three.
#include <memory>
#include <string>
#include <vector>

#include "dual_cell.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct DelaunayCell : DualCell {
  double radius = 0.0;  // of the circumsphere
  double height = 0.0;  // how far the cell is from flat
  // False for a cell of unequal spheres left out of the pores (tangent_cells).
  bool pore = true;
};

class DelaunayTriangulation {
 public:
  // Of `centres` (the frame names their particles). Throws InputError after `where` for two
  // particles at one position (naming both) and centres that span no volume (all coplanar
  // or collinear).
  DelaunayTriangulation(const Centres& centres, const Frame& frame, const std::string& where);
  ~DelaunayTriangulation();
  DelaunayTriangulation(const DelaunayTriangulation&) = delete;
  DelaunayTriangulation& operator=(const DelaunayTriangulation&) = delete;

  // The finite cells; a cell's neighbours are indices into the same vector.
  std::vector<DelaunayCell> cells();
  // Adds points, numbered on from the rows already triangulated (mirror images).
  void insert(const std::vector<Eigen::Vector3d>& points);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granpipe::pores
