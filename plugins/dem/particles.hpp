#pragma once
// The engine's particle state, structure of arrays: one contiguous array per quantity. A
// 3-vector quantity is a 3 x N matrix, so a particle's three components sit together (the
// pair loop gathers all three of a neighbour at once) and a whole array can be updated as
// one flat run of 3N doubles (the integration loops).
//
// The engine reorders particles spatially at every neighbour-list rebuild; `tag` is each
// particle's index in the order the caller gave them (and its row in emitted frames).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace granpipe::dem {

using Vectors = Eigen::Matrix3Xd;

// What the caller gives: positions, radii and species, optionally velocities and angular
// velocities (zero when empty).
struct InitialState {
  Vectors position;
  Eigen::ArrayXd radius;
  Eigen::ArrayXi species;
  Vectors velocity;
  Vectors angular_velocity;
};

struct Particles {
  Vectors x, v, omega;
  Vectors force;  // contact + damping forces of the last force evaluation (no gravity)
  Vectors torque;
  Eigen::ArrayXd radius, inv_mass, inv_inertia;
  Eigen::ArrayXi species;
  std::vector<std::int32_t> tag;
  // Tangential elastic displacement against each active wall (slot order of WallSet),
  // zero when not touching it. Empty without friction.
  std::vector<Vectors> wall_history;
  // The rolling angle against each active wall likewise; empty without rolling resistance.
  std::vector<Vectors> wall_rolling_history;

  int size() const { return static_cast<int>(radius.size()); }
  // Asks for huge pages under every array (granpipe/huge_pages.hpp): each step streams
  // through all of them. Called once they hold the particles.
  void prefer_huge_pages();
  // Applies the permutation new index k <- old index order[k] to every per-particle array,
  // through `scratch` buffers so that a rebuild allocates nothing once they have grown (the
  // buffers take turns with the arrays, so they are on huge pages too).
  void permute(const std::vector<std::int32_t>& order);

 private:
  Vectors scratch_vectors_;
  Eigen::ArrayXd scratch_reals_;
  Eigen::ArrayXi scratch_ints_;
  std::vector<std::int32_t> scratch_tags_;
};

}  // namespace granpipe::dem
