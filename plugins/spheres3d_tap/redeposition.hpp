#pragma once
// A tap of the 3D model: a homothetic dilation z -> z (1 + epsilon) of the centres, then
// redeposition by Monte Carlo: a random sphere tries a move drawn by TrialMove, rejected
// when it would overlap a sphere, the bottom or a wall. Every `check_moves` trials the
// mean centre height <Z> is compared with the previous check; the redeposition stops
// when its relative change falls below eta (or at max_checks, which is reported, as is a
// dilated packing in which no sphere moved).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "granpipe/random.hpp"
#include "neighbour_lists.hpp"
#include "sphere_grid.hpp"
#include "tap_box.hpp"
#include "trial_move.hpp"

namespace granpipe::spheres3d_tap {

struct RedepositionOptions {
  TrialMove move;
  double eta = 1e-6;
  std::int64_t check_moves = 0;  // 0: one sweep, N trials
  std::int64_t max_checks = 100000;
};

struct TapStats {
  std::int64_t trials = 0, accepted = 0;
  bool converged = true;  // false when max_checks ended it or no lifted sphere moved
};

class Redeposition {
 public:
  Redeposition(const TapBox& box, RedepositionOptions options);

  // Dilates and redeposits `centres` in place.
  TapStats tap(std::vector<Eigen::Vector3d>& centres, double epsilon, FastRandomStream& rng);
  // Trials only, no dilation and no stopping rule: n trial moves.
  TapStats shake(std::vector<Eigen::Vector3d>& centres, std::int64_t n, FastRandomStream& rng);
  // The most <Z> of `spheres` spheres can change between two checks: each trial moves one
  // sphere by d_max at most. When it is below eta <Z>, every tap stops at its first check
  // whether the packing settled or not.
  double largest_height_change(std::size_t spheres) const;
  // The fewest trials between two checks, and the default: one sweep (N), at least 64. A
  // check of a few trials sees a few spheres' moves, and a run of refused ones passed for
  // settled (check_moves 10 of 500 spheres: every tap "converged", <Z> rising 18 to 24 R).
  static std::int64_t fewest_trials_per_check(std::size_t spheres);
  double eta() const { return options_.eta; }
  // Neighbour lists renewed one sphere at a time since the object was made.
  std::size_t list_renewals() const { return lists_.renewals(); }

 private:
  void rebuild(const std::vector<Eigen::Vector3d>& centres);
  // A random sphere, whose list and centre are then fetched ahead of its trial.
  std::int32_t pick(const std::vector<Eigen::Vector3d>& centres, FastRandomStream& rng);
  // One trial move of a random sphere; true when accepted. `height_sum` follows.
  bool trial(std::vector<Eigen::Vector3d>& centres, FastRandomStream& rng, double& height_sum);
  // The bottom and the walls (centre planes) leave room for a sphere at x.
  bool inside(const Eigen::Vector3d& x) const;
  std::int64_t trials_per_check(std::size_t spheres) const;

  TapBox box_;
  RedepositionOptions options_;
  SphereGrid grid_;
  NeighbourLists lists_;
  std::int32_t next_ = 0;  // the sphere of the next trial
};

}  // namespace granpipe::spheres3d_tap
