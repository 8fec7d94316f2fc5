#pragma once
// The vector between two particles' centres as the contact and distance checks need it:
// across a periodic side the nearer image is meant, so a pair touching through the side is
// as close as it is in the container.
#include <Eigen/Core>

#include "granpipe/frame.hpp"

namespace granpipe {

// From the centre of row i to the point p (its first dim components), by the minimum-image
// convention along the container's periodic axes; the components past the frame's
// dimension are zero.
template <class Point>
Eigen::Vector3d separation_to(const Frame& f, Eigen::Index i, const Point& p) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int a = 0; a < f.dim; ++a) d[a] = f.container.minimum_image(a, p(a) - f.position()(i, a));
  return d;
}

// From the centre of row i to that of row j, likewise.
inline Eigen::Vector3d separation(const Frame& f, Eigen::Index i, Eigen::Index j) {
  return separation_to(f, i, f.position().row(j));
}

}  // namespace granpipe
