#include "granpipe/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

// Method. A rectangle (box) is an inclusion-exclusion of its 4 (8) corner regions
// {X >= a, Y >= b (, Z >= c)}, so everything reduces to the overlap of the unit disk
// (ball) with one such corner region. A corner with a negative coordinate is reflected
// onto non-negative ones ({X >= a} = everything minus the mirror image {X >= -a}),
// which leaves corners with a, b, c >= 0 inside the unit disk (ball). Their areas and
// volumes follow from the divergence theorem, measure = (1/d) ∮ x·n dS: the curved
// boundary contributes r times its length (area), the flat faces minus their offsets
// times their lengths (areas). Lengths and areas of flat faces are again corner terms
// one dimension down; the area of the spherical patch follows from Archimedes'
// hat-box theorem (dA = dphi dz on the unit sphere) with a closed-form z integral.

namespace granpipe::overlap {
namespace {

constexpr double kPi = std::numbers::pi;

// Area of the unit disk ∩ {X >= a, Y >= b} for a, b >= 0.
double unit_disk_corner(double a, double b) {
  if (a * a + b * b >= 1.0) return 0.0;
  const double xa = std::sqrt((1.0 - b) * (1.0 + b));  // where Y = b meets the circle
  const double yb = std::sqrt((1.0 - a) * (1.0 + a));  // where X = a meets the circle
  const double arc = std::atan2(yb, a) - std::atan2(b, xa);
  // (1/2)[arc length - b (xa - a) - a (yb - b)]
  return 0.5 * (arc - b * xa - a * yb + 2.0 * a * b);
}

// Area of the unit disk ∩ {X >= a, Y >= b}, any a, b.
double unit_disk_quadrant(double a, double b) {
  if (a >= 1.0 || b >= 1.0) return 0.0;
  if (a < 0.0) return 2.0 * unit_disk_quadrant(0.0, b) - unit_disk_quadrant(-a, b);
  if (b < 0.0) return 2.0 * unit_disk_quadrant(a, 0.0) - unit_disk_quadrant(a, -b);
  return unit_disk_corner(a, b);
}

// Antiderivative in z of the angle acos(a / rho(z)), rho = sqrt(1 - z^2), for a >= 0 and
// 0 <= z <= sqrt(1 - a^2): the angular half-width of {X >= a} on the circle of latitude z.
// (Integration by parts; differentiate to check.)
double latitude_angle_integral(double a, double z) {
  if (a == 0.0) return 0.5 * kPi * z;
  const double w = std::sqrt(std::max(0.0, (1.0 - a) * (1.0 + a) - z * z));  // sqrt(rho^2 - a^2)
  return z * std::atan2(w, a) - a * std::atan2(z, w) + std::atan2(a * z, w);
}

// Volume of the unit ball ∩ {X >= a, Y >= b, Z >= c} for a, b, c >= 0.
double unit_ball_corner(double a, double b, double c) {
  if (a * a + b * b + c * c >= 1.0) return 0.0;
  // Spherical patch: latitudes z in [c, h] where the arc {X >= a, Y >= b} is not empty,
  // of angular length acos(a/rho) + acos(b/rho) - pi/2.
  const double h = std::sqrt(std::max(0.0, 1.0 - a * a - b * b));
  auto patch = [&](double z) {
    return latitude_angle_integral(a, z) + latitude_angle_integral(b, z) - 0.5 * kPi * z;
  };
  const double sphere_area = patch(h) - patch(c);
  // Flat faces: the face X = a is a disk of radius^2 1 - a^2 cut at (b, c), and so on.
  auto face = [](double offset, double u, double v) {
    const double k2 = (1.0 - offset) * (1.0 + offset);
    const double k = std::sqrt(k2);
    return k2 * unit_disk_corner(u / k, v / k);
  };
  const double flat = a * face(a, b, c) + b * face(b, a, c) + c * face(c, a, b);
  return (sphere_area - flat) / 3.0;
}

// Volume of the unit ball ∩ {X >= a, Y >= b, Z >= c}, any a, b, c.
double unit_ball_octant(double a, double b, double c) {
  if (a >= 1.0 || b >= 1.0 || c >= 1.0) return 0.0;
  if (a < 0.0) return 2.0 * unit_ball_octant(0.0, b, c) - unit_ball_octant(-a, b, c);
  if (b < 0.0) return 2.0 * unit_ball_octant(a, 0.0, c) - unit_ball_octant(a, -b, c);
  if (c < 0.0) return 2.0 * unit_ball_octant(a, b, 0.0) - unit_ball_octant(a, b, -c);
  return unit_ball_corner(a, b, c);
}

}  // namespace

double ball_measure(int dim, double r) {
  return dim == 2 ? kPi * r * r : 4.0 / 3.0 * kPi * r * r * r;
}

double cut_radius(double r, double h) {
  const double d = std::abs(h);
  return d >= r ? 0.0 : std::sqrt((r - d) * (r + d));
}

double disk_segment_area(double r, double h) {
  if (h >= r) return 0.0;
  if (h <= -r) return kPi * r * r;
  return r * r * std::acos(h / r) - h * cut_radius(r, h);
}

double sphere_cap_volume(double r, double h) {
  if (h >= r) return 0.0;
  if (h <= -r) return 4.0 / 3.0 * kPi * r * r * r;
  return kPi * (r - h) * (r - h) * (2.0 * r + h) / 3.0;
}

double interval_overlap(double c, double w, double x0, double x1) {
  return std::max(0.0, std::min(c + w, x1) - std::max(c - w, x0));
}

double disk_rectangle_area(const Eigen::Vector2d& c, double r, const Eigen::Vector2d& lo,
                           const Eigen::Vector2d& hi) {
  if (!(r > 0.0)) return 0.0;
  bool inside = true;
  for (int a = 0; a < 2; ++a) {
    if (c[a] + r <= lo[a] || c[a] - r >= hi[a] || hi[a] <= lo[a]) return 0.0;
    inside = inside && lo[a] <= c[a] - r && c[a] + r <= hi[a];
  }
  if (inside) return kPi * r * r;
  const double x0 = (lo[0] - c[0]) / r, x1 = (hi[0] - c[0]) / r;
  const double y0 = (lo[1] - c[1]) / r, y1 = (hi[1] - c[1]) / r;
  const double q = unit_disk_quadrant(x0, y0) - unit_disk_quadrant(x1, y0) -
                   unit_disk_quadrant(x0, y1) + unit_disk_quadrant(x1, y1);
  return r * r * q;
}

double sphere_box_volume(const Eigen::Vector3d& c, double r, const Eigen::Vector3d& lo,
                         const Eigen::Vector3d& hi) {
  if (!(r > 0.0)) return 0.0;
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    if (c[a] + r <= lo[a] || c[a] - r >= hi[a] || hi[a] <= lo[a]) return 0.0;
    inside = inside && lo[a] <= c[a] - r && c[a] + r <= hi[a];
  }
  if (inside) return 4.0 / 3.0 * kPi * r * r * r;
  double u[3][2];
  for (int a = 0; a < 3; ++a) {
    u[a][0] = (lo[a] - c[a]) / r;
    u[a][1] = (hi[a] - c[a]) / r;
  }
  double v = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const double sign = ((i + j + k) % 2 == 0) ? 1.0 : -1.0;
        v += sign * unit_ball_octant(u[0][i], u[1][j], u[2][k]);
      }
  return r * r * r * v;
}

double ball_box_measure(int dim, const double* c, double r, const double* lo, const double* hi) {
  if (dim == 2) {
    return disk_rectangle_area({c[0], c[1]}, r, {lo[0], lo[1]}, {hi[0], hi[1]});
  }
  return sphere_box_volume({c[0], c[1], c[2]}, r, {lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]});
}

}  // namespace granpipe::overlap
