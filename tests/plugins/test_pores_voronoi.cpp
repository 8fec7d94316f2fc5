// Each sphere's Voronoi cell (Laguerre cell for unequal radii) from the pores analyzer's
// triangulation: the crystals' cells of known volume, in periodic boxes and in walls (the
// cells there cut at the walls), volumes that fill a periodic box and a walled one, a
// radical plane placed by hand between spheres of two sizes, and the cells left undefined
// under an open top.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "crystals.hpp"
#include "granpipe/frame.hpp"
#include "measure_pores.hpp"

namespace {

using granpipe::Container;
using granpipe::Frame;
using granpipe::pores::measure_pores;
using granpipe::pores::PoreMeasurement;
using granpipe::test::Crystal;
using granpipe::test::crystal_frame;

PoreMeasurement measure(const Frame& f) { return measure_pores(f, std::nullopt, 1e-9, "test"); }

void expect_every_volume(const PoreMeasurement& m, double volume, const std::string& name) {
  EXPECT_EQ(m.undefined_volumes, 0) << name;
  for (Eigen::Index k = 0; k < m.cell_volume.size(); ++k)
    EXPECT_NEAR(m.cell_volume[k] / volume, 1.0, 1e-9) << name << " particle " << k;
}

// Periodic boxes of 3^3 unit cells, the crystal moved off the box's corner or not: the
// cells of touching spheres are the cube 8 R^3 (sc), the truncated octahedron
// 32 / (3 sqrt 3) R^3 (bcc), the rhombic and trapezo-rhombic dodecahedra 4 sqrt 2 R^3
// (fcc, hcp): one sphere per cell, packing fraction pi / (3 sqrt 2) for the last two.
TEST(PoresVoronoi, CrystalCellsInPeriodicBoxes) {
  using namespace granpipe::test;
  const std::vector<std::pair<Crystal, double>> crystals{{sc(), 8.0},
                                                         {bcc(), 32.0 / (3.0 * std::sqrt(3.0))},
                                                         {fcc(), 4.0 * std::sqrt(2.0)},
                                                         {hcp(), 4.0 * std::sqrt(2.0)}};
  for (const auto& [c, volume] : crystals) {
    for (double offset : {0.0, 0.37}) {
      Frame f = crystal_frame(c, 3);
      f.container = Container::periodic_box(3, {0, 0, 0}, 3 * c.cell);
      f.position().rowwise() += offset * c.cell.transpose().array();
      expect_every_volume(measure(f), volume, "offset " + std::to_string(offset));
    }
  }
}

// Spheres of `radius` (or radii in [radius / 2, radius]) at random without overlap in a
// cube of side `side`, periodic or walled (the spheres inside).
Frame random_spheres(int n, double side, double radius, bool unequal, unsigned seed,
                     bool periodic = true) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(periodic ? 0.0 : radius,
                                                    periodic ? side : side - radius);
  std::uniform_real_distribution<double> r(radius / 2.0, radius);
  Frame f;
  f.resize(n, 3);
  f.container = Container::periodic_box(3, {0, 0, 0}, {side, side, side});
  if (!periodic) f.container = Container{};  // walls on every side
  f.container.hi.setConstant(side);
  for (Eigen::Index k = 0; k < f.size();) {
    const Eigen::Vector3d x(coordinate(rng), coordinate(rng), coordinate(rng));
    const double rk = unequal ? r(rng) : radius;
    bool free = true;
    for (Eigen::Index j = 0; j < k && free; ++j) {
      Eigen::Vector3d d = x - f.position().row(j).transpose().matrix();
      for (int a = 0; a < 3; ++a) d[a] = f.container.minimum_image(a, d[a]);
      free = d.norm() >= rk + f.radius()[j];
    }
    if (!free) continue;
    f.position().row(k) = x.transpose().array();
    f.radius()[k++] = rk;
  }
  return f;
}

// The cells of a periodic packing tile its box, Voronoi and Laguerre alike.
TEST(PoresVoronoi, RandomPeriodicCellsFillTheBox) {
  for (bool unequal : {false, true}) {
    const double side = 16.0;  // packing fraction 0.2 (equal radii)
    const PoreMeasurement m = measure(random_spheres(200, side, 1.0, unequal, 7));
    EXPECT_EQ(m.undefined_volumes, 0);
    EXPECT_EQ(m.hidden_spheres, 0);
    EXPECT_NEAR(m.cell_volume.sum() / (side * side * side), 1.0, 1e-9) << unequal;
    EXPECT_GT(m.cell_volume.minCoeff(), 0.0);
  }
}

