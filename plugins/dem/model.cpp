#include "model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

void require(bool ok, const std::string& what, const std::string& expected, double got) {
  if (ok) return;
  std::ostringstream s;
  s << "dem: " << what << ": expected " << expected << ", got " << got;
  throw InputError(s.str());
}

void check_material(const ContactMaterial& m, const std::string& where) {
  const auto finite_nonnegative = [&](double v, const char* name) {
    require(std::isfinite(v) && v >= 0.0, where + ": " + name, "a finite value >= 0", v);
  };
  require(std::isfinite(m.kn) && m.kn > 0.0, where + ": kn", "a finite value > 0", m.kn);
  finite_nonnegative(m.kt, "kt");
  finite_nonnegative(m.gamma_n, "gamma_n");
  finite_nonnegative(m.gamma_t, "gamma_t");
  finite_nonnegative(m.mu, "mu");
  finite_nonnegative(m.mu_roll, "rolling_friction");
}

// Integral of (1 - x^(5/2))^(-1/2) over [0, 1] = (2/5) B(2/5, 1/2): the shape factor of
// the undamped Hertz contact duration.
double hertz_shape_integral() {
  return 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
}

}  // namespace

Model Model::uniform(int species, double density, const ContactMaterial& particles,
                     const ContactMaterial& walls) {
  Model m;
  m.density.assign(static_cast<std::size_t>(species), density);
  m.pair.assign(static_cast<std::size_t>(species * species), particles);
  m.wall.assign(static_cast<std::size_t>(kWallCount * species), walls);
  return m;
}

void Model::set_pair(int a, int b, const ContactMaterial& m) {
  pair[a * species() + b] = m;
  pair[b * species() + a] = m;
}

void Model::set_walls(int s, const ContactMaterial& m) {
  for (int w = 0; w < kWallCount; ++w) wall[w * species() + s] = m;
}

bool Model::rolls() const {
  const auto rolling = [](const ContactMaterial& m) { return m.mu_roll > 0.0; };
  return std::any_of(pair.begin(), pair.end(), rolling) ||
         std::any_of(wall.begin(), wall.end(), rolling);
}

void Model::check() const {
  const int n = species();
  require(n >= 1, "species", "at least one species", n);
  require(pair.size() == static_cast<std::size_t>(n * n), "pair materials",
          std::to_string(n * n) + " entries (species x species)", static_cast<double>(pair.size()));
  require(wall.size() == static_cast<std::size_t>(kWallCount * n), "wall materials",
          std::to_string(kWallCount * n) + " entries (walls x species)",
          static_cast<double>(wall.size()));
  require(fixed.empty() || fixed.size() == static_cast<std::size_t>(n), "fixed species",
          "none or one flag per species", static_cast<double>(fixed.size()));
  for (int s = 0; s < n; ++s) {
    require(std::isfinite(density[s]) && density[s] > 0.0,
            "species " + std::to_string(s) + ": density", "a finite value > 0", density[s]);
  }
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const std::string where = "species " + std::to_string(a) + " with " + std::to_string(b);
      check_material(between(a, b), where);
      const ContactMaterial &x = between(a, b), &y = between(b, a);
      if (x.kn != y.kn || x.kt != y.kt || x.gamma_n != y.gamma_n || x.gamma_t != y.gamma_t ||
          x.mu != y.mu || x.mu_roll != y.mu_roll) {
        throw InputError("dem: " + where + ": expected the same material as species " +
                         std::to_string(b) + " with " + std::to_string(a) + ", got another");
      }
    }
    for (int w = 0; w < kWallCount; ++w) {
      check_material(
          with_wall(static_cast<Wall>(w), a),
          "species " + std::to_string(a) + " with wall " + to_string(static_cast<Wall>(w)));
    }
  }
}

double damping_for_restitution(double e, double kn, double m_eff) {
  require(e > 0.0 && e <= 1.0, "restitution coefficient", "a value in (0, 1]", e);
  const double L = -std::log(e);
  return 2.0 * L * std::sqrt(kn / m_eff) / std::sqrt(std::numbers::pi * std::numbers::pi + L * L);
}

double linear_contact_time(double kn, double gamma_n, double m_eff) {
  const double w2 = kn / m_eff - 0.25 * gamma_n * gamma_n;
  return std::numbers::pi / std::sqrt(w2 > 0.0 ? w2 : kn / m_eff);
}

double linear_restitution(double kn, double gamma_n, double m_eff) {
  if (kn / m_eff - 0.25 * gamma_n * gamma_n <= 0.0) return 0.0;
  return std::exp(-0.5 * gamma_n * linear_contact_time(kn, gamma_n, m_eff));
}

double dashpot_time(double rate) {
  return rate > 0.0 ? 2.0 * std::numbers::pi / rate : std::numeric_limits<double>::infinity();
}

double hertz_contact_time(double kn, double d, double m_eff, double speed) {
  const double delta_max = std::pow(1.25 * m_eff * speed * speed * std::sqrt(d) / kn, 0.4);
  return 2.0 * hertz_shape_integral() * delta_max / speed;
}

}  // namespace granpipe::dem
