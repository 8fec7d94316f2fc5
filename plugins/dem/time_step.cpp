#include "time_step.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "contact_evaluator.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

// The lightest particle of each species (infinite when a species has none), and its radius
// (its moment of inertia is then 2/5 m a^2).
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

double inertia(const Lightest& l) { return 0.4 * l.mass * l.radius * l.radius; }

// The two bodies of a pair of species' lightest particles.
TwoBodies pair_of(const Lightest& a, const Lightest& b, double speed) {
  const double ia = inertia(a), ib = inertia(b);
  return {a.mass * b.mass / (a.mass + b.mass), ia * ib / (ia + ib), a.radius + b.radius,
          a.radius * b.radius / (a.radius + b.radius), speed};
}

// A species' lightest particle against a wall (infinitely heavy).
TwoBodies wall_pair_of(const Lightest& a, double speed) {
  return {a.mass, inertia(a), 2.0 * a.radius, a.radius, speed};
}

// The shortest contact with the parts of C (its Contact).
template <class C>
ContactTime smallest_contact_time(const Model& model, const WallSet& walls,
                                  const Eigen::ArrayXd& radius, const Eigen::ArrayXi& species,
                                  double impact_speed) {
  if (C::NormalPart::kDurationNeedsSpeed && !(std::isfinite(impact_speed) && impact_speed > 0.0)) {
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
      consider(C::contact_time(model.between(a, b), pair_of(la, lb, impact_speed)),
               "species " + std::to_string(a) + " and species " + std::to_string(b));
    }
    for (int slot = 0; slot < walls.count(); ++slot) {
      const Wall w = walls.wall_of_slot(slot);
      consider(C::contact_time(model.with_wall(w, a), wall_pair_of(la, impact_speed)),
               "species " + std::to_string(a) + " and wall " + to_string(w));
    }
  }
  return best;
}

}  // namespace

ContactTime smallest_contact_time(const Model& model, const WallSet& walls,
                                  const Eigen::ArrayXd& radius, const Eigen::ArrayXi& species,
                                  ContactLaw law, double impact_speed) {
  // Every part's duration counts (a part without its material, e.g. no rolling friction,
  // gives none); the engine refuses rolling without friction and rotation.
  return with_contact(law, true, true, model.rolls(), [&](auto contact) {
    return smallest_contact_time<decltype(contact)>(model, walls, radius, species, impact_speed);
  });
}

StepCheck check_time_step(double dt, const ContactTime& shortest) {
  const double fraction = dt / shortest.t_c;
  if (fraction <= kWarnAboveContactFraction) return {StepVerdict::Fine, ""};
  std::ostringstream s;
  s << "dem: dt = " << dt << " is t_c/" << 1.0 / fraction << " for the shortest contact ("
    << shortest.between << ", t_c = " << shortest.t_c << ")";
  if (fraction > kRefuseAboveContactFraction) {
    s << ": expected dt <= t_c/" << 1.0 / kRefuseAboveContactFraction << " = "
      << shortest.t_c * kRefuseAboveContactFraction
      << " (or that pair's contact longer: t_c is the shortest its normal law, tangential "
         "spring and dashpot and rolling spring give; stiffer k_n, k_t, k_roll and larger "
         "gamma_n, gamma_t shorten it)";
    return {StepVerdict::Refuse, s.str()};
  }
  s << ": above t_c/" << 1.0 / kWarnAboveContactFraction
    << ", the contact time and restitution lose accuracy";
  return {StepVerdict::Warn, s.str()};
}

}  // namespace granpipe::dem
