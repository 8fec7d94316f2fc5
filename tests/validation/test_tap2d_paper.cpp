// The 2D tapping paper's main findings, on a small bed through the real plugins
// (disks2d_tap -> arches, packing): an ordered, denser packing at small tap amplitude and a
// disordered, looser one at large amplitude, with <z>_support between 3 and 4 and lower in
// the disordered bed (Figs. 3 and 6). Short runs (N = 500, 300 + 100 taps) decide the sign
// and size of the differences, not the paper's decimals: docs/disks2d_tap.md has those.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"

using namespace granpipe;

TEST(Tap2dPaper, OrderedAtSmallAmplitudeDisorderedAtLarge) {
  Registry registry;
  load_plugins(registry, plugin_search_path());
  const Pipeline p = Pipeline::parse(R"({
    "name": "tap2d_validation", "seed": 7,
    "source": {"plugin": "disks2d_tap",
               "params": {"N": 500, "width": 20, "delta": 0.01, "equilibration_taps": 300,
                          "production_taps": 100, "save_every": 10}},
    "analyzers": [{"plugin": "arches", "params": {"svg_frames": 0}},
                  {"plugin": "packing", "params": {"exclude_bottom": 3, "exclude_top": 3, "profile_step": 0}}],
    "output": {"save_frames": false},
    "sweep": {"parameters": {"source.params.A": [1.05, 1.5]}}})",
                                     "tap2d_validation.json", {}, registry);
  Log log;
  log.set_quiet(true);
  RunOptions options;
  options.progress = false;
  options.out = std::filesystem::temp_directory_path() /
                ("granpipe_tap2d_validation_" + std::to_string(::getpid()));
  std::filesystem::remove_all(*options.out);
  const RunSummary run = p.run(options, log);
  std::filesystem::remove_all(*options.out);

  const Results& small_packing = run.results.at("point_000/packing");
  const Results& large_packing = run.results.at("point_001/packing");
  const Results& small_arches = run.results.at("point_000/arches");
  const Results& large_arches = run.results.at("point_001/arches");
  const double phi_small = small_packing.scalar("phi").value,
               phi_large = large_packing.scalar("phi").value;
  const double z_small = small_arches.scalar("z_support_eq4").value;
  const double z_large = large_arches.scalar("z_support_eq4").value;

  // Paper: phi just above 0.84 (ordered) for A < 1.1, about 0.75-0.78 for A = 1.5. A short
  // run may still be ordering (0.81-0.84), the more the nearer the transition (A = 1.1 read
  // 0.817 here), hence A = 1.05; the gap is what marks the transition.
  EXPECT_GT(phi_small, 0.80);
  EXPECT_GT(phi_small - phi_large, 0.04);
  EXPECT_GT(phi_large, 0.70);
  EXPECT_LT(phi_large, 0.80);
  // <z>_support lies between 3 and 4 and drops at the order-disorder transition.
  for (double z : {z_small, z_large}) {
    EXPECT_GT(z, 3.0);
    EXPECT_LT(z, 4.0);
  }
  EXPECT_GT(z_small - z_large, 0.05);
  // More arches per particle in the disordered bed (Eq. 4: arches and <z> go together).
  EXPECT_GT(large_arches.scalar("arches_per_particle").value,
            small_arches.scalar("arches_per_particle").value);

  // On every frame of the real runs, Eq. (4) and the direct count of supporting contacts
  // differ exactly by 2 N_base / N (Eq. 4 counts a base disk as if it had two supports),
  // and every disk is stable or on the base: the only supports missing are the second ones
  // of base disks.
  for (const Results* r : {&small_arches, &large_arches}) {
    const Table& t = r->tables().at("per_frame");
    ASSERT_EQ(t.rows(), 10u);
    for (std::size_t k = 0; k < t.rows(); ++k) {
      EXPECT_NEAR(t.column("z_support_eq4")[k] - t.column("z_support_direct")[k],
                  2.0 * t.column("base_fraction")[k], 1e-12);
      EXPECT_EQ(t.column("missing_supports_per_particle")[k], t.column("base_fraction")[k]);
    }
  }
}
