// Exact disk/sphere overlaps with rectangles and boxes, checked against analytic
// special cases and against independent computations (high-order quadrature of chord
// lengths and of cross-section areas, and tilings of space).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "granpipe/overlap.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using granpipe::overlap::disk_rectangle_area;
using granpipe::overlap::sphere_box_volume;

constexpr double kPi = std::numbers::pi;
constexpr double kBig = 1e3;  // "infinite" extent of a region, in units of the radius

// Gauss-Legendre nodes and weights on [-1, 1] by Newton's method on P_n.
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x.push_back(z);
      w.push_back(2.0 / ((1 - z * z) * dp * dp));
    }
  }
};

// One piece [lo, hi] with z = mid - half cos(t), which makes square-root behaviour at the
// ends smooth, then Gauss-Legendre in t; bisected until two orders agree, which copes
// with a singularity just outside the piece.
double integrate_piece(const std::function<double(double)>& f, double lo, double hi, int depth) {
  static const GaussLegendre coarse(24), fine(48);
  auto rule = [&](const GaussLegendre& gl) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double sum = 0;
    for (std::size_t k = 0; k < gl.x.size(); ++k) {
      const double t = 0.5 * kPi * (gl.x[k] + 1);  // t in [0, pi]
      sum += gl.w[k] * 0.5 * kPi * f(mid - half * std::cos(t)) * half * std::sin(t);
    }
    return sum;
  };
  const double a = rule(coarse), b = rule(fine);
  if (std::abs(a - b) <= 1e-16 || depth >= 30) return b;
  const double mid = 0.5 * (lo + hi);
  return integrate_piece(f, lo, mid, depth + 1) + integrate_piece(f, mid, hi, depth + 1);
}

// Integral of f over [a, b], split at `breaks` where f is not smooth.
double integrate(const std::function<double(double)>& f, double a, double b,
                 std::vector<double> breaks) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
    const double lo = std::max(a, breaks[p]), hi = std::min(b, breaks[p + 1]);
    if (hi > lo) sum += integrate_piece(f, lo, hi, 0);
  }
  return sum;
}

// Disk ∩ rectangle as the integral over y of the chord length inside [x0, x1].
double disk_rectangle_by_chords(Vector2d c, double r, Vector2d lo, Vector2d hi) {
  auto chord = [&](double y) {
    const double h = y - c.y();
    if (std::abs(h) >= r) return 0.0;
    const double w = std::sqrt(r * r - h * h);
    return std::max(0.0, std::min(c.x() + w, hi.x()) - std::max(c.x() - w, lo.x()));
  };
  std::vector<double> breaks{c.y() - r, c.y() + r};
  for (double x : {lo.x(), hi.x()}) {
    const double d = std::abs(x - c.x());
    if (d < r) {
      breaks.push_back(c.y() - std::sqrt(r * r - d * d));
      breaks.push_back(c.y() + std::sqrt(r * r - d * d));
    }
  }
  return integrate(chord, lo.y(), hi.y(), breaks);
}

// Sphere ∩ box as the integral over z of the cross-section area, with a break wherever
// the section radius equals the distance to a side or a corner of the rectangle.
double sphere_box_by_sections(Vector3d c, double r, Vector3d lo, Vector3d hi) {
  auto section = [&](double z) {
    const double h = z - c.z();
    if (std::abs(h) >= r) return 0.0;
    return disk_rectangle_area(c.head<2>(), std::sqrt(r * r - h * h), lo.head<2>(), hi.head<2>());
  };
  std::vector<double> breaks{c.z() - r, c.z() + r}, dists;
  for (double x : {lo.x(), hi.x()})
    for (double y : {lo.y(), hi.y()}) {
      const double dx = x - c.x(), dy = y - c.y();
      dists.insert(dists.end(), {std::abs(dx), std::abs(dy), std::hypot(dx, dy)});
    }
  for (double d : dists) {
    if (d < r) {
      breaks.push_back(c.z() - std::sqrt(r * r - d * d));
      breaks.push_back(c.z() + std::sqrt(r * r - d * d));
    }
  }
  return integrate(section, lo.z(), hi.z(), breaks);
}

