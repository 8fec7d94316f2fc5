// The whole pores measurement of one frame against CGAL's bare Delaunay triangulation of
// the same centres: a plain timing binary.
//
//   bench_pores N [walls|periodic]
//
// N random non-overlapping spheres of radius 1 (random sequential addition to a packing
// fraction of 0.3) in a cube, periodic or walled. Prints the seconds of each step.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "cell_volumes.hpp"
#include "delaunay_cells.hpp"
#include "measure_pores.hpp"
#include "merge_cells.hpp"
#include "periodic_images.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Random sequential addition on a grid of cells whose diagonal is below one diameter: each
// cell holds at most one centre, and the 125 around a trial point every sphere it could
// overlap.
granpipe::Frame random_spheres(long n, bool periodic) {
  constexpr double kPhi = 0.3;
  const double side = std::cbrt(static_cast<double>(n) * 4.0 * M_PI / 3.0 / kPhi);
  const int cells = static_cast<int>(side / (2.0 / std::sqrt(3.0)));
  const double cell = side / cells;
  std::vector<int> grid(static_cast<std::size_t>(cells) * cells * cells, -1);
  granpipe::Frame f;
  f.resize(n, 3);
  f.radius().setConstant(1.0);
  f.container = periodic ? granpipe::Container::periodic_box(3, {0, 0, 0}, {side, side, side})
                         : granpipe::Container{};
  if (!periodic) f.container.hi.setConstant(side);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(periodic ? 0.0 : 1.0, periodic ? side : side - 1.0);
  const auto wrap = [&](int i) { return (i % cells + cells) % cells; };
  for (long k = 0; k < n;) {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    const int ci = static_cast<int>(x[0] / cell), cj = static_cast<int>(x[1] / cell),
              cl = static_cast<int>(x[2] / cell);
    bool free = true;
    for (int di = -2; di <= 2 && free; ++di)
      for (int dj = -2; dj <= 2 && free; ++dj)
        for (int dl = -2; dl <= 2 && free; ++dl) {
          const int other =
              grid[(static_cast<std::size_t>(wrap(ci + di)) * cells + wrap(cj + dj)) * cells +
                   wrap(cl + dl)];
          if (other < 0) continue;
          Eigen::Vector3d d = x - f.position().row(other).transpose().matrix();
          for (int a = 0; a < 3; ++a) d[a] = f.container.minimum_image(a, d[a]);
          free = d.norm() >= 2.0;
        }
    const std::size_t own = (static_cast<std::size_t>(ci) * cells + cj) * cells + cl;
    if (!free || grid[own] >= 0) continue;
    grid[own] = static_cast<int>(k);
    f.position().row(k++) = x.transpose().array();
  }
  return f;
}

double bare_triangulation(const granpipe::Frame& f) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> points;
  points.reserve(static_cast<std::size_t>(f.size()));
  for (Eigen::Index k = 0; k < f.size(); ++k)
    points.emplace_back(f.position()(k, 0), f.position()(k, 1), f.position()(k, 2));
  const auto start = Clock::now();
  const CGAL::Delaunay_triangulation_3<Kernel> t(points.begin(), points.end());
  const double s = seconds_since(start);
  std::printf("cells %zu\n", t.number_of_finite_cells());
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_pores N [walls|periodic]\n");
    return 2;
  }
  const long n = std::stol(argv[1]);
  const bool periodic = argc < 3 || std::string(argv[2]) == "periodic";
  const granpipe::Frame f = random_spheres(n, periodic);
  std::printf("bare triangulation %.3f s\n", bare_triangulation(f));
  auto start = Clock::now();
  const auto m = granpipe::pores::measure_pores(f, std::nullopt, 1e-9, "bench");
  std::printf("measure_pores %.3f s (%zu pores)\n", seconds_since(start), m.xi.size());
  using namespace granpipe::pores;
  start = Clock::now();
  const Centres centres = centres_with_images(f, 4.0);
  std::printf("  images %.3f s\n", seconds_since(start));
  start = Clock::now();
  DelaunayTriangulation t(centres, f, "bench");
  std::printf("  triangulation %.3f s\n", seconds_since(start));
  start = Clock::now();
  const auto cells = t.cells();
  std::printf("  cells %.3f s\n", seconds_since(start));
  start = Clock::now();
  const auto merged = merge_cells(cells, 1.0, 1e-9);
  std::printf("  merge %.3f s\n", seconds_since(start));
  start = Clock::now();
  const auto volumes = voronoi_volumes(t, cells, centres, f, 1e-9);
  std::printf("  volumes %.3f s (skin needed %.2f)\n", seconds_since(start), volumes.skin_needed);
}