// The cells of a packing in a box of walls tile the box: those at the walls cut there
// (the triangulation leaves them unbounded or reaching through a wall).
TEST(PoresVoronoi, RandomCellsInWallsFillTheBox) {
  for (bool unequal : {false, true}) {
    const double side = 16.0;
    const PoreMeasurement m = measure(random_spheres(200, side, 1.0, unequal, 8, false));
    EXPECT_EQ(m.undefined_volumes, 0);
    EXPECT_EQ(m.hidden_spheres, 0);
    EXPECT_NEAR(m.cell_volume.sum() / (side * side * side), 1.0, 1e-9) << unequal;
    EXPECT_GT(m.cell_volume.minCoeff(), 0.0);
  }
}

// A simple cubic crystal in walls one radius from its outermost spheres: cut at the
// walls, every cell is the cube 8 R^3, at the faces, edges and corners too.
TEST(PoresVoronoi, CubicCrystalInWallsHasCubicCellsAtTheWalls) {
  for (double radius : {1e-3, 1.0, 1e3}) {
    const PoreMeasurement m = measure(crystal_frame(granpipe::test::sc(), 5, radius));
    expect_every_volume(m, 8.0 * radius * radius * radius, "radius " + std::to_string(radius));
  }
}

// The same crystal periodic along x and y, walled along z, in units from 1e-15 to 1e3: the
// cells cut at the walls were cut with planes a container's length plus 1 (in the file's
// unit) away, and at radius 1e-15 their volumes came out 11 % off.
TEST(PoresVoronoi, VolumesDoNotDependOnTheLengthUnit) {
  for (double radius : {1e-15, 1e-12, 1.0, 1e3}) {
    Frame f = crystal_frame(granpipe::test::sc(), 5, radius);
    for (int a = 0; a < 2; ++a)
      f.container.boundary[a] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
    expect_every_volume(measure(f), 8.0 * radius * radius * radius,
                        "radius " + std::to_string(radius));
  }
}

// Layers of a simple cubic crystal (spacing a) alternate between radii r1 and r2 along z,
// in a periodic box. The radical plane of two spheres at distance a, where their powers
// |x - x_i|^2 - r_i^2 are equal, lies at t = (a^2 + r1^2 - r2^2) / (2a) from the r1 centre
// (beside equal spheres, halfway): the cells are square prisms a x a x 2t and a x a x
// 2(a - t), a^3 +- a (r1^2 - r2^2).
TEST(PoresVoronoi, LaguerrePlaneBetweenTwoSizes) {
  const double a = 2.0, r1 = 1.0, r2 = 0.6;
  const int n = 4;
  Frame f;
  f.resize(n * n * n, 3);
  Eigen::Index k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l, ++k) {
        f.position().row(k) << a * i + 0.3, a * j + 0.3, a * l + 0.3;
        f.radius()[k] = l % 2 == 0 ? r1 : r2;
      }
  f.container = Container::periodic_box(3, {0, 0, 0}, {n * a, n * a, n * a});
  const PoreMeasurement m = measure(f);
  EXPECT_EQ(m.undefined_volumes, 0);
  const double shift = a * (r1 * r1 - r2 * r2);
  for (Eigen::Index p = 0; p < f.size(); ++p) {
    const double expected = a * a * a + (f.radius()[p] == r1 ? shift : -shift);
    EXPECT_NEAR(m.cell_volume[p] / expected, 1.0, 1e-9) << p;
  }
}

// A simple cubic crystal with walls at its sides and bottom and an open top: the top
// layer's cells are unbounded (NaN, counted), the others cubes of 8 R^3.
TEST(PoresVoronoi, OpenTopLeavesTheTopLayerUndefined) {
  const int n = 4;
  Frame f = crystal_frame(granpipe::test::sc(), n);
  f.container.boundary[2][1] = granpipe::Boundary::Open;
  const PoreMeasurement m = measure(f);
  const double top = f.position().col(2).maxCoeff();
  EXPECT_EQ(m.undefined_volumes, n * n);
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    if (f.position()(k, 2) == top) {
      EXPECT_TRUE(std::isnan(m.cell_volume[k])) << k;
    } else {
      EXPECT_NEAR(m.cell_volume[k], 8.0, 8e-9) << k;
    }
  }
}

}  // namespace
