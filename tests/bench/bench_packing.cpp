// Cost of one frame of the packing analyzer (region fraction, contacts, profile and
// phi_cuts) against the number of particles, on a jittered simple cubic crystal in an
// open-top box. Expect O(N).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "packing_analyzer.hpp"

namespace {

granpipe::Frame jittered_cube(int n_side) {
  granpipe::Frame f;
  f.resize(static_cast<Eigen::Index>(n_side) * n_side * n_side, 3);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  Eigen::Index k = 0;
  for (int i = 0; i < n_side; ++i)
    for (int j = 0; j < n_side; ++j)
      for (int l = 0; l < n_side; ++l, ++k) {
        f.position().row(k) << 0.5 + i + u(rng), 0.5 + j + u(rng), 0.5 + l + u(rng);
        f.radius()[k] = 0.4;
      }
  f.container =
      granpipe::Container::open_top_box(3, {0, 0, 0}, {1.0 * n_side, 1.0 * n_side, 1.0 * n_side});
  return f;
}

void BM_MeasurePacking(benchmark::State& state) {
  const granpipe::Frame f = jittered_cube(static_cast<int>(state.range(0)));
  granpipe::packing::PackingSettings s;
  s.exclude_bottom = s.exclude_top = s.exclude_sides = 1.0;
  for (auto _ : state) {
    granpipe::FrameCache cache;
    benchmark::DoNotOptimize(granpipe::packing::measure_packing(f, cache, s));
  }
  state.SetComplexityN(f.size());
  state.SetItemsProcessed(state.iterations() * f.size());
}
BENCHMARK(BM_MeasurePacking)->Arg(8)->Arg(16)->Arg(32)->Complexity(benchmark::oN);

}  // namespace

BENCHMARK_MAIN();
