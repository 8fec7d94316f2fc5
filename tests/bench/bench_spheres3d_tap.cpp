// The 3D tapping model at the paper's size (N = 4096, L = 32 R, periodic): the sequential
// deposition, Monte Carlo trial moves (items = trials) and whole taps (items = taps, with
// the trials' rate as a counter) at the paper's d_max = R/5, theta0 = pi/4, eta = 1e-6.
#include <benchmark/benchmark.h>

#include "deposit.hpp"
#include "redeposition.hpp"

namespace {

using granpipe::FastRandomStream;
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

// Trials as a tap makes them: on the deposited packing dilated by 1 + epsilon (a packing
// at rest has no free downward move, so trials on it would all be rejections).
void BM_TrialMoves(benchmark::State& state) {
  const double epsilon = static_cast<double>(state.range(0)) * 1e-3;
  const std::vector<Eigen::Vector3d> deposited = paper_deposition();
  Redeposition redeposition(kPaperBox, RedepositionOptions{});
  FastRandomStream rng(2);
  const std::int64_t trials = 4096 * 100;
  TapStats stats;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<Eigen::Vector3d> centres = deposited;
    for (auto& c : centres) c.z() *= 1.0 + epsilon;
    state.ResumeTiming();
    const TapStats s = redeposition.shake(centres, trials, rng);
    stats.trials += s.trials;
    stats.accepted += s.accepted;
  }
  state.SetItemsProcessed(stats.trials);
  state.counters["acceptance"] =
      static_cast<double>(stats.accepted) / static_cast<double>(stats.trials);
}
BENCHMARK(BM_TrialMoves)->Arg(5)->Arg(50)->Arg(150)->Unit(benchmark::kMillisecond);

// Whole taps from the deposited packing: the first ones, which are the costliest.
void BM_Taps(benchmark::State& state) {
  const double epsilon = static_cast<double>(state.range(0)) * 1e-3;
  std::vector<Eigen::Vector3d> centres = paper_deposition();
  Redeposition redeposition(kPaperBox, RedepositionOptions{});
  FastRandomStream rng(3);
  std::int64_t trials = 0;
  for (auto _ : state) trials += redeposition.tap(centres, epsilon, rng).trials;
  state.SetItemsProcessed(state.iterations());
  state.counters["trials_per_second"] =
      benchmark::Counter(static_cast<double>(trials), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Taps)->Arg(5)->Arg(50)->Arg(150)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
