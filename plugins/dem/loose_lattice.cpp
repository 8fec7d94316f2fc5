#include "loose_lattice.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/random.hpp"

namespace granpipe::dem {

InitialState loose_lattice(const LooseLattice& spec) {
  const double a = spec.radius, s = spec.spacing;
  if (!(a > 0.0) || !(spec.jitter >= 0.0) || !(s > 2.0 * a + 2.0 * spec.jitter)) {
    std::ostringstream m;
    m << "dem: loose lattice: expected radius > 0 and spacing > diameter + 2 jitter, got radius "
      << a << ", spacing " << s << ", jitter " << spec.jitter;
    throw InputError(m.str());
  }
  // Centres stay this far inside the cylinder, so no sphere starts touching it.
  const double reach = spec.cylinder_radius - a - spec.jitter - 0.01 * a;
  if (!(reach >= 0.0) || spec.count < 0) {
    std::ostringstream m;
    m << "dem: loose lattice: no sphere of radius " << a << " fits in a cylinder of radius "
      << spec.cylinder_radius;
    throw InputError(m.str());
  }
  RandomStream random(spec.seed);
  std::vector<Eigen::Vector3d> centres;
  const int half = static_cast<int>(reach / s) + 1;
  for (int layer = 0; static_cast<int>(centres.size()) < spec.count; ++layer) {
    const double z = spec.base + a * 1.01 + layer * s;
    const double shift = layer % 2 ? 0.5 * s : 0.0;
    for (int i = -half; i <= half && static_cast<int>(centres.size()) < spec.count; ++i) {
      for (int j = -half; j <= half && static_cast<int>(centres.size()) < spec.count; ++j) {
        const double x = i * s + shift, y = j * s + shift;
        if (std::hypot(x, y) > reach) continue;
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
  return out;
}

}  // namespace granpipe::dem
