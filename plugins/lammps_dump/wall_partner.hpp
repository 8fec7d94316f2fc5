#pragma once
// Which wall of a frame's container a particle-wall contact of a contact dump touches.
// LIGGGHTS names the mesh and triangle, which granpipe's containers do not have: the
// contact belongs to the stated wall its point faces from the particle's centre (without a
// point, the wall nearest to the particle).
#include <Eigen/Core>
#include <optional>

#include "granpipe/container.hpp"

namespace granpipe::lammps_dump {

struct WallTouch {
  Wall wall = Wall::Count;
  Eigen::Vector3d normal;  // unit vector from the particle's centre towards the wall
  double distance = 0.0;   // of the given point from the wall
  double facing = 1.0;     // cosine of the angle between the normal and the way to the point
};

// The solid wall (not a periodic or open side) nearest to `point`; nothing when the
// container has none.
std::optional<WallTouch> nearest_wall(const Container& c, const Eigen::Vector3d& point);

// The solid wall whose normal at the particle's centre the contact point lies along
// (`to_point`: from the centre to the point; `facing` 0 for a point at the centre): a point
// on a vibrated base raised above where it is stated is nearer the cylinder than the base
// for a bead touching both, but lies below the bead. How far the point is from that wall
// is not judged (a wall moves; docs/lammps_dump.md). Nothing when the container has none.
std::optional<WallTouch> facing_wall(const Container& c, const Eigen::Vector3d& centre,
                                     const Eigen::Vector3d& to_point);

}  // namespace granpipe::lammps_dump
