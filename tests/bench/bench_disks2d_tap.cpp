// Speed of the disks2d_tap engine: deposition moves (falls and rolls of length delta)
// per second, and full taps (dilation, Monte Carlo loops, deposition) per second, at
// the paper's settings (width 20, r = 0.1 + 1/sqrt2, A = 1.1, delta = 0.01) with the
// plugin's 60 MC loops.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "deposit.hpp"
#include "placement.hpp"
#include "shake.hpp"

namespace dt = granpipe::disks2d_tap;

namespace {

constexpr double kA = 1.1;
constexpr int kWarmTaps = 20;  // taps before timing, away from the initial deposition

struct Bed {
  dt::DiskPacking packing;
  std::unique_ptr<dt::Deposit> deposit;
  dt::Shaker shaker{dt::kPaperMatchedMcLoops, dt::Dilation::CentreHeight};
  granpipe::RandomStream deposition{1}, taps{2};

  explicit Bed(std::size_t n) {
    const double r = 0.1 + 1.0 / std::numbers::sqrt2, width = 20.0;
    granpipe::RandomStream placement(3);
    packing = dt::place_at_random(width,
                                  static_cast<double>(n) * std::numbers::pi * r * r / (width * 0.3),
                                  std::vector<double>(n, r), placement, "bench");
    deposit = std::make_unique<dt::Deposit>(packing, dt::DepositOptions{.delta = 0.01});
    deposit->run(deposition);
    for (int k = 0; k < kWarmTaps; ++k) tap();
  }
  void tap() {
    shaker.tap(packing, kA, taps);
    deposit->reset();
    deposit->run(deposition);
  }
};

void BM_Tap(benchmark::State& state) {
  Bed bed(static_cast<std::size_t>(state.range(0)));
  const auto moves0 = bed.deposit->stats().moves();
  for (auto _ : state) bed.tap();
  const auto moves = static_cast<double>(bed.deposit->stats().moves() - moves0);
  state.counters["taps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["moves_per_tap"] = moves / static_cast<double>(state.iterations());
}

// Deposition alone: the tap's dilation and shaking run with the timer paused.
void BM_Moves(benchmark::State& state) {
  Bed bed(static_cast<std::size_t>(state.range(0)));
  double moves = 0;
  for (auto _ : state) {
    state.PauseTiming();
    bed.shaker.tap(bed.packing, kA, bed.taps);
    bed.deposit->reset();
    const auto before = bed.deposit->stats().moves();
    state.ResumeTiming();
    bed.deposit->run(bed.deposition);
    moves += static_cast<double>(bed.deposit->stats().moves() - before);
  }
  state.counters["moves_per_s"] = benchmark::Counter(moves, benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_Tap)->Arg(500)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Moves)->Arg(500)->Arg(2000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
