#include "diagnostics.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace granpipe::dem {

namespace {

// Contact k's 3-vector of a per-contact history, zero when the part keeps none (empty).
Vec3 history_of(const HugePageVector<double>& history, std::int32_t k) {
  if (history.empty()) return Vec3::Zero();
  return Vec3::Map(&history[3 * static_cast<std::size_t>(k)]);
}
Vec3 history_of(const std::vector<Vectors>& per_slot, int slot, int i) {
  return per_slot.empty() ? Vec3::Zero() : Vec3(per_slot[slot].col(i));
}

void add(Energy& e, const ContactEnergy& c) {
  e.normal_elastic += c.normal;
  e.tangential_elastic += c.tangential;
  e.rolling_elastic += c.rolling;
}

// The energies with the parts of the engine's contacts (C: its Contact).
template <class C>
Energy energy_of(const Engine& e) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  const Eigen::Vector3d offset = e.wall_offset();
  Energy out;
  for (int i = 0; i < p.size(); ++i) {
    const double m = 1.0 / p.inv_mass[i];
    out.translational += 0.5 * m * p.v.col(i).squaredNorm();
    out.rotational += 0.5 / p.inv_inertia[i] * p.omega.col(i).squaredNorm();
    out.gravitational -= m * e.settings().gravity.dot(p.x.col(i));
    for (std::int32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      const int j = list.partner[k];
      const double d = p.radius[i] + p.radius[j];
      const double delta = d - (p.x.col(i) - p.x.col(j)).norm();
      if (delta <= 0.0) continue;
      add(out, C::energy(e.model().between(p.species[i], p.species[j]), delta, d,
                         p.radius[i] * p.radius[j] / d, history_of(list.history, k),
                         history_of(list.rolling_history, k)));
    }
    for (int slot = 0; slot < e.walls().count(); ++slot) {
      Vec3 n;
      const double delta = e.walls().overlap(slot, p.x.col(i), p.radius[i], offset, n);
      if (delta <= 0.0) continue;
      const ContactMaterial& mat = e.model().with_wall(e.walls().wall_of_slot(slot), p.species[i]);
      add(out,
          C::energy(mat, delta, 2.0 * p.radius[i], p.radius[i], history_of(p.wall_history, slot, i),
                    history_of(p.wall_rolling_history, slot, i)));
    }
  }
  return out;
}

std::string where(const Engine& e) {
  std::ostringstream s;
  s << "dem: step " << e.step() << " (t = " << e.time() << ")";
  return s.str();
}

}  // namespace

double kinetic_energy(const Particles& p) {
  double sum = 0.0;
  for (int i = 0; i < p.size(); ++i) {
    sum += 0.5 * (p.v.col(i).squaredNorm() / p.inv_mass[i] +
                  p.omega.col(i).squaredNorm() / p.inv_inertia[i]);
  }
  return sum;
}

Energy energy(const Engine& e) {
  const Settings& s = e.settings();
  return with_contact(s.law, s.friction, s.rotation, e.model().rolls(),
                      [&](auto contact) { return energy_of<decltype(contact)>(e); });
}

std::optional<std::int32_t> first_non_finite(const Engine& e) {
  const Particles& p = e.particles();
  for (int i = 0; i < p.size(); ++i) {
    if (!p.x.col(i).allFinite() || !p.v.col(i).allFinite() || !p.omega.col(i).allFinite()) {
      return p.tag[i];
    }
  }
  return std::nullopt;
}

void check_health(const Engine& e, double max_kinetic_energy) {
  const auto advice = [&] {
    std::ostringstream s;
    s << "; reduce dt (now " << e.settings().dt
      << ") against the shortest contact time, or the initial overlaps";
    return s.str();
  };
  if (const auto tag = first_non_finite(e)) {
    throw BlowUp(where(e) + ": particle " + std::to_string(*tag) +
                 " has a non-finite position or velocity: the run blew up" + advice());
  }
  if (!std::isfinite(max_kinetic_energy)) return;  // no bound: no sum to take
  const double kinetic = kinetic_energy(e.particles());
  if (kinetic > max_kinetic_energy) {
    std::ostringstream s;
    s << where(e) << ": kinetic energy " << kinetic << " exceeds " << max_kinetic_energy
      << ": the run blew up" << advice();
    throw BlowUp(s.str());
  }
}

}  // namespace granpipe::dem
