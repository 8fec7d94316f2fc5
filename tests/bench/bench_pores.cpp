// The whole pores analysis of one saved frame against CGAL's bare Delaunay triangulation
// of the same centres: a plain timing binary, driven by tests/bench/pores_vs_qhull.py.
//
//   bench_pores points FRAMES.h5 OUT    the frame's centres as rows of three little-endian doubles
//   bench_pores bare FRAMES.h5          CGAL's Delaunay triangulation of the centres, one thread
//   bench_pores analysis FRAMES.h5 THREADS
//                                       measure_pores (triangulation, merge, cell volumes)
//                                       and the histograms, region inner (margin 2 R)
//
// The first frame of the H5MD file is read; bare and analysis print the peak resident
// memory before the timed part ("memory_before_kb": the frame, the libraries), then its
// wall-clock "seconds", the "cpu_seconds" of all threads, and what they made.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "granpipe/frame_store.hpp"
#include "granpipe/huge_pages.hpp"
#include "measure_pores.hpp"
#include "pore_statistics.hpp"
#include "volume_distribution.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// Wall-clock and processor time since it was made.
struct Stopwatch {
  Clock::time_point start = Clock::now();
  std::clock_t cpu_start = std::clock();

  void print() const {
    std::printf("seconds %.4f\ncpu_seconds %.4f\n",
                std::chrono::duration<double>(Clock::now() - start).count(),
                static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
  }
};

void print_memory_before() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("memory_before_kb %ld\n", usage.ru_maxrss);
}

void write_points(const granpipe::Frame& f, const std::string& path) {
  std::vector<double> rows;
  rows.reserve(3 * static_cast<std::size_t>(f.size()));
  for (Eigen::Index k = 0; k < f.size(); ++k)
    for (int a = 0; a < 3; ++a) rows.push_back(f.position()(k, a));
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(rows.data()),
             static_cast<std::streamsize>(rows.size() * sizeof(double)));
  std::printf("points %td\n", f.size());
}

void bare_triangulation(const granpipe::Frame& f) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> points;
  points.reserve(static_cast<std::size_t>(f.size()));
  for (Eigen::Index k = 0; k < f.size(); ++k)
    points.emplace_back(f.position()(k, 0), f.position()(k, 1), f.position()(k, 2));
  print_memory_before();
  const Stopwatch watch;
  const CGAL::Delaunay_triangulation_3<Kernel> t(points.begin(), points.end());
  watch.print();
  std::printf("cells %zu\n", t.number_of_finite_cells());
}

void whole_analysis(const granpipe::Frame& f, int threads) {
  granpipe::pores::PoreSettings settings;
  settings.region.kind = granpipe::pores::RegionKind::Inner;
  settings.threads = threads;
  granpipe::pores::PoreStatistics statistics(0.01, 1.0);
  granpipe::pores::VolumeDistribution volumes(0.005, 0.5, 0.0711);
  print_memory_before();
  const Stopwatch watch;
  const auto m = granpipe::pores::measure_pores(f, settings, "bench");
  statistics.add(m);
  volumes.add(m.xi);
  watch.print();
  std::printf("cells %ld\npores %zu\nundefined_volumes %ld\n", m.cells, m.xi.size(),
              m.undefined_volumes);
}

}  // namespace

int main(int argc, char** argv) {
  // As granpipe does; the bare triangulation keeps the environment it is given.
  if (argc > 1 && std::string(argv[1]) == "analysis")
    granpipe::huge_pages::restart_with_malloc_huge_pages(argv);
  const std::string mode = argc > 2 ? argv[1] : "";
  if (!((mode == "points" && argc == 4) || (mode == "bare" && argc == 3) ||
        (mode == "analysis" && argc == 4))) {
    std::fprintf(stderr,
                 "usage: bench_pores points FRAMES.h5 OUT | bare FRAMES.h5 | analysis FRAMES.h5 "
                 "THREADS\n");
    return 2;
  }
  const granpipe::Frame f = granpipe::FrameReader(argv[2]).read(0);
  if (mode == "points") write_points(f, argv[3]);
  if (mode == "bare") bare_triangulation(f);
  if (mode == "analysis") whole_analysis(f, std::stoi(argv[3]));
}
