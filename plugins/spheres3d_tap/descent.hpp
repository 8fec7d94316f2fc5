#pragma once
// Steepest descent of a hard sphere under gravity among the obstacles it touches, without
// friction: the way it moves is gravity projected onto the directions that do not push
// into any obstacle (a convex cone), and the obstacles that push back are its supports.
// One obstacle below: it rolls over it; two: it rolls in the groove between them; no
// direction left: it rests. This is the rule of sequential deposition (Jullien & Meakin),
// written once for spheres, walls and the bottom alike.
#include <Eigen/Core>
#include <vector>

#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

// An obstacle a sphere touches: another sphere, through the image of its centre nearest
// the sphere, or a plane of centres (a wall or the bottom).
struct Obstacle {
  static constexpr int kNone = -1;
  int sphere = kNone;                                // the sphere's index, or kNone for a plane
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // the sphere's image centre
  CentrePlane plane{};                               // the plane, when sphere == kNone

  static Obstacle of_sphere(int index, const Eigen::Vector3d& image_centre) {
    Obstacle o;
    o.sphere = index;
    o.centre = image_centre;
    return o;
  }
  static Obstacle of_plane(const CentrePlane& p) {
    Obstacle o;
    o.plane = p;
    return o;
  }
  bool is_plane() const { return sphere == kNone; }
  // Unit normal at a sphere centre p, pointing from the obstacle towards p.
  Eigen::Vector3d normal_at(const Eigen::Vector3d& p) const {
    return is_plane() ? plane.normal : Eigen::Vector3d((p - centre).normalized());
  }
  // How far p may move towards the obstacle: centre distance beyond 2R, or beyond the plane.
  double gap(const Eigen::Vector3d& p, double radius) const {
    return is_plane() ? plane.normal.dot(p) - plane.offset : (p - centre).norm() - 2.0 * radius;
  }
};

struct Descent {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // zero when nothing moves it
  std::vector<int> supports;  // indices into the touching list that push back
};

// The motion of a sphere at p touching `touching` (unit gravity along -z).
Descent descend(const Eigen::Vector3d& p, const std::vector<Obstacle>& touching);

}  // namespace granpipe::spheres3d_tap
