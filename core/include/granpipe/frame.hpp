#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "granpipe/container.hpp"

namespace granpipe {

// N x dim, column-major: each coordinate is one contiguous array (structure of arrays).
using Coordinates = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic>;
using IndexArray = Eigen::Array<std::int64_t, Eigen::Dynamic, 1>;
using IntArray = Eigen::Array<std::int32_t, Eigen::Dynamic, 1>;

// What a particle touches or leans on: a particle index (>= 0), nothing, or a wall.
// One encoding serves contacts and 2D support labels alike.
namespace partner {
constexpr std::int64_t none = -1;
constexpr std::int64_t wall(Wall w) { return -2 - static_cast<std::int64_t>(w); }
constexpr bool is_particle(std::int64_t p) { return p >= 0; }
constexpr bool is_wall(std::int64_t p) { return p <= -2; }
constexpr Wall wall_of(std::int64_t p) { return static_cast<Wall>(-2 - p); }
}  // namespace partner

// Contacts of one frame, structure of arrays. Particle-wall contacts have j a wall partner.
struct Contacts {
  IndexArray i, j;
  Eigen::ArrayXd overlap;
  Coordinates normal_force;      // M x dim
  Coordinates tangential_force;  // M x dim
  Coordinates point;             // M x dim
  Eigen::Index size() const { return i.size(); }
  void resize(Eigen::Index m, int dim);
};

// 2D pseudo-dynamics: which particle or wall supports each disk on its left and right.
struct Supports {
  IndexArray left, right;  // partner encoding
};

// One configuration of particles.
struct Frame {
  int dim = 3;
  Coordinates position;  // N x dim
  Eigen::ArrayXd radius;
  IndexArray id;
  IntArray species;
  std::optional<Coordinates> velocity;          // N x dim
  std::optional<Coordinates> angular_velocity;  // N x 3 in 3D, N x 1 in 2D
  Container container;
  std::optional<Contacts> contacts;
  std::optional<Supports> supports;
  double time = 0.0;
  std::int64_t step = 0;
  std::int64_t tap = -1;    // tap index of tapped scenes, -1 when not tapped
  // Cycle of a cyclic protocol, -1 when none. Ramped protocols (annealed tapping) count
  // half-cycles: 0 the first increase, odd decreasing, even increasing (ramp_means.hpp).
  std::int64_t cycle = -1;

  Eigen::Index size() const { return position.rows(); }
  // Sizes every per-particle array to n, ids 0..n-1, species 0; drops optional data.
  void resize(Eigen::Index n, int dimension);
  // Throws InputError naming `where` on NaN/inf positions or radii, non-positive radii,
  // or inconsistent array sizes.
  void check(const std::string& where) const;
};

}  // namespace granpipe
