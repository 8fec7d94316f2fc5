#include "wall_mirrors.hpp"

#include <cmath>

namespace granpipe::pores {

std::vector<PlaneWall> plane_walls(const Container& c) {
  std::vector<PlaneWall> walls;
  for (int a = 0; a < 3; ++a) {
    if (c.shape == ContainerShape::Cylinder && a < 2) continue;
    for (int high = 0; high < 2; ++high) {
      if (c.boundary[a][high] != Boundary::Wall) continue;
      walls.push_back({a, high, (high ? c.hi[a] : c.lo[a]) + c.wall_offset[a]});
    }
  }
  return walls;
}

Centres wall_mirrors(const Centres& centres, const std::vector<PlaneWall>& walls, double from,
                     double to) {
  Centres mirrors;
  for (const PlaneWall& w : walls) {
    for (std::size_t k = 0; k < centres.points.size(); ++k) {
      const Eigen::Vector3d& x = centres.points[k];
      const double distance = std::abs(x[w.axis] - w.position);
      if (distance < from || distance >= to) continue;
      Eigen::Vector3d image = x;
      image[w.axis] = 2.0 * w.position - x[w.axis];
      mirrors.points.push_back(image);
      mirrors.particle.push_back(centres.particle[k]);
    }
  }
  return mirrors;
}

}  // namespace granpipe::pores
