#pragma once
// Crystals built in the pores tests: unit cells in radii, and frames of whole unit cells.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe::test {

// A crystal of rectangular unit cells, `cell` and `basis` in radii.
struct Crystal {
  Eigen::Vector3d cell;
  std::vector<Eigen::Vector3d> basis;
};

inline Crystal fcc() {
  const double a = 2.0 * std::sqrt(2.0);
  return {{a, a, a}, {{0, 0, 0}, {a / 2, a / 2, 0}, {a / 2, 0, a / 2}, {0, a / 2, a / 2}}};
}
inline Crystal hcp() {  // orthohexagonal cell, layers stacked along z
  const double s3 = std::sqrt(3.0), c = std::sqrt(8.0 / 3.0);
  return {{2, 2 * s3, 2 * c}, {{0, 0, 0}, {1, s3, 0}, {1, s3 / 3, c}, {0, s3 / 3 + s3, c}}};
}
inline Crystal sc() { return {{2, 2, 2}, {{0, 0, 0}}}; }
inline Crystal bcc() {
  const double a = 4.0 / std::sqrt(3.0);
  return {{a, a, a}, {{0, 0, 0}, {a / 2, a / 2, a / 2}}};
}

// cells^3 unit cells of touching spheres of `radius`, in walls one radius from the
// outermost spheres: a container of no periodic side.
inline Frame crystal_frame(const Crystal& c, int cells, double radius = 1.0) {
  Frame f;
  f.resize(static_cast<Eigen::Index>(c.basis.size()) * cells * cells * cells, 3);
  f.radius().setConstant(radius);
  Eigen::Index k = 0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int l = 0; l < cells; ++l)
        for (const auto& b : c.basis) {
          const Eigen::Vector3d site(i, j, l);
          f.position().row(k++) = radius * (site.cwiseProduct(c.cell) + b).transpose();
        }
  for (int a = 0; a < 3; ++a) {
    f.container.lo[a] = f.position().col(a).minCoeff() - radius;
    f.container.hi[a] = f.position().col(a).maxCoeff() + radius;
  }
  return f;
}

}  // namespace granpipe::test
