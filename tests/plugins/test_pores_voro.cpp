// The cell volumes against voro++'s library (Debian voro++-dev), which computes each cell
// on its own by cutting a box with the bisecting planes of the neighbours: an independent
// method, compared to 1e-9 on random packings, Voronoi (equal radii) and radical
// (Laguerre, unequal radii), periodic, and in walls on some sides or all (voro++'s cells
// end at its container's walls). Skipped where the library was not found at configure time.
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <random>

#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"
#include "measure_pores.hpp"

#ifdef GRANPIPE_HAVE_VORO
#include <voro++/voro++.hh>
#endif

namespace {

using granpipe::Frame;

#ifdef GRANPIPE_HAVE_VORO
// Spheres of radii in [r_min, r_max] at random without overlap in a cube, periodic along
// the axes given and walled along the others (the spheres inside).
Frame random_spheres(int n, double side, double r_min, double r_max, unsigned seed,
                     std::array<bool, 3> periodic = {true, true, true}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(r_max, side - r_max), radius(r_min, r_max);
  Frame f;
  f.resize(n, 3);
  f.container = granpipe::Container::periodic_box(3, {0, 0, 0}, {side, side, side});
  for (int a = 0; a < 3; ++a)
    if (!periodic[a])
      f.container.boundary[a] = {granpipe::Boundary::Wall, granpipe::Boundary::Wall};
  for (Eigen::Index k = 0; k < f.size();) {
    const Eigen::Vector3d x(coordinate(rng), coordinate(rng), coordinate(rng));
    const double r = radius(rng);
    bool free = true;
    for (Eigen::Index j = 0; j < k && free; ++j) {
      Eigen::Vector3d d = x - f.position().row(j).transpose().matrix();
      for (int a = 0; a < 3; ++a) d[a] = f.container.minimum_image(a, d[a]);
      free = d.norm() >= r + f.radius()[j];
    }
    if (!free) continue;
    f.position().row(k) = x.transpose().array();
    f.radius()[k++] = r;
  }
  return f;
}

// voro++'s cell volumes, by particle (a radical tessellation for a container_poly).
template <class Container>
Eigen::ArrayXd voro_volumes(Container& con, Eigen::Index n) {
  Eigen::ArrayXd volume = Eigen::ArrayXd::Constant(n, std::nan(""));
  voro::c_loop_all loop(con);
  voro::voronoicell cell;
  if (loop.start()) do {
      if (con.compute_cell(cell, loop)) volume[loop.pid()] = cell.volume();
    } while (loop.inc());
  return volume;
}

// The cells of every particle; the pores counted only away from the walls, whose hull cells
// have pore spheres far wider than a periodic side (refused).
Eigen::ArrayXd our_volumes(const Frame& f) {
  granpipe::Region away;
  for (int a = 0; a < 3; ++a) {
    const bool periodic = f.container.periodic(a);
    away.lo[a] = periodic ? -std::numeric_limits<double>::infinity() : f.container.lo[a] + 1.0;
    away.hi[a] = periodic ? std::numeric_limits<double>::infinity() : f.container.hi[a] - 1.0;
  }
  return granpipe::pores::measure_pores(f, away, 1e-9, "test").cell_volume;
}

void expect_equal(const Eigen::ArrayXd& ours, const Eigen::ArrayXd& theirs) {
  ASSERT_EQ(ours.size(), theirs.size());
  for (Eigen::Index k = 0; k < ours.size(); ++k)
    EXPECT_NEAR(ours[k] / theirs[k], 1.0, 1e-9) << "particle " << k;
}
#endif

TEST(PoresVoro, VoronoiVolumesEqualVoroPlusPlus) {
#ifndef GRANPIPE_HAVE_VORO
  GTEST_SKIP() << "voro++'s library (voro++-dev) not found at configure time";
#else
  const double side = 10.0;
  for (const std::array<bool, 3> periodic :
       {std::array{true, true, true}, std::array{true, true, false},
        std::array{false, false, false}}) {
    const Frame f = random_spheres(400, side, 0.5, 0.5, 3, periodic);
    voro::container con(0, side, 0, side, 0, side, 6, 6, 6, periodic[0], periodic[1], periodic[2],
                        8);
    for (Eigen::Index k = 0; k < f.size(); ++k)
      con.put(static_cast<int>(k), f.position()(k, 0), f.position()(k, 1), f.position()(k, 2));
    expect_equal(our_volumes(f), voro_volumes(con, f.size()));
  }
#endif
}

TEST(PoresVoro, LaguerreVolumesEqualVoroPlusPlusRadical) {
#ifndef GRANPIPE_HAVE_VORO
  GTEST_SKIP() << "voro++'s library (voro++-dev) not found at configure time";
#else
  const double side = 10.0;
  for (const std::array<bool, 3> periodic :
       {std::array{true, true, true}, std::array{true, true, false},
        std::array{false, false, false}}) {
    const Frame f = random_spheres(400, side, 0.3, 0.6, 4, periodic);
    voro::container_poly con(0, side, 0, side, 0, side, 6, 6, 6, periodic[0], periodic[1],
                             periodic[2], 8);
    for (Eigen::Index k = 0; k < f.size(); ++k) {
      con.put(static_cast<int>(k), f.position()(k, 0), f.position()(k, 1), f.position()(k, 2),
              f.radius()[k]);
    }
    expect_equal(our_volumes(f), voro_volumes(con, f.size()));
  }
#endif
}

}  // namespace
