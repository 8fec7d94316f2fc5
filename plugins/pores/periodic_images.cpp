#include "periodic_images.hpp"

namespace granpipe::pores {

namespace {

// The shifts along one axis that bring coordinate x within `skin` of the box's other side.
std::vector<double> shifts_along(const Container& c, int a, double x, double skin) {
  std::vector<double> shifts{0.0};
  if (!c.periodic(a)) return shifts;
  if (x < c.lo[a] + skin) shifts.push_back(c.length(a));
  if (x >= c.hi[a] - skin) shifts.push_back(-c.length(a));
  return shifts;
}

}  // namespace

Centres centres_with_images(const Frame& frame, double skin) {
  const Container& c = frame.container;
  Centres centres;
  centres.points.reserve(static_cast<std::size_t>(frame.size()));
  centres.particle.reserve(static_cast<std::size_t>(frame.size()));
  centres.primary.reserve(static_cast<std::size_t>(frame.size()));
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    Eigen::Vector3d x;
    for (int a = 0; a < 3; ++a) x[a] = c.wrap(a, frame.position()(k, a));
    const auto sx = shifts_along(c, 0, x[0], skin), sy = shifts_along(c, 1, x[1], skin),
               sz = shifts_along(c, 2, x[2], skin);
    centres.primary.push_back(static_cast<std::uint32_t>(centres.points.size()));  // shift 0 first
    for (double dx : sx)
      for (double dy : sy)
        for (double dz : sz) {
          centres.points.push_back(x + Eigen::Vector3d(dx, dy, dz));
          centres.particle.push_back(static_cast<std::uint32_t>(k));
        }
  }
  return centres;
}

}  // namespace granpipe::pores