TEST(Overlap, WholeDiskAndSphereInside) {
  EXPECT_DOUBLE_EQ(disk_rectangle_area({0.3, -0.2}, 1.5, {-5, -5}, {5, 5}), kPi * 2.25);
  EXPECT_DOUBLE_EQ(sphere_box_volume({0.3, -0.2, 1}, 1.5, {-5, -5, -5}, {5, 5, 5}),
                   4.0 / 3.0 * kPi * 3.375);
  EXPECT_EQ(sphere_box_volume({0, 0, 0}, 1, {1, -5, -5}, {5, 5, 5}), 0.0);
  EXPECT_EQ(disk_rectangle_area({0, 0}, 1, {-5, -5}, {5, -1}), 0.0);
}

TEST(Overlap, DiskAtCornerEdgeAndFace) {
  const double r = 0.7, area = kPi * r * r;
  // Centre at the corner of a large rectangle: a quarter; on an edge: a half.
  EXPECT_NEAR(disk_rectangle_area({2, 3}, r, {2, 3}, {kBig, kBig}), area / 4, 1e-15 * area);
  EXPECT_NEAR(disk_rectangle_area({2, 3}, r, {2, -kBig}, {kBig, kBig}), area / 2, 1e-15 * area);
  EXPECT_NEAR(disk_rectangle_area({2, 3}, r, {-kBig, -kBig}, {kBig, 3}), area / 2, 1e-15 * area);
}

TEST(Overlap, SphereAtCornerEdgeAndFace) {
  const double r = 1.3, vol = 4.0 / 3.0 * kPi * r * r * r;
  const Vector3d c(0.5, -1, 2);
  EXPECT_NEAR(sphere_box_volume(c, r, c, c + Vector3d::Constant(kBig)), vol / 8, 1e-15 * vol);
  EXPECT_NEAR(sphere_box_volume(c, r, {0.5, -1, -kBig}, {kBig, kBig, kBig}), vol / 4, 1e-15 * vol);
  EXPECT_NEAR(sphere_box_volume(c, r, {-kBig, -kBig, -kBig}, {kBig, -1, kBig}), vol / 2,
              1e-15 * vol);
  // Centre at the high corner: the octant below, left and behind.
  EXPECT_NEAR(sphere_box_volume(c, r, c - Vector3d::Constant(kBig), c), vol / 8, 1e-15 * vol);
}

TEST(Overlap, SphereHalfSpaceIsTheCapFormula) {
  const double r = 0.8;
  for (double h : {-0.79, -0.5, -0.1, 0.0, 0.25, 0.6, 0.7999}) {
    const double cap = kPi * (r - h) * (r - h) * (2 * r + h) / 3.0;
    EXPECT_NEAR(sphere_box_volume({0, 0, 0}, r, {-kBig, -kBig, h}, Vector3d::Constant(kBig)), cap,
                2e-15 * r * r * r)
        << "h = " << h;
    // Same cut along x and y: the formula does not single out an axis.
    EXPECT_NEAR(sphere_box_volume({0, 0, 0}, r, {h, -kBig, -kBig}, Vector3d::Constant(kBig)), cap,
                2e-15 * r * r * r);
    EXPECT_NEAR(granpipe::overlap::sphere_cap_volume(r, h), cap, 1e-15 * r * r * r);
  }
}

TEST(Overlap, SphereSlabIsADifferenceOfCaps) {
  const double r = 1.0;
  auto cap = [&](double h) { return kPi * (r - h) * (r - h) * (2 * r + h) / 3.0; };
  const double z0 = -0.37, z1 = 0.52;
  EXPECT_NEAR(sphere_box_volume({0, 0, 0}, r, {-kBig, -kBig, z0}, {kBig, kBig, z1}),
              cap(z0) - cap(z1), 2e-15);
}

