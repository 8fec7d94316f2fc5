// Cell-list neighbour search: build + full pair loop, random dense packings in 2D and 3D.
#include <benchmark/benchmark.h>

#include <utility>
#include <vector>

#include "granpipe/cell_list.hpp"
#include "granpipe/random.hpp"

using namespace granpipe;

static void BM_CellListPairs(benchmark::State& state) {
  const int dim = static_cast<int>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  // Unit-diameter particles at a number density near random close packing.
  const double density = dim == 2 ? 1.0 : 1.1;
  const double side = std::pow(n / density, 1.0 / dim);
  const Container c =
      Container::periodic_box(dim, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side));
  RandomStream rng = Seeds(1).stream("bench");
  Coordinates x(n, dim);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < dim; ++a) x(i, a) = rng.uniform(0, side);
  // The pairs are stored, as scipy's query_pairs returns them, so that the comparison in
  // compare_neighbours.py measures the same work.
  std::vector<std::pair<int, int>> pairs;
  for (auto _ : state) {
    pairs.clear();
    CellList cells(x, c, dim, 1.0);
    cells.for_each_pair([&](int i, int j, const double*, double) { pairs.emplace_back(i, j); });
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["particles/s"] =
      benchmark::Counter(static_cast<double>(n) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CellListPairs)
    ->Args({2, 2000})
    ->Args({2, 20000})
    ->Args({3, 8000})
    ->Args({3, 64000})
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
