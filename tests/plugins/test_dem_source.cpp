// The `dem` source as a pipeline makes it: a sphere started on the base settles at the
// overlap m g / k_n with the base's contact in its frames, and a time step above the
// shortest contact time is refused before anything runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "dem_source.hpp"
#include "model.hpp"
#include "granpipe/frame_store.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// Spheres of radius 0.5 at these centres (by default one just touching the base) in an
// open-top box.
fs::path start_file(const std::vector<Eigen::Vector3d>& centres = {{0.0, 0.0, 0.5}}) {
  const fs::path p = fs::temp_directory_path() / ("granpipe_dem_start_" + std::to_string(::getpid()) + ".h5");
  fs::remove(p);
  Frame f;
  f.resize(static_cast<Eigen::Index>(centres.size()), 3);
  f.radius().setConstant(0.5);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    f.position().row(static_cast<Eigen::Index>(k)) = centres[k].transpose().array();
  }
  f.container = Container::open_top_box(3, Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 10));
  FrameWriter w(p, "{}");
  w.append(f);
  w.close();
  return p;
}

}  // namespace

TEST(DemSource, ASphereOnTheBaseSettlesAtTheOverlapOfItsWeight) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                      {"duration", 2.0},
                                                      {"save_every", 5000}});
  dem::DemSource source(*ctx);
  Frame f;
  std::vector<Frame> frames;
  while (source.next(f)) frames.push_back(f);
  ASSERT_EQ(frames.size(), 3u);  // t = 0, 1, 2
  const Frame& last = frames.back();
  const double mass = 1.91 * std::numbers::pi / 6.0, weight = mass * 1.0, kn = 2e5;
  EXPECT_NEAR(0.5 - last.position()(0, 2), weight / kn, 1e-3 * weight / kn);
  EXPECT_NEAR(last.time, 2.0, 1e-12);
  ASSERT_TRUE(last.contacts.has_value());
  ASSERT_EQ(last.contacts->rows(), 1);
  EXPECT_EQ(last.contact_i()[0], 0);
  EXPECT_EQ(last.contact_j()[0], partner::wall(Wall::ZLow));
  const auto& normal = last.contacts->get<Coordinates>("normal_force");
  EXPECT_NEAR(std::abs(normal(0, 2)), weight, 1e-3 * weight);
  fs::remove(file);
}

TEST(DemSource, ATimeStepAboveTheShortestContactTimeIsRefusedNamingDt) {
  const fs::path file = start_file();
  try {
    const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()}, {"dt", 1e-2}});
    dem::DemSource source(*ctx);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("params.dt: ", 0), 0u) << e.what();
  }
  fs::remove(file);
}

TEST(DemSource, SaveFromEmitsOnlyTheFramesDueFromThatTimeOn) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                      {"duration", 2.0},
                                                      {"save_every", 1000},
                                                      {"save_from", 1.1}});
  dem::DemSource source(*ctx);
  Frame f;
  std::vector<double> times;
  while (source.next(f)) times.push_back(f.time);
  // dt = 2e-4: steps 5500 .. 10000 due, frames at multiples of 1000 steps from 6000 on.
  ASSERT_EQ(times.size(), 5u);
  EXPECT_NEAR(times.front(), 1.2, 1e-12);
  EXPECT_NEAR(times.back(), 2.0, 1e-12);
  fs::remove(file);
}

TEST(DemSource, ASaveFromBeyondTheDurationIsRefusedNamingIt) {
  const fs::path file = start_file();
  try {
    const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                        {"duration", 1.0},
                                                        {"save_from", 2.0}});
    dem::DemSource source(*ctx);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "params.save_from: expected a time within the duration (1), got 2");
  }
  fs::remove(file);
}

TEST(DemSource, TheTimingTableCountsEveryStepOnceAndItsPartsFitInIt) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                      {"duration", 1.0},
                                                      {"save_every", 2000}});
  dem::DemSource source(*ctx);
  Frame f;
  while (source.next(f)) {
  }
  Results results;
  source.finish(results);
  const Table& timing = results.tables().at("timing");
  ASSERT_EQ(timing.rows(), 3u);  // 2000, 4000, 5000 steps
  double steps = 0.0;
  for (std::size_t r = 0; r < timing.rows(); ++r) {
    steps += timing.column("steps")[r];
    const double parts = timing.column("force_seconds")[r] + timing.column("integrate_seconds")[r] +
                         timing.column("neighbour_seconds")[r];
    EXPECT_LE(parts, timing.column("seconds")[r]);
  }
  EXPECT_EQ(steps, 5000.0);
  EXPECT_EQ(timing.column("step")[2], 5000.0);
  fs::remove(file);
}

TEST(DemSource, FramesCarryTheDrivesCyclesAndTheContainersVelocity) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(
      dem::schema(), {{"initial_file", file.string()},
                      {"duration", 1.5},
                      {"save_every", 2500},
                      {"drive", {{"form", "one_minus_cos"}, {"amplitude", 0.001}, {"frequency", 0.5}}}});
  dem::DemSource source(*ctx);
  Frame f;
  while (source.next(f)) {
  }
  EXPECT_NEAR(*f.real_observable("cycles"), 0.75, 1e-12);
  // V = A w sin(w t) at w t = 3 pi / 2.
  EXPECT_NEAR(*f.real_observable("container_velocity"), -0.001 * std::numbers::pi, 1e-12);
  fs::remove(file);
}

TEST(DemSource, AnEnergyBlowUpStopsTheRunNamingTheOverlaps) {
  // Two spheres started half a diameter into each other: the spring releases k d^2 / 8,
  // about 6000 times what the scene's speeds allow, and the run stops at the first check.
  const fs::path file = start_file({{0.0, 0.0, 0.5}, {0.5, 0.0, 0.5}});
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()}, {"duration", 1.0}});
  dem::DemSource source(*ctx);
  Frame f;
  ASSERT_TRUE(source.next(f));  // the start
  try {
    source.next(f);
    FAIL() << "expected a blow-up";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("dem: step 1000 (t = 0.2): kinetic energy ", 0), 0u) << m;
    EXPECT_NE(m.find(": the run blew up; reduce dt (now 0.0002) against the shortest contact "
                     "time, or the initial overlaps"), std::string::npos) << m;
  }
  fs::remove(file);
}

TEST(DemSource, ASphereDroppedOntoTheBaseIsNoBlowUp) {
  // Started 10 diameters above the base it lands at sqrt(2 g h) = 4.4: the bound counts the
  // drop from the walls, not only the particles' own spread (none for one sphere).
  const fs::path file = start_file({{0.0, 0.0, 10.5}});
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                      {"duration", 6.0},
                                                      {"save_every", 100}});
  dem::DemSource source(*ctx);
  Frame f;
  double rebound = 0.0;
  while (source.next(f)) rebound = std::max(rebound, f.table<double>("velocity")(0, 2));
  // It bounced off the base with Eq. (9)'s restitution (m_eff = m against a wall), sampled
  // within 0.02 of the bounce.
  const double e = dem::linear_restitution(2e5, 42.398, 1.91 * std::numbers::pi / 6.0);
  EXPECT_NEAR(rebound, e * std::sqrt(20.0), 0.03);
  fs::remove(file);
}
