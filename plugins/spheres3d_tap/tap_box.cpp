#include "tap_box.hpp"

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

Container TapBox::container(double top) const {
  Container c =
      Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(side, side, top));
  if (periodic()) c.boundary[0] = c.boundary[1] = {Boundary::Periodic, Boundary::Periodic};
  return c;
}

Eigen::Vector3d TapBox::wrap(Eigen::Vector3d x) const {
  // Most calls (every accepted Monte Carlo move) find x inside already.
  if (!periodic() || (x.x() >= 0.0 && x.x() < side && x.y() >= 0.0 && x.y() < side)) return x;
  // The container's wrap, which also keeps a coordinate a hair below 0 off L.
  const Container c = container(1.0);
  for (int a = 0; a < 2; ++a) x[a] = c.wrap(a, x[a]);
  return x;
}

}  // namespace granpipe::spheres3d_tap
