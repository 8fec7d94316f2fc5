#pragma once
// Mirror images of particle centres across the container's plane walls. A particle and its
// mirror image have equal radii, so their bisector (equal power) is the wall itself: with
// the mirrors triangulated, the cells of the particles end exactly at the walls.
#include <vector>

#include "granpipe/container.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct PlaneWall {
  int axis = 0;
  int high = 0;  // 1: the upper side of the axis
  double position = 0.0;
};

// The Wall sides of the box (moved by the wall offset), but the x and y sides of a
// cylinder container, which the cylinder replaces.
std::vector<PlaneWall> plane_walls(const Container& c);

// The mirror images of the points whose distance to a wall is in [from, to), across that
// wall (points and particles; no primary rows).
Centres wall_mirrors(const Centres& centres, const std::vector<PlaneWall>& walls, double from,
                     double to);

}  // namespace granpipe::pores
