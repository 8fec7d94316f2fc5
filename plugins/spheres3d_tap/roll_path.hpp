#pragma once
// The paths of steepest descent, in closed form: a free fall along -z, or an arc of a
// circle (over one supporting sphere, in the groove of two, or along a wall over one),
// and the first thing that ends them: a new obstacle hit, a support whose force falls to
// zero, or the arc's lowest point. Hits are roots of a cos t + b sin t = c, so a sphere
// stops exactly at contact, never by a small step's overshoot.
#include <Eigen/Core>
#include <vector>

#include "descent.hpp"

namespace granpipe::spheres3d_tap {

// P(t) = centre + cos(t) a + sin(t) b for an arc (|a| = |b|, a . b = 0, t from 0), or
// P(t) = start - t z for a fall (is_fall).
struct Path {
  bool is_fall = true;
  Eigen::Vector3d start, centre, a, b;
  double end = 0.0;  // the arc's lowest point (a fall ends only at an obstacle)

  Eigen::Vector3d at(double t) const {
    return is_fall ? Eigen::Vector3d(start - t * Eigen::Vector3d::UnitZ())
                   : Eigen::Vector3d(centre + std::cos(t) * a + std::sin(t) * b);
  }
  // A box holding every point of the path from t = 0 to `until`.
  void bounds(double until, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const;
};

// The path from p along `direction` keeping the given supports touched (none, one or two).
Path path_from(const Eigen::Vector3d& p, const Eigen::Vector3d& direction,
               const std::vector<Obstacle>& supports);

struct PathEnd {
  enum class Kind : unsigned char { Hit, Release, Lowest } kind = Kind::Lowest;
  double t = 0.0;
  Obstacle hit;  // for Hit
};

// The first end of `path` among the candidate obstacles (supports excluded), the support
// forces and the arc's lowest point; `radius` is R. A fall always ends (the bottom is a
// candidate).
PathEnd first_end(const Path& path, const std::vector<Obstacle>& supports,
                  const std::vector<Obstacle>& candidates, double radius);

}  // namespace granpipe::spheres3d_tap
