#include "tap_box.hpp"

#include <cmath>

#include "granpipe/container.hpp"

namespace granpipe::spheres3d_tap {

std::vector<CentrePlane> TapBox::centre_planes() const {
  const double r = radius, far = side - radius;
  std::vector<CentrePlane> planes{{Eigen::Vector3d::UnitZ(), r, static_cast<int>(Wall::ZLow)}};
  if (periodic()) return planes;
  planes.push_back({Eigen::Vector3d::UnitX(), r, static_cast<int>(Wall::XLow)});
  planes.push_back({-Eigen::Vector3d::UnitX(), -far, static_cast<int>(Wall::XHigh)});
  planes.push_back({Eigen::Vector3d::UnitY(), r, static_cast<int>(Wall::YLow)});
  planes.push_back({-Eigen::Vector3d::UnitY(), -far, static_cast<int>(Wall::YHigh)});
  return planes;
}

Eigen::Vector3d TapBox::wrap(Eigen::Vector3d x) const {
  if (!periodic()) return x;
  for (int a = 0; a < 2; ++a) {
    x[a] -= side * std::floor(x[a] / side);
    if (x[a] >= side) x[a] = 0.0;  // a hair below 0 rounds up to L
  }
  return x;
}

}  // namespace granpipe::spheres3d_tap
