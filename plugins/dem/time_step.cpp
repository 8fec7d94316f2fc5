#include "time_step.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

// The lightest particle of each species (infinite when a species has none), and its radius.
struct Lightest {
  double mass = std::numeric_limits<double>::infinity();
  double radius = 0.0;
};

std::vector<Lightest> lightest(const Model& model, const Eigen::ArrayXd& radius,
                               const Eigen::ArrayXi& species) {
  std::vector<Lightest> out(static_cast<std::size_t>(model.species()));
  if (species.size() != radius.size()) {
    throw InputError("dem: contact time: expected one species per radius, got " +
                     std::to_string(species.size()) + " species for " +
                     std::to_string(radius.size()) + " radii");
  }
  for (Eigen::Index i = 0; i < radius.size(); ++i) {
    if (species[i] < 0 || species[i] >= model.species()) {
      throw InputError("dem: particle " + std::to_string(i) +
                       ": species: expected a species in 0.." +
                       std::to_string(model.species() - 1) + ", got " + std::to_string(species[i]));
    }
    const double a = radius[i];
    const double m = model.sphere_mass(species[i], a);
    Lightest& l = out[static_cast<std::size_t>(species[i])];
    if (m < l.mass) l = {m, a};
  }
  return out;
}

double contact_time(const ContactMaterial& m, double m_eff, double d, ContactLaw law,
                    double speed) {
  return law == ContactLaw::Linear ? linear_contact_time(m.kn, m.gamma_n, m_eff)
                                   : hertz_contact_time(m.kn, d, m_eff, speed);
}

}  // namespace

ContactTime smallest_contact_time(const Model& model, const WallSet& walls,
                                  const Eigen::ArrayXd& radius, const Eigen::ArrayXi& species,
                                  ContactLaw law, double impact_speed) {
  if (law == ContactLaw::Hertz && !(std::isfinite(impact_speed) && impact_speed > 0.0)) {
    std::ostringstream s;
    s << "dem: impact speed for the Hertz contact time: expected a finite value > 0, got "
      << impact_speed;
    throw InputError(s.str());
  }
  const std::vector<Lightest> light = lightest(model, radius, species);
  ContactTime best{std::numeric_limits<double>::infinity(), "no contact possible"};
  const auto consider = [&](double t, const std::string& between) {
    if (t < best.t_c) best = {t, between};
  };
  for (int a = 0; a < model.species(); ++a) {
    const Lightest& la = light[static_cast<std::size_t>(a)];
    if (!std::isfinite(la.mass)) continue;
    for (int b = a; b < model.species(); ++b) {
      const Lightest& lb = light[static_cast<std::size_t>(b)];
      if (!std::isfinite(lb.mass)) continue;
      const double m_eff = la.mass * lb.mass / (la.mass + lb.mass);
      consider(contact_time(model.between(a, b), m_eff, la.radius + lb.radius, law, impact_speed),
               "species " + std::to_string(a) + " and species " + std::to_string(b));
    }
    for (int slot = 0; slot < walls.count(); ++slot) {
      const Wall w = walls.wall_of_slot(slot);
      consider(contact_time(model.with_wall(w, a), la.mass, 2.0 * la.radius, law, impact_speed),
               "species " + std::to_string(a) + " and wall " + to_string(w));
    }
  }
  return best;
}

StepCheck check_time_step(double dt, const ContactTime& shortest) {
  const double fraction = dt / shortest.t_c;
  if (fraction <= kWarnAboveContactFraction) return {StepVerdict::Fine, ""};
  std::ostringstream s;
  s << "dem: dt = " << dt << " is t_c/" << 1.0 / fraction << " for the shortest contact ("
    << shortest.between << ", t_c = " << shortest.t_c << ")";
  if (fraction > kRefuseAboveContactFraction) {
    s << ": expected dt <= t_c/" << 1.0 / kRefuseAboveContactFraction << " = "
      << shortest.t_c * kRefuseAboveContactFraction;
    return {StepVerdict::Refuse, s.str()};
  }
  s << ": above t_c/" << 1.0 / kWarnAboveContactFraction
    << ", the contact time and restitution lose accuracy";
  return {StepVerdict::Warn, s.str()};
}

}  // namespace granpipe::dem
