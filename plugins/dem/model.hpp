#pragma once
// What the particles are made of: a density per species and a contact material per
// species pair and per (wall, species), in the paper's notation (Sun, Battaglia and
// Subramaniam 2006, Sec. II, Eqs. 5-6):
//   F_n = f(delta/d) (k_n delta n - gamma_n m_eff v_n)
//   F_t = f(delta/d) (-k_t u_t - gamma_t m_eff v_t),   |F_t| <= mu |F_n|
// and, when mu_roll > 0, a rolling torque |M_r| <= mu_roll R_eff |F_n| (contact_parts.hpp)
// gamma_n and gamma_t are rates (1/time) multiplied by m_eff = m_i m_j / (m_i + m_j), as the
// paper's Table I gives them and as LAMMPS' gran/hooke/history takes them; a wall counts
// as infinitely heavy (m_eff = m_i).
#include <numbers>
#include <string>
#include <vector>

#include "granpipe/container.hpp"

namespace granpipe::dem {

struct ContactMaterial {
  double kn = 0.0;       // normal stiffness (force/length)
  double kt = 0.0;       // tangential stiffness (force/length)
  double gamma_n = 0.0;  // normal damping rate (1/time), times m_eff
  double gamma_t = 0.0;  // tangential damping rate (1/time), times m_eff
  double mu = 0.0;       // Coulomb friction coefficient
  // Rolling friction coefficient mu_r (a length ratio: the rolling torque's cap over
  // R_eff |F_n|); 0: no rolling resistance (contact_parts.hpp, RollingSpring).
  double mu_roll = 0.0;
};

inline constexpr int kWallCount = static_cast<int>(Wall::Count);

struct Model {
  std::vector<double> density;        // per species (mass/length^3)
  std::vector<ContactMaterial> pair;  // species x species, symmetric, row-major
  std::vector<ContactMaterial> wall;  // kWallCount x species, row-major by wall
  // Per species (empty: none): particles held by the container, moving rigidly with it
  // (the paper's preparation fixes the large sphere at the bottom). They keep their mass,
  // so a contact with one is damped with the two particles' effective mass.
  std::vector<bool> fixed;

  // `species` species of one density, one particle-particle material and one material
  // for every wall.
  static Model uniform(int species, double density, const ContactMaterial& particles,
                       const ContactMaterial& walls);

  int species() const { return static_cast<int>(density.size()); }
  bool is_fixed(int s) const { return !fixed.empty() && fixed[static_cast<std::size_t>(s)]; }
  const ContactMaterial& between(int a, int b) const { return pair[a * species() + b]; }
  // The mass of a solid sphere of species s and radius a.
  double sphere_mass(int s, double a) const {
    return density[s] * 4.0 / 3.0 * std::numbers::pi * a * a * a;
  }
  const ContactMaterial& with_wall(Wall w, int s) const {
    return wall[static_cast<int>(w) * species() + s];
  }
  // Sets the material of species a with b and of b with a.
  void set_pair(int a, int b, const ContactMaterial& m);
  // Sets the material of species s against every wall.
  void set_walls(int s, const ContactMaterial& m);
  // Whether any material has rolling resistance.
  bool rolls() const;

  // Throws InputError naming the offending entry ("dem: species 1: density: expected a
  // finite value > 0, got -1") on a negative, infinite or NaN coefficient, a zero normal
  // stiffness, a table of the wrong size or an asymmetric pair table.
  void check() const;
};

// The normal damping rate that gives restitution coefficient e (0 < e <= 1) for the linear
// law at this stiffness and effective mass: Eqs. (9)-(10) solved for gamma_n,
// gamma_n = 2 L sqrt(k_n/m_eff) / sqrt(pi^2 + L^2) with L = -ln e.
double damping_for_restitution(double e, double kn, double m_eff);

// Eq. (10): the duration of a linear spring-dashpot contact,
// t_c = pi (k_n/m_eff - gamma_n^2/4)^(-1/2); for an overdamped pair (no rebound) the
// undamped pi sqrt(m_eff/k_n), which is shorter.
double linear_contact_time(double kn, double gamma_n, double m_eff);
// Eq. (9): the restitution coefficient exp(-gamma_n t_c / 2) of the linear law (0 when
// overdamped).
double linear_restitution(double kn, double gamma_n, double m_eff);
// The time an explicit step must resolve for a dashpot that slows a relative velocity at
// `rate` (gamma_n, or gamma_t's on the tangential mass): 2 pi / rate, infinite for none.
// The velocity Verlet step multiplies that velocity by about 1 - rate dt, which flips its
// sign past rate dt = 2: a contact damped past critical then threw its spheres apart faster
// than they met (gamma_n = 1.2e4 at dt = 2.5e-4: e = 2), while its undamped t_c passed.
double dashpot_time(double rate);
// Duration of an undamped Hertzian contact of the paper's law, F = k_n delta^(3/2) / sqrt(d),
// hit at normal speed v: t_c = 2.943... delta_max / v with
// delta_max = (5 m_eff v^2 sqrt(d) / (4 k_n))^(2/5).
double hertz_contact_time(double kn, double d, double m_eff, double speed);

}  // namespace granpipe::dem
