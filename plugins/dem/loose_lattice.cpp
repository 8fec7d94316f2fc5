#include "loose_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/random.hpp"

namespace granpipe::dem {

namespace {

// Gaps left between the spheres and the walls or the intruder, in radii of a small
// sphere: the bed starts without a single contact.
constexpr double kClearance = 0.01;

void check(const LooseLattice& spec) {
  const double a = spec.radius, s = spec.spacing;
  if (!(a > 0.0) || !(spec.jitter >= 0.0) || !(s > 2.0 * a + 2.0 * spec.jitter)) {
    std::ostringstream m;
    m << "dem: loose lattice: expected radius > 0 and spacing > diameter + 2 jitter, got radius "
      << a << ", spacing " << s << ", jitter " << spec.jitter;
    throw InputError(m.str());
  }
  if (!(spec.cylinder_radius >= narrowest_cylinder_radius(a, spec.jitter)) || spec.count < 0 ||
      !(spec.intruder_radius < spec.cylinder_radius)) {
    std::ostringstream m;
    m << "dem: loose lattice: no sphere of radius " << a << " (or intruder of radius "
      << spec.intruder_radius << ") fits in a cylinder of radius " << spec.cylinder_radius;
    throw InputError(m.str());
  }
}

}  // namespace

double narrowest_cylinder_radius(double radius, double jitter) {
  return radius + jitter + kClearance * radius;
}

InitialState loose_lattice(const LooseLattice& spec) {
  check(spec);
  const double a = spec.radius, s = spec.spacing;
  const bool intruder = spec.intruder_radius > 0.0;
  const Eigen::Vector3d nut(0.0, 0.0, spec.base + spec.intruder_radius * (1.0 + kClearance));
  // Centres stay this far inside the cylinder, and this far from the intruder's centre
  // (a sideways nudge moves a sphere by up to sqrt(2) jitter).
  const double reach = spec.cylinder_radius - a - spec.jitter - kClearance * a;
  const double keep_off = spec.intruder_radius + a + 2.0 * spec.jitter + kClearance * a;
  RandomStream random(spec.seed);
  std::vector<Eigen::Vector3d> centres;
  if (intruder) centres.push_back(nut);
  const std::size_t wanted = static_cast<std::size_t>(spec.count) + (intruder ? 1 : 0);
  const int half = static_cast<int>(reach / s) + 1;
  for (int layer = 0; centres.size() < wanted; ++layer) {
    const double z = spec.base + a * (1.0 + kClearance) + layer * s;
    const double shift = layer % 2 ? 0.5 * s : 0.0;
    for (int i = -half; i <= half && centres.size() < wanted; ++i) {
      // Only the columns of the row that can lie inside (a wide cylinder's square of
      // (2 half + 1)^2 sites took minutes to cross for a few spheres); one spare each side,
      // and the exact test below, keep the sites and their order as a full scan's.
      const double x = i * s + shift, room = reach * reach - x * x;
      if (room < 0.0) continue;
      const double chord = std::sqrt(room);
      const int first = std::max(-half, static_cast<int>(std::floor((-chord - shift) / s)) - 1);
      const int last = std::min(half, static_cast<int>(std::ceil((chord - shift) / s)) + 1);
      for (int j = first; j <= last && centres.size() < wanted; ++j) {
        const double y = j * s + shift;
        if (std::hypot(x, y) > reach) continue;
        if (intruder && (Eigen::Vector3d(x, y, z) - nut).norm() < keep_off) continue;
        centres.emplace_back(x + random.uniform(-spec.jitter, spec.jitter),
                             y + random.uniform(-spec.jitter, spec.jitter), z);
      }
    }
  }
  InitialState out;
  const auto n = static_cast<Eigen::Index>(centres.size());
  out.position.resize(3, n);
  for (Eigen::Index k = 0; k < n; ++k) out.position.col(k) = centres[static_cast<std::size_t>(k)];
  out.radius = Eigen::ArrayXd::Constant(n, a);
  out.species = Eigen::ArrayXi::Zero(n);
  if (intruder) {
    out.radius[0] = spec.intruder_radius;
    out.species[0] = 1;
  }
  return out;
}

}  // namespace granpipe::dem
