#include "granpipe/container.hpp"

namespace granpipe {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::Wall:
      return "wall";
    case Boundary::Periodic:
      return "periodic";
    case Boundary::Open:
      return "open";
  }
  return "?";
}

const char* to_string(ContainerShape s) { return s == ContainerShape::Box ? "box" : "cylinder"; }

const char* to_string(Wall w) {
  static const char* names[] = {"x_low", "x_high", "y_low",   "y_high",
                                "z_low", "z_high", "cylinder"};
  const auto k = static_cast<unsigned>(w);
  return k < static_cast<unsigned>(Wall::Count) ? names[k] : "?";
}

Container Container::periodic_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Container c;
  c.lo = lo;
  c.hi = hi;
  for (int a = 0; a < dim; ++a) c.boundary[a] = {Boundary::Periodic, Boundary::Periodic};
  return c;
}

Container Container::open_top_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Container c;
  c.lo = lo;
  c.hi = hi;
  c.boundary[dim - 1][1] = Boundary::Open;
  return c;
}

}  // namespace granpipe
