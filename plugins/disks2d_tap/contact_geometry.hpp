#pragma once
// Exact contact points along the two paths of the Manna-Khakhar moves, in closed form:
// a vertical fall (a segment) against the circle of contact positions around another
// disk, and a roll (an arc of the circle of contact positions around the support)
// against the same kind of circle, a side wall or the base.
#include <algorithm>
#include <cmath>

namespace granpipe::disks2d_tap {

// A roll path: the centre moves on the circle of radius R around (cx, cy), starting at
// unit direction (ux, uy) from it, clockwise (h = +1, towards larger x in the upper half)
// or counter-clockwise (h = -1).
struct RollPath {
  double cx, cy, R, ux, uy, h;

  // Angle travelled from the start to the point of unit direction (qx, qy), in
  // (-pi, pi]: negative when that point lies behind the start.
  double angle_to(double qx, double qy) const {
    return std::atan2(-h * (ux * qy - uy * qx), ux * qx + uy * qy);
  }
};

// Height at which a centre falling vertically at abscissa x from height y first sits at
// distance R from (xj, yj); false when the fall never approaches it (misses it, or the
// other centre is not below). The contact height is set exactly: |(x, y_hit) - (xj, yj)|
// = R up to rounding, even for grazing contacts.
inline bool fall_contact(double x, double y, double xj, double yj, double R, double& y_hit) {
  const double dx = xj - x;
  if (dx >= R || dx <= -R || y <= yj) return false;
  y_hit = yj + std::sqrt((R - dx) * (R + dx));
  return true;
}

// Where a roll path enters and leaves the circle of radius Rj around (xj, yj), as unit
// directions from the path's centre; false when the two circles do not cross.
struct RollCrossings {
  double entry_x, entry_y, exit_x, exit_y;
};
inline bool roll_crossings(const RollPath& path, double xj, double yj, double Rj,
                           RollCrossings& c) {
  const double Dx = xj - path.cx, Dy = yj - path.cy;
  const double d2 = Dx * Dx + Dy * Dy;
  const double d = std::sqrt(d2);
  // cos of the angle between the line of centres and the crossing points.
  const double k = (d2 + path.R * path.R - Rj * Rj) / (2.0 * path.R * d);
  if (!(k > -1.0 && k < 1.0)) return false;
  const double s = std::sqrt((1.0 - k) * (1.0 + k));
  const double nx = Dx / d, ny = Dy / d;
  // The entry lies on the side the path comes from, i.e. the line of centres rotated by
  // h * angle; the exit on the other.
  c = {nx * k - path.h * ny * s, path.h * nx * s + ny * k, nx * k + path.h * ny * s,
       -path.h * nx * s + ny * k};
  return true;
}

// Where a roll path in the upper half reaches abscissa x_contact (a side wall).
inline void roll_reach_x(const RollPath& path, double x_contact, double& qx, double& qy) {
  qx = (x_contact - path.cx) / path.R;
  qy = std::sqrt(std::max(0.0, (1.0 - qx) * (1.0 + qx)));
}

// Where a roll path on the side h reaches height y_contact (the base).
inline void roll_reach_y(const RollPath& path, double y_contact, double& qx, double& qy) {
  qy = (y_contact - path.cy) / path.R;
  qx = path.h * std::sqrt(std::max(0.0, (1.0 - qy) * (1.0 + qy)));
}

}  // namespace granpipe::disks2d_tap
