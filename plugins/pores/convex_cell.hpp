#pragma once
// A convex polyhedron cut down by half-spaces, kept as its faces: each a polygon of its
// corners, counter-clockwise seen from outside. For the cells of particles at plane walls
// (wall_cells), which start as the container's box.
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace granpipe::pores {

class ConvexCell {
 public:
  // Becomes the box [lo, hi] (the memory of the cell before is kept for the cuts).
  void reset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  // Keeps the part where normal . x <= offset.
  void cut(const Eigen::Vector3d& normal, double offset);

  bool empty() const { return sizes_.empty(); }
  double volume() const;
  // The faces' corners, face after face (a corner once for each of its faces).
  const std::vector<Eigen::Vector3d>& corners() const { return corners_; }

 private:
  // Appends the polygon where the cut plane meets the cell, from its corners in `lid_`.
  void close(const Eigen::Vector3d& normal);

  std::vector<Eigen::Vector3d> corners_;
  std::vector<int> sizes_;                           // corners per face
  double farthest_squared_ = 0;                      // of the corners from the origin
  std::vector<double> side_;                         // per corner: normal . x - offset of the cut
  std::vector<Eigen::Vector3d> kept_corners_, lid_;  // made by a cut
  std::vector<int> kept_sizes_;
  std::vector<std::pair<double, int>> by_angle_;  // of the lid's corners
};

}  // namespace granpipe::pores
