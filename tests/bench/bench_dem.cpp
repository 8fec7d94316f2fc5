// Speed of the dem engine in particle-steps per second: a settled bed of 3000 spheres in
// the Brazil-nut scene's cylinder (R = 6.125), with its materials and drive (linear
// spring-dashpot, k_n = 2e5, e = 0.9, friction 0.5 on spheres and walls, spins,
// dt = 2e-4, skin 0.2, base and cylinder vibrated as A (1 - cos w t), A = 7.5,
// w = 2 pi 0.107), on 1 and 2 threads. The bed is settled once, with the walls at rest.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <numbers>

#include "diagnostics.hpp"
#include "engine.hpp"
#include "loose_lattice.hpp"

namespace dem = granpipe::dem;

namespace {

constexpr int kSpheres = 3000;
constexpr double kCylinder = 6.125;
// The reference runs' window: 5000 warm-up steps, then 25000 timed ones (t = 1 ... 6 of
// the first cycle). Fixed, so that every thread count times the same stretch of motion.
constexpr int kWarmUp = 5000;
constexpr int kStepsPerIteration = 200;
constexpr int kIterations = 25000 / kStepsPerIteration;

dem::Model model() {
  const double kn = 2e5, gamma = dem::damping_for_restitution(0.9, kn, 0.5);
  const dem::ContactMaterial m{kn, 2.0 / 7.0 * kn, gamma, 0.5 * gamma, 0.5};
  return dem::Model::uniform(1, 1.91, m, m);
}

granpipe::Container cylinder() {
  granpipe::Container c;
  for (auto& axis : c.boundary) axis = {granpipe::Boundary::Open, granpipe::Boundary::Open};
  c.boundary[2][0] = granpipe::Boundary::Wall;
  c.shape = granpipe::ContainerShape::Cylinder;
  c.cylinder_radius = kCylinder;
  return c;
}

dem::Settings settings(int threads) {
  dem::Settings s;
  s.dt = 2e-4;
  s.threads = threads;
  return s;
}

// The loose lattice of the reference inputs, settled under gravity until its kinetic
// energy per sphere is below 1e-5 (m0 g d0).
const dem::InitialState& settled_bed() {
  static const dem::InitialState bed = [] {
    const dem::InitialState loose = dem::loose_lattice(
        {.count = kSpheres, .radius = 0.5, .cylinder_radius = kCylinder, .spacing = 1.03});
    dem::Engine e(model(), dem::WallSet(cylinder(), {}), settings(2), loose);
    do {
      e.run(5000);
    } while (dem::energy(e).kinetic() > 1e-5 * kSpheres && e.time() < 60.0);
    std::fprintf(stderr, "bench_dem: bed settled at t = %g, kinetic energy per sphere %g\n",
                 e.time(), dem::energy(e).kinetic() / kSpheres);
    dem::InitialState out = loose;
    for (int i = 0; i < kSpheres; ++i) out.position.col(i) = e.particles().x.col(e.index_of(i));
    return out;
  }();
  return bed;
}

void BM_VibratedBed(benchmark::State& state) {
  dem::Drive drive;
  drive.amplitude = 7.5;
  drive.angular_frequency = 2.0 * std::numbers::pi * 0.107;
  dem::Engine e(model(), dem::WallSet(cylinder(), drive),
                settings(static_cast<int>(state.range(0))), settled_bed());
  e.run(kWarmUp);
  const auto builds = e.neighbors().builds();
  for (auto _ : state) e.run(kStepsPerIteration);
  const double steps = static_cast<double>(state.iterations()) * kStepsPerIteration;
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(steps * kSpheres, benchmark::Counter::kIsRate);
  state.counters["pairs_per_sphere"] = static_cast<double>(e.neighbors().pairs()) / kSpheres;
  state.counters["steps_per_rebuild"] =
      steps / static_cast<double>(e.neighbors().builds() - builds);
}

}  // namespace

BENCHMARK(BM_VibratedBed)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(kIterations);

BENCHMARK_MAIN();
