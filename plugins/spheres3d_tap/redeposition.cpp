#include "redeposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "granpipe/stop_request.hpp"

namespace granpipe::spheres3d_tap {
namespace {

// A sweep of a few spheres is too short a check: with one sphere, one refused trial left
// <Z> unchanged and passed for settled, the sphere still 0.03 R above its rest (and lifted
// again by the next dilation). 64 trials all refused while a sphere can still descend are
// rare (about 3e-5 for one 0.03 R up).
constexpr std::int64_t kFewestTrialsPerCheck = 64;

// A mask: a stop is looked for when the trial count's low 20 bits are all set.
constexpr std::int64_t kTrialsBetweenStopChecks = (std::int64_t{1} << 20) - 1;

// How far a sphere may stray before its neighbour list is renewed, in units of the
// longest move: measured at the paper's settings, renewals then cost a few per cent of
// the trials' time while the lists stay about a dozen spheres long.
constexpr double kSlackPerMove = 1.0;
}  // namespace

Redeposition::Redeposition(const TapBox& box, RedepositionOptions options)
    : box_(box),
      options_(options),
      grid_(box),
      lists_(box, options.move.d_max(), kSlackPerMove * options.move.d_max()) {}

void Redeposition::rebuild(const std::vector<Eigen::Vector3d>& centres) {
  grid_ = SphereGrid(box_);
  for (std::size_t i = 0; i < centres.size(); ++i)
    grid_.put(static_cast<std::int32_t>(i), centres[i]);
  lists_.rebuild(centres, grid_);
}

bool Redeposition::inside(const Eigen::Vector3d& x) const {
  const double r = box_.radius;
  if (x.z() < r) return false;
  return box_.periodic() ||
         (x.x() >= r && x.y() >= r && x.x() <= box_.side - r && x.y() <= box_.side - r);
}

std::int32_t Redeposition::pick(const std::vector<Eigen::Vector3d>& centres,
                                FastRandomStream& rng) {
  const auto i = static_cast<std::int32_t>(rng.below(centres.size()));
  lists_.prefetch(i);
  __builtin_prefetch(centres.data() + i);
  return i;
}

bool Redeposition::trial(std::vector<Eigen::Vector3d>& centres, FastRandomStream& rng,
                         double& height_sum) {
  // The sphere after this one is drawn now, so that its list and centre come from memory
  // while this trial runs: misses on them were a third of a trial's time.
  const std::int32_t i = next_;
  next_ = pick(centres, rng);
  Eigen::Vector3d& c = centres[static_cast<std::size_t>(i)];
  const Eigen::Vector3d x = c + options_.move.draw(rng);
  if (!inside(x) || lists_.overlaps(i, x, centres)) return false;
  const Eigen::Vector3d wrapped = box_.wrap(x);
  grid_.erase(c);
  grid_.put(i, wrapped);
  height_sum += wrapped.z() - c.z();
  c = wrapped;
  lists_.moved(i, centres, grid_);
  return true;
}

TapStats Redeposition::shake(std::vector<Eigen::Vector3d>& centres, std::int64_t n,
                             FastRandomStream& rng) {
  rebuild(centres);
  next_ = pick(centres, rng);
  TapStats stats;
  double height_sum = 0.0;
  for (; stats.trials < n; ++stats.trials) stats.accepted += trial(centres, rng, height_sum);
  return stats;
}

TapStats Redeposition::tap(std::vector<Eigen::Vector3d>& centres, double epsilon,
                           FastRandomStream& rng) {
  // Vertical distances only grow, so the dilated packing overlaps nothing.
  for (auto& c : centres) c.z() *= 1.0 + epsilon;
  rebuild(centres);
  next_ = pick(centres, rng);
  const std::int64_t per_check = trials_per_check(centres.size());
  double height_sum = 0.0;
  for (const auto& c : centres) height_sum += c.z();
  TapStats stats;
  for (std::int64_t check = 0; check < options_.max_checks; ++check) {
    throw_if_stop_requested();  // a tap of a large packing may take minutes
    const double before = height_sum;
    for (std::int64_t k = 0; k < per_check; ++k, ++stats.trials) {
      // One check can hold any number of trials (check_moves 1e15 never ended one): the
      // signal is looked for every 2^20 too.
      if ((k & kTrialsBetweenStopChecks) == kTrialsBetweenStopChecks) throw_if_stop_requested();
      stats.accepted += trial(centres, rng, height_sum);
    }
    if (std::abs(height_sum - before) < options_.eta * std::abs(before)) {
      // A dilated packing in which no sphere moved stayed lifted: it did not settle.
      stats.converged = stats.accepted > 0 || epsilon == 0.0;
      return stats;
    }
  }
  stats.converged = false;
  return stats;
}

std::int64_t Redeposition::trials_per_check(std::size_t spheres) const {
  if (options_.check_moves > 0) return options_.check_moves;
  return fewest_trials_per_check(spheres);
}

std::int64_t Redeposition::fewest_trials_per_check(std::size_t spheres) {
  return std::max(static_cast<std::int64_t>(spheres), kFewestTrialsPerCheck);
}

double Redeposition::largest_height_change(std::size_t spheres) const {
  return static_cast<double>(trials_per_check(spheres)) * options_.move.d_max() /
         static_cast<double>(spheres);
}

}  // namespace granpipe::spheres3d_tap
