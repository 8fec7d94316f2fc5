// The cells behind the pores and the cell volumes: a polyhedron cut by planes against
// volumes worked out by hand; the triangulation of a periodic packing widened by adding
// images against one made with them from the start; and the whole measurement, which
// must give the same bits on any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "convex_cell.hpp"
#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "measure_pores.hpp"
#include "periodic_images.hpp"
#include "skin.hpp"

namespace {

using Eigen::Vector3d;
using granpipe::Container;
using granpipe::Frame;
using granpipe::pores::ConvexCell;

ConvexCell unit_cube() {
  ConvexCell cell;
  cell.reset(Vector3d::Zero(), Vector3d::Ones());
  return cell;
}

TEST(PoresConvexCell, BoxCutByPlanes) {
  ConvexCell cell = unit_cube();
  EXPECT_NEAR(cell.volume(), 1.0, 1e-15);
  cell.cut({1, 0, 0}, 0.25);  // x <= 1/4
  EXPECT_NEAR(cell.volume(), 0.25, 1e-15);
  cell = unit_cube();
  cell.cut({1, 1, 1}, 1.5);  // half the cube, by symmetry
  EXPECT_NEAR(cell.volume(), 0.5, 1e-15);
  cell = unit_cube();
  cell.cut({1, 1, 1}, 1.0);  // the corner tetrahedron
  EXPECT_NEAR(cell.volume(), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(cell.corners().size(), 12u);  // four triangles
  cell = unit_cube();
  cell.cut({1, 0, 0}, 2.0);  // nothing cut
  EXPECT_NEAR(cell.volume(), 1.0, 1e-15);
  cell.cut({1, 0, 0}, -1.0);  // everything cut
  EXPECT_TRUE(cell.empty());
  EXPECT_EQ(cell.volume(), 0.0);
}

// Planes through corners and edges of the cube exactly: the corners on the plane are
// kept once, with no sliver face.
TEST(PoresConvexCell, PlanesThroughCornersAndEdges) {
  ConvexCell cell = unit_cube();
  cell.cut({1, 1, 0}, 1.0);  // through two vertical edges: a prism, half the cube
  EXPECT_NEAR(cell.volume(), 0.5, 1e-15);
  EXPECT_EQ(cell.corners().size(), 3u + 3u + 4u + 4u + 4u);  // 2 triangles, 3 rectangles
  cell.cut({1, 1, 0}, 1.0);  // the same plane again: nothing changes
  EXPECT_NEAR(cell.volume(), 0.5, 1e-15);
  cell.cut({-1, -1, 0}, -1.0);  // the other side of it: a flat remainder
  EXPECT_NEAR(cell.volume(), 0.0, 1e-15);
}

// The octahedron |x| + |y| + |z| <= 1 cut from a box by its eight faces' planes, in any
// order: volume 4/3.
TEST(PoresConvexCell, OctahedronFromEightPlanes) {
  std::vector<Vector3d> normals;
  for (int s = 0; s < 8; ++s) normals.emplace_back(s & 1 ? 1 : -1, s & 2 ? 1 : -1, s & 4 ? 1 : -1);
  std::mt19937 rng(5);
  for (int round = 0; round < 5; ++round) {
    std::shuffle(normals.begin(), normals.end(), rng);
    ConvexCell cell;
    cell.reset(Vector3d::Constant(-3.0), Vector3d::Constant(2.0));
    for (const Vector3d& n : normals) cell.cut(n, 1.0);
    EXPECT_NEAR(cell.volume(), 4.0 / 3.0, 1e-14) << round;
    for (const Vector3d& c : cell.corners()) EXPECT_NEAR(c.lpNorm<1>(), 1.0, 1e-14);
  }
}

// Spheres of radius 1 at random (overlaps allowed: the cells do not care) in a box.
Frame random_frame(int n, double side, const Container& c, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(1.0, side - 1.0);
  Frame f;
  f.resize(n, 3);
  f.radius().setConstant(1.0);
  f.container = c;
  for (Eigen::Index k = 0; k < n; ++k)
    f.position().row(k) << coordinate(rng), coordinate(rng), coordinate(rng);
  return f;
}

// The circumcentres of the cells around the box (those far out, at the hull of the images,
// are flat and their centres set by rounding), to 1e-6 and sorted: the triangulation as a
// set of cells, whatever the rows of its points (which round the last bits differently).
std::vector<std::array<long, 3>> circumcentres(granpipe::pores::DelaunayTriangulation& t,
                                               double side) {
  std::vector<std::array<long, 3>> centres;
  for (const auto& cell : t.cells(1e-9, 1)) {
    const Vector3d c = cell.centre;
    if ((c.array() > -1.0).all() && (c.array() < side + 1.0).all())
      centres.push_back(
          {std::lround(c[0] * 1e6), std::lround(c[1] * 1e6), std::lround(c[2] * 1e6)});
  }
  std::sort(centres.begin(), centres.end());
  return centres;
}

// A triangulation of the centres with their images within 2, widened to 5 by adding the
// images between, has the cells of one made with the images within 5 from the start
// (the Delaunay triangulation of a set of points is one, whatever the order they come in).
TEST(PoresCells, WideningTheSkinGivesTheCellsOfTheWiderSkin) {
  using namespace granpipe::pores;
  const double side = 12.0;
  const Frame f =
      random_frame(300, side, Container::periodic_box(3, {0, 0, 0}, {side, side, side}), 9);
  Centres narrow = centres_with_images(f, 2.0);
  DelaunayTriangulation widened(narrow, f, "test");
  widened.insert(images_between(f, 2.0, 5.0).points);
  DelaunayTriangulation wide(centres_with_images(f, 5.0), f, "test");
  const auto a = circumcentres(widened, side);
  EXPECT_GT(a.size(), 6u * 300u);
  EXPECT_EQ(a, circumcentres(wide, side));
}

// A deep box with periodic sides, a wall below and an open top: the first skin is 4 radii
// wide in the bulk and 10 in the bands along the wall (8 radii deep) and the packing's top
// (24 deep); a sphere has the band's width only when it lies in the band whole.
TEST(PoresCells, SkinIsWiderInBandsAlongTheOtherSides) {
  using namespace granpipe::pores;
  Container c = Container::open_top_box(3, {0, 0, 0}, {100, 100, 120});
  for (int a = 0; a < 2; ++a)
    c.boundary[a] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  const Frame f = random_frame(300, 100.0, c, 3);
  const Skin skin = first_skin(f, 1.0);
  const double top = (f.position().col(2).array() + 1.0).maxCoeff();
  EXPECT_EQ(skin.bulk, 4.0);
  EXPECT_EQ(skin.edge, 10.0);
  EXPECT_EQ(skin.band[2][0], 8.0);
  EXPECT_EQ(skin.band[2][1], top - 24.0);
  EXPECT_EQ(skin.at({50, 50, 7}), 10.0);
  EXPECT_EQ(skin.at({50, 50, 12}), 4.0);
  EXPECT_EQ(skin.at({50, 50, top - 20.0}), 10.0);
  EXPECT_EQ(skin.around({50, 50, top - 20.0}, 3.0), 10.0);
  EXPECT_EQ(skin.around({50, 50, top - 20.0}, 5.0), 4.0);  // reaches below the band
  const Skin wider = skin.wider(1.0, 100.0);
  EXPECT_DOUBLE_EQ(wider.bulk, 5.5);
  EXPECT_DOUBLE_EQ(wider.edge, 11.5);
  // The images a wider skin adds lie within its widths, beyond the first's.
  const Centres added = images_between(f, skin, wider);
  EXPECT_FALSE(added.points.empty());
  for (const Vector3d& x : added.points) {
    const double out = std::max({-x[0], x[0] - 100.0, -x[1], x[1] - 100.0});
    EXPECT_LT(out, wider.at(x));
    EXPECT_GE(out, skin.at(x));
  }
}

template <class T>
bool same_bits(const T& a, const T& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

// The pores and the cells on one, two and three threads: the same bits. Equal and unequal
// radii, in walls (cells cut there) and in a periodic box (skin widened).
TEST(PoresCells, ResultsDoNotDependOnTheThreads) {
  const double side = 14.0;
  Container walls;
  walls.hi.setConstant(side);
  for (const Container& c : {walls, Container::periodic_box(3, {0, 0, 0}, {side, side, side})}) {
    for (bool unequal : {false, true}) {
      Frame f = random_frame(400, side, c, 11);
      if (unequal) f.radius() = 0.5 + 0.5 * (Eigen::ArrayXd::LinSpaced(f.size(), 0, 1));
      const auto one = granpipe::pores::measure_pores(f, std::nullopt, 1e-9, "test", 1);
      for (int threads : {2, 3}) {
        const auto more = granpipe::pores::measure_pores(f, std::nullopt, 1e-9, "test", threads);
        EXPECT_TRUE(same_bits(one.xi, more.xi)) << threads;
        EXPECT_TRUE(same_bits(one.cell_volume, more.cell_volume)) << threads;
        ASSERT_EQ(one.pores.size(), more.pores.size());
        for (std::size_t k = 0; k < one.pores.size(); ++k) {
          EXPECT_TRUE(same_bits(one.pores[k].centre, more.pores[k].centre)) << k;
          EXPECT_EQ(one.pores[k].cells, more.pores[k].cells) << k;
        }
      }
    }
  }
}

}  // namespace
