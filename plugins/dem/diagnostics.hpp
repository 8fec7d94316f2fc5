#pragma once
// Checks a caller runs between steps (never inside the hot loop): energies, and the
// blow-ups that must stop a run with a clear message (a NaN, an energy explosion). A
// particle going through a wall is stopped by the engine itself, in the step it happens,
// as an overlap past the limit (overlap_limit.hpp).
#include <cstdint>
#include <optional>
#include <string>

#include "blow_up.hpp"
#include "engine.hpp"

namespace granpipe::dem {

struct Energy {
  double translational = 0.0;
  double rotational = 0.0;
  double gravitational = 0.0;       // -m g.x, zero at the origin
  double normal_elastic = 0.0;      // springs of the normal law (pairs and walls)
  double tangential_elastic = 0.0;  // tangential springs, 1/2 f k_t u^2
  double rolling_elastic = 0.0;     // rolling springs, 1/2 f k_r theta^2
  double kinetic() const { return translational + rotational; }
  double total() const {
    return translational + rotational + gravitational + normal_elastic + tangential_elastic +
           rolling_elastic;
  }
};
Energy energy(const Engine& engine);
// Translational plus rotational kinetic energy: Energy::kinetic() without the O(pairs) sums
// of the elastic terms.
double kinetic_energy(const Particles& particles);

// The tag of a particle whose position, velocity or angular velocity is not finite.
std::optional<std::int32_t> first_non_finite(const Engine& engine);
// Throws BlowUp when a particle is not finite or the kinetic energy exceeds
// max_kinetic_energy; the message names the step, the time, the particle and dt against
// the contact time.
void check_health(const Engine& engine, double max_kinetic_energy);

}  // namespace granpipe::dem
