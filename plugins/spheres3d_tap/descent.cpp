#include "descent.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "granpipe/errors.hpp"

namespace granpipe::spheres3d_tap {

namespace {

const Eigen::Vector3d kGravity(0.0, 0.0, -1.0);
// Forces and motions below this (gravity is 1) are rounding noise; they decide no contact.
constexpr double kTiny = 1e-12;
// A support must carry at least this share of the weight, so that a contact left at the
// exact point where its force vanishes (a roll's end) is not taken for a support again.
constexpr double kLeastForce = 1e-9;

// The projection for one candidate set of pushing obstacles (the bits of `set`): false
// when their normals are dependent, one would pull, or the motion enters another obstacle.
bool try_supports(const std::vector<Eigen::Vector3d>& normals, std::uint32_t set, Descent& out) {
  std::vector<int> chosen;
  for (int k = 0; k < static_cast<int>(normals.size()); ++k)
    if (set >> k & 1u) chosen.push_back(k);
  const auto m = static_cast<Eigen::Index>(chosen.size());
  Eigen::MatrixXd n(3, m);
  for (Eigen::Index c = 0; c < m; ++c) n.col(c) = normals[static_cast<std::size_t>(chosen[c])];
  Eigen::VectorXd force = Eigen::VectorXd::Zero(m);
  if (m > 0) {
    const Eigen::MatrixXd gram = n.transpose() * n;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(gram);
    if (std::abs(lu.determinant()) < 1e-10) return false;
    force = lu.solve(-(n.transpose() * kGravity));
    if ((force.array() < -kTiny).any()) return false;
  }
  // Three independent normals span space, so they balance gravity exactly; and the
  // projection d of gravity satisfies g . d = |d|^2. What fails either is the solve's
  // rounding, which, taken for a direction, once rolled a sphere uphill out of its rest
  // on two spheres and a wall, and back, forever.
  Eigen::Vector3d d = m == 3 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(kGravity + n * force);
  for (const auto& normal : normals)
    if (normal.dot(d) < -kTiny) return false;
  const bool noise = d.norm() < kTiny || kGravity.dot(d) <= 0.5 * d.squaredNorm();
  out.direction = noise ? Eigen::Vector3d::Zero() : d;
  out.supports.clear();
  for (Eigen::Index c = 0; c < m; ++c)
    if (force[c] > kLeastForce) out.supports.push_back(chosen[static_cast<std::size_t>(c)]);
  return true;
}

}  // namespace

Descent descend(const Eigen::Vector3d& p, const std::vector<Obstacle>& touching) {
  std::vector<Eigen::Vector3d> normals;
  for (const auto& o : touching) normals.push_back(o.normal_at(p));
  // Twelve equal spheres, the bottom and two walls are the most one sphere can touch.
  if (normals.size() > 16) throw InternalError("descent: more than 16 touching obstacles");
  // The projection onto the cone is unique and, in 3D, is reached with at most three
  // independent pushing normals (Caratheodory): try the sets from the smallest up.
  const auto k = static_cast<int>(normals.size());
  Descent out;
  for (int size = 0; size <= std::min(k, 3); ++size) {
    for (std::uint32_t set = 0; set < (1u << k); ++set) {
      if (__builtin_popcount(set) == size && try_supports(normals, set, out)) return out;
    }
  }
  throw InternalError("descent: no projection of gravity found among " + std::to_string(k) +
                      " touching obstacles");
}

}  // namespace granpipe::spheres3d_tap
