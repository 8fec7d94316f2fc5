#pragma once
// The walls a DEM run sees, taken from a granpipe::Container at rest: a plane for every
// side whose boundary is a Wall (for a cylinder, only the z sides: the base and a lid),
// and the inside of the vertical cylinder. All of them move rigidly with the drive.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "drive.hpp"
#include "granpipe/container.hpp"

namespace granpipe::dem {

// An axis-aligned plane; particles stay on the side `sign` points to (+1 above a low wall,
// -1 below a high wall).
struct PlaneWall {
  Wall wall;
  int axis;
  double sign;
  double rest_position;
};

// Overlap of a sphere (centre coordinate x along the plane's axis, radius a) with a plane
// wall at `position` facing `sign`; > 0 when touching. The force loop and everything that
// reports contacts use these two functions, so they agree on which contacts exist.
inline double plane_overlap(double sign, double x, double position, double a) {
  return a - sign * (x - position);
}
// Overlap with the inside of a vertical cylinder, from the centre's offset (dx, dy) to
// the axis; rho receives the distance to the axis. On the axis (rho = 0) the inward
// normal is undefined and only a sphere wider than the cylinder could touch: no contact.
inline double cylinder_overlap(double dx, double dy, double cylinder_radius, double a,
                               double& rho) {
  rho = std::sqrt(dx * dx + dy * dy);
  return rho > 0.0 ? a - (cylinder_radius - rho) : 0.0;
}

class WallSet {
 public:
  WallSet() = default;
  // Throws InputError for a periodic side (not supported by the DEM engine), a cylinder
  // of non-positive or non-finite radius, or an invalid drive.
  WallSet(const Container& rest, const Drive& drive);

  const Container& rest() const { return rest_; }
  const Drive& drive() const { return drive_; }
  void set_drive(const Drive& drive);
  const std::vector<PlaneWall>& planes() const { return planes_; }
  bool has_cylinder() const { return cylinder_; }
  // Active walls, planes first then the cylinder: the slot numbering of the per-wall
  // arrays (materials, history).
  int count() const { return static_cast<int>(planes_.size()) + (cylinder_ ? 1 : 0); }
  Wall wall_of_slot(int slot) const;

  // The geometry of active wall `slot` displaced by `offset`: the contact normal (from the
  // wall into the particle) and the overlap of a sphere at x of radius a.
  double overlap(int slot, const Eigen::Vector3d& x, double a, const Eigen::Vector3d& offset,
                 Eigen::Vector3d& normal) const;

  // The container displaced to time t (wall_offset and wall_velocity set), as frames show it.
  Container at(double t) const;

 private:
  Container rest_;
  Drive drive_;
  std::vector<PlaneWall> planes_;
  bool cylinder_ = false;
};

}  // namespace granpipe::dem
