#pragma once
// A box-shaped measuring region inside a frame's container, and what lies in it: the
// exact volume (2D: area) of the particles, counting the parts of particles cut by the
// region's boundary and the periodic images of particles across periodic sides.
#include <Eigen/Core>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe {

struct Region {
  int dim = 3;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Ones();
  double volume() const;  // area in 2D
};

// The container's box [lo, hi] where its walls are at this frame (displaced by the wall
// offset, as a vibrated base is) as a region (for a cylinder, its bounding box).
Region container_region(const Frame& frame);

// Shifts k*L (k integer) along a periodic axis of length L that make [x - r, x + r]
// overlap [a, b]; on a non-periodic axis just 0 when they overlap. Written into `out`.
void image_shifts(double x, double r, double a, double b, bool periodic, double period,
                  std::vector<double>& out);

// Volume (2D: area) of the particles inside the region, exactly.
double particle_measure_in(const Frame& frame, const Region& region);

// Whether each particle's centre lies in the half-open region [lo, hi), periodic
// coordinates taken back into the container first.
std::vector<char> centres_in(const Frame& frame, const Region& region);

}  // namespace granpipe
