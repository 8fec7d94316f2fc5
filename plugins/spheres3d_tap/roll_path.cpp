#include "roll_path.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>

namespace granpipe::spheres3d_tap {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Ends closer than this to the path's start (radians of an arc, or R of a fall) are the
// contact the sphere is leaving or has just made, not a new one.
constexpr double kLeastStep = 1e-10;
constexpr double kNever = std::numeric_limits<double>::infinity();

// The smallest t in (from, to] where h(t) = c0 + cc cos t + cs sin t reaches zero going
// down (h' <= 0), or kNever.
double first_fall_to_zero(double c0, double cc, double cs, double from, double to) {
  const double amplitude = std::hypot(cc, cs);
  if (amplitude == 0.0 || std::abs(c0) > amplitude) return kNever;
  const double phase = std::atan2(cs, cc), half = std::acos(-c0 / amplitude);
  double best = kNever;
  for (double root : {phase + half, phase - half}) {
    root = std::fmod(root, kTwoPi);
    if (root < 0.0) root += kTwoPi;
    const double slope = -cc * std::sin(root) + cs * std::cos(root);
    if (root > from && root <= to && slope <= 1e-14 * amplitude) best = std::min(best, root);
  }
  return best;
}

Eigen::Vector3d unit_part(const Eigen::Vector3d& v, const Eigen::Vector3d& off) {
  const Eigen::Vector3d u = off.normalized();
  return (v - v.dot(u) * u).normalized();
}

// The first time a fall from `start` brings the centre to `obstacle`, or kNever.
double fall_hit(const Eigen::Vector3d& start, const Obstacle& obstacle, double radius) {
  if (obstacle.is_plane()) {
    const double nz = obstacle.plane.normal.z();
    if (nz <= 0.0) return kNever;  // a side wall, parallel to the fall
    return (obstacle.plane.normal.dot(start) - obstacle.plane.offset) / nz;
  }
  const double h2 = (start - obstacle.centre).head<2>().squaredNorm(),
               reach = 4.0 * radius * radius;
  if (h2 >= reach) return kNever;
  return start.z() - obstacle.centre.z() - std::sqrt(reach - h2);
}

PathEnd end_of_fall(const Path& path, const std::vector<Obstacle>& candidates, double radius) {
  PathEnd end{PathEnd::Kind::Hit, kNever, Obstacle()};
  for (const auto& o : candidates) {
    const double t = fall_hit(path.start, o, radius);
    if (t > kLeastStep * radius && t < end.t) {
      end.t = t;
      end.hit = o;
    }
  }
  return end;
}

// The coefficients of -(g . n) = n_z at P(t), for each support, as (c0, cc, cs).
Eigen::Matrix3Xd lift_coefficients(const Path& path, const std::vector<Obstacle>& supports) {
  Eigen::Matrix3Xd lift(3, static_cast<Eigen::Index>(supports.size()));
  for (std::size_t k = 0; k < supports.size(); ++k) {
    const Obstacle& s = supports[k];
    if (s.is_plane()) {
      lift.col(static_cast<Eigen::Index>(k)) << s.plane.normal.z(), 0.0, 0.0;
      continue;
    }
    const double r = (path.at(0.0) - s.centre).norm();  // constant along the arc
    lift.col(static_cast<Eigen::Index>(k)) << (path.centre.z() - s.centre.z()) / r, path.a.z() / r,
        path.b.z() / r;
  }
  return lift;
}

// The first t at which a support's force, G^-1 (-(g . n)), falls to zero; the Gram
// matrix G of the supports' normals stays the same along the arc.
double first_release(const Path& path, const std::vector<Obstacle>& supports, double to) {
  const auto m = static_cast<Eigen::Index>(supports.size());
  Eigen::MatrixXd normals(3, m);
  for (Eigen::Index k = 0; k < m; ++k)
    normals.col(k) = supports[static_cast<std::size_t>(k)].normal_at(path.at(0.0));
  const Eigen::MatrixXd force =
      (normals.transpose() * normals).inverse() * lift_coefficients(path, supports).transpose();
  double best = kNever;
  for (Eigen::Index k = 0; k < m; ++k)
    best =
        std::min(best, first_fall_to_zero(force(k, 0), force(k, 1), force(k, 2), kLeastStep, to));
  return best;
}

// The first t at which the arc meets `o`, or kNever.
double arc_hit(const Path& path, const Obstacle& o, double radius, double to) {
  if (o.is_plane()) {
    const Eigen::Vector3d& n = o.plane.normal;
    return first_fall_to_zero(n.dot(path.centre) - o.plane.offset, n.dot(path.a), n.dot(path.b),
                              kLeastStep, to);
  }
  const Eigen::Vector3d off = path.centre - o.centre;
  return first_fall_to_zero(off.squaredNorm() + path.a.squaredNorm() - 4.0 * radius * radius,
                            2.0 * off.dot(path.a), 2.0 * off.dot(path.b), kLeastStep, to);
}

PathEnd end_of_arc(const Path& path, const std::vector<Obstacle>& supports,
                   const std::vector<Obstacle>& candidates, double radius) {
  PathEnd end{PathEnd::Kind::Lowest, path.end, Obstacle()};
  const double release = first_release(path, supports, end.t);
  if (release < end.t) end = {PathEnd::Kind::Release, release, Obstacle()};
  for (const auto& o : candidates) {
    const double t = arc_hit(path, o, radius, end.t);
    if (t < end.t) end = {PathEnd::Kind::Hit, t, o};
  }
  return end;
}

}  // namespace

void Path::bounds(double until, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const {
  if (is_fall) {
    lo = start - until * Eigen::Vector3d::UnitZ();
    hi = start;
    return;
  }
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(a.norm());
  lo = centre - reach;
  hi = centre + reach;
}

Path path_from(const Eigen::Vector3d& p, const Eigen::Vector3d& direction,
               const std::vector<Obstacle>& supports) {
  Path path;
  path.start = p;
  if (supports.empty()) return path;
  path.is_fall = false;
  const Obstacle& sphere = supports[0].is_plane() ? supports[1] : supports[0];
  path.centre = sphere.centre;
  Eigen::Vector3d tangent = direction;
  if (supports.size() == 2) {
    const Obstacle& other = supports[0].is_plane() ? supports[0] : supports[1];
    const Eigen::Vector3d axis = other.is_plane()
                                     ? other.plane.normal
                                     : Eigen::Vector3d(other.centre - sphere.centre).normalized();
    path.centre += (p - sphere.centre).dot(axis) * axis;
    tangent -= tangent.dot(axis) * axis;
  }
  path.a = p - path.centre;
  path.b = path.a.norm() * unit_part(tangent, path.a);
  // The lowest point of the arc: where (cos t, sin t) points along -(a_z, b_z).
  const bool level = std::hypot(path.a.z(), path.b.z()) < 1e-12 * path.a.norm();
  path.end = level ? kTwoPi : std::atan2(-path.b.z(), -path.a.z());
  if (path.end <= 0.0) path.end += kTwoPi;
  return path;
}

PathEnd first_end(const Path& path, const std::vector<Obstacle>& supports,
                  const std::vector<Obstacle>& candidates, double radius) {
  return path.is_fall ? end_of_fall(path, candidates, radius)
                      : end_of_arc(path, supports, candidates, radius);
}

}  // namespace granpipe::spheres3d_tap
