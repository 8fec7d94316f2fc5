#pragma once
// Sequential gravitational deposition (steepest descent, Jullien & Meakin): each sphere
// is dropped at a random horizontal position above the packing and descends - falling,
// rolling over one sphere, rolling in the groove of two - until three supports hold it,
// or it touches the bottom. Spheres at rest never move again. Every stage is solved in
// closed form (roll_path.hpp), so a sphere stops exactly at contact.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "descent.hpp"
#include "granpipe/random.hpp"
#include "sphere_grid.hpp"
#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

// Up to three supports of a sphere at rest, in the partner encoding of frame.hpp
// (a sphere index, or partner::wall for the bottom and the side walls; partner::none
// for an unused slot). A sphere on the bottom has the bottom alone.
using Supports = std::array<std::int64_t, 3>;

class Deposition {
 public:
  explicit Deposition(const TapBox& box);

  // Drops one sphere at (x, y) from above the packing (2R above the highest centre) and
  // adds it where it comes to rest; `rng` breaks the ties of unstable balance (a sphere
  // exactly on top of another).
  void drop(double x, double y, RandomStream& rng);
  // Drops n spheres at uniformly random positions over the open cross-section.
  void drop_random(int n, RandomStream& rng);

  const std::vector<Eigen::Vector3d>& centres() const { return centres_; }
  const std::vector<Supports>& supports() const { return supports_; }
  // Descent stages (falls and rolls) over all drops so far.
  std::uint64_t stages() const { return stages_; }

 private:
  std::vector<Obstacle> touching(const Eigen::Vector3d& p) const;
  // The spheres near a path and every plane, without the path's supports.
  std::vector<Obstacle> candidates(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                   const std::vector<Obstacle>& supports) const;
  // The way down from a balance point that is not a rest (one support straight below,
  // or the top of a groove): away from a touching wall, else at random.
  Eigen::Vector3d roll_off(const Eigen::Vector3d& p, const std::vector<Obstacle>& supports,
                           const std::vector<Obstacle>& touching, RandomStream& rng) const;
  void add(const Eigen::Vector3d& p, const std::vector<Obstacle>& supports);

  TapBox box_;
  std::vector<CentrePlane> planes_;
  SphereGrid grid_;
  std::vector<Eigen::Vector3d> centres_;
  std::vector<Supports> supports_;
  double top_ = 0.0;
  std::uint64_t stages_ = 0;
};

// True when a sphere with these supports is at rest: on the bottom, or held by three.
bool at_rest(const std::vector<Obstacle>& supports);

}  // namespace granpipe::spheres3d_tap
