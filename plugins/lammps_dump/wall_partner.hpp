#pragma once
// Which wall of a frame's container a particle-wall contact of a contact dump touches.
// LIGGGHTS names the mesh and triangle, which granpipe's containers do not have: the
// contact belongs to the stated wall nearest to its point (or to the particle's surface).
#include <Eigen/Core>
#include <optional>

#include "granpipe/container.hpp"

namespace granpipe::lammps_dump {

struct WallTouch {
  Wall wall = Wall::Count;
  Eigen::Vector3d normal;  // unit vector from the particle's centre towards the wall
  double distance = 0.0;   // of the given point from the wall
};

// The solid wall (not a periodic or open side) nearest to `point`; nothing when the
// container has none.
std::optional<WallTouch> nearest_wall(const Container& c, const Eigen::Vector3d& point);

}  // namespace granpipe::lammps_dump
