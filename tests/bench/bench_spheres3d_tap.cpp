// The 3D tapping model at the paper's size (N = 4096, L = 32 R, periodic): the sequential
// deposition, and Monte Carlo trial moves on the deposited packing (items = trials).
#include <benchmark/benchmark.h>

#include "deposit.hpp"
#include "redeposition.hpp"

namespace {

using granpipe::RandomStream;
using namespace granpipe::spheres3d_tap;

const TapBox kPaperBox{32.0, 1.0, Sides::Periodic};

std::vector<Eigen::Vector3d> paper_deposition() {
  Deposition deposition(kPaperBox);
  RandomStream rng(1);
  deposition.drop_random(4096, rng);
  return deposition.centres();
}

void BM_Deposition(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(paper_deposition());
  state.SetItemsProcessed(state.iterations() * 4096);
}
BENCHMARK(BM_Deposition)->Unit(benchmark::kMillisecond);

void BM_TrialMoves(benchmark::State& state) {
  std::vector<Eigen::Vector3d> centres = paper_deposition();
  Redeposition redeposition(kPaperBox, RedepositionOptions{});
  RandomStream rng(2);
  const std::int64_t trials = 1 << 20;
  for (auto _ : state) benchmark::DoNotOptimize(redeposition.shake(centres, trials, rng));
  state.SetItemsProcessed(state.iterations() * trials);
}
BENCHMARK(BM_TrialMoves)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
