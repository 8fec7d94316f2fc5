#include "redeposition.hpp"

#include <cmath>

namespace granpipe::spheres3d_tap {

Redeposition::Redeposition(const TapBox& box, RedepositionOptions options)
    : box_(box), options_(options), grid_(box) {}

void Redeposition::rebuild(const std::vector<Eigen::Vector3d>& centres) {
  grid_ = SphereGrid(box_);
  for (std::size_t i = 0; i < centres.size(); ++i)
    grid_.put(static_cast<std::int32_t>(i), centres[i]);
}

bool Redeposition::fits(const std::vector<Eigen::Vector3d>& centres, std::int32_t i,
                        const Eigen::Vector3d& x) const {
  const double r = box_.radius;
  if (x.z() < r) return false;
  if (!box_.periodic() &&
      (x.x() < r || x.y() < r || x.x() > box_.side - r || x.y() > box_.side - r))
    return false;
  return !grid_.any_within(x, 2.0 * r, i, centres);
}

bool Redeposition::trial(std::vector<Eigen::Vector3d>& centres, RandomStream& rng,
                         double& height_sum) {
  const auto i = static_cast<std::int32_t>(rng.below(centres.size()));
  Eigen::Vector3d& c = centres[static_cast<std::size_t>(i)];
  const Eigen::Vector3d x = box_.wrap(c + options_.move.draw(rng));
  if (!fits(centres, i, x)) return false;
  grid_.erase(c);
  grid_.put(i, x);
  height_sum += x.z() - c.z();
  c = x;
  return true;
}

TapStats Redeposition::shake(std::vector<Eigen::Vector3d>& centres, std::int64_t n,
                             RandomStream& rng) {
  rebuild(centres);
  TapStats stats;
  double height_sum = 0.0;
  for (; stats.trials < n; ++stats.trials) stats.accepted += trial(centres, rng, height_sum);
  return stats;
}

TapStats Redeposition::tap(std::vector<Eigen::Vector3d>& centres, double epsilon,
                           RandomStream& rng) {
  // Vertical distances only grow, so the dilated packing overlaps nothing.
  for (auto& c : centres) c.z() *= 1.0 + epsilon;
  rebuild(centres);
  const std::int64_t per_check =
      options_.check_moves > 0 ? options_.check_moves : static_cast<std::int64_t>(centres.size());
  double height_sum = 0.0;
  for (const auto& c : centres) height_sum += c.z();
  TapStats stats;
  for (std::int64_t check = 0; check < options_.max_checks; ++check) {
    const double before = height_sum;
    for (std::int64_t k = 0; k < per_check; ++k, ++stats.trials)
      stats.accepted += trial(centres, rng, height_sum);
    if (std::abs(height_sum - before) < options_.eta * std::abs(before)) return stats;
  }
  stats.converged = false;
  return stats;
}

}  // namespace granpipe::spheres3d_tap