TEST(Overlap, DiskSegmentFormula) {
  const double r = 2.0;
  for (double h : {-1.9, -0.3, 0.0, 1.2, 1.99}) {
    const double seg = r * r * std::acos(h / r) - h * std::sqrt(r * r - h * h);
    EXPECT_NEAR(disk_rectangle_area({0, 0}, r, {-kBig, h}, {kBig, kBig}), seg, 4e-15 * r * r);
    EXPECT_NEAR(granpipe::overlap::disk_segment_area(r, h), seg, 4e-15 * r * r);
  }
}

TEST(Overlap, DiskRectangleMatchesChordQuadrature) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5), len(0.05, 2.5);
  for (int trial = 0; trial < 300; ++trial) {
    const double r = 1.0;
    const Vector2d c(u(rng), u(rng));
    const Vector2d lo(u(rng), u(rng));
    const Vector2d hi = lo + Vector2d(len(rng), len(rng));
    const double exact = disk_rectangle_area(c, r, lo, hi);
    const double quad = disk_rectangle_by_chords(c, r, lo, hi);
    ASSERT_NEAR(exact, quad, 1e-14) << "trial " << trial;
  }
}

TEST(Overlap, SphereBoxMatchesSectionQuadrature) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.4, 1.4), len(0.05, 2.5);
  for (int trial = 0; trial < 200; ++trial) {
    const double r = 1.0;
    const Vector3d c(u(rng), u(rng), u(rng));
    const Vector3d lo(u(rng), u(rng), u(rng));
    const Vector3d hi = lo + Vector3d(len(rng), len(rng), len(rng));
    const double exact = sphere_box_volume(c, r, lo, hi);
    const double quad = sphere_box_by_sections(c, r, lo, hi);
    ASSERT_NEAR(exact, quad, 1e-14) << "trial " << trial;
  }
}

// Boxes tiling space cut a sphere into pieces whose volumes add up to the whole sphere.
TEST(Overlap, TilingPiecesAddUpToTheWholeSphere) {
  const double r = 0.9, s = 0.37;
  const Vector3d c(0.123, -0.456, 0.0789);
  double sum = 0;
  for (int i = -4; i < 4; ++i)
    for (int j = -4; j < 4; ++j)
      for (int k = -4; k < 4; ++k) {
        const Vector3d lo(i * s, j * s, k * s);
        sum += sphere_box_volume(c, r, lo, lo + Vector3d::Constant(s));
      }
  const double vol = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(sum, vol, 1e-14 * vol);

  double area = 0;
  for (int i = -4; i < 4; ++i)
    for (int j = -4; j < 4; ++j) {
      const Vector2d lo(i * s, j * s);
      area += disk_rectangle_area(c.head<2>(), r, lo, lo + Vector2d::Constant(s));
    }
  EXPECT_NEAR(area, kPi * r * r, 1e-14 * kPi * r * r);
}

TEST(Overlap, ScalesWithTheRadius) {
  const Vector3d c(0.2, 0.1, -0.3), lo(-0.4, -1, 0.05), hi(0.7, 0.3, 2);
  const double v1 = sphere_box_volume(c, 1.0, lo, hi);
  const double v3 = sphere_box_volume(3.0 * c, 3.0, 3.0 * lo, 3.0 * hi);
  EXPECT_NEAR(v3, 27.0 * v1, 1e-14 * v3);
}

TEST(Overlap, CutsAndIntervals) {
  EXPECT_DOUBLE_EQ(granpipe::overlap::cut_radius(1.0, 0.6), 0.8);
  EXPECT_EQ(granpipe::overlap::cut_radius(1.0, -1.0), 0.0);
  EXPECT_DOUBLE_EQ(granpipe::overlap::interval_overlap(0.0, 1.0, -0.5, 3.0), 1.5);
  EXPECT_EQ(granpipe::overlap::interval_overlap(0.0, 1.0, 1.0, 3.0), 0.0);
}

}  // namespace
