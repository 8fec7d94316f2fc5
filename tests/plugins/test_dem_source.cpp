// The `dem` source as a pipeline makes it: a sphere started on the base settles at the
// overlap m g / k_n with the base's contact in its frames, and a time step above the
// shortest contact time is refused before anything runs.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "blow_up.hpp"
#include "dem_source.hpp"
#include "granpipe/available_memory.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/frame_store.hpp"
#include "memory_check.hpp"
#include "model.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// Spheres of radius 0.5 at these centres (by default one just touching the base) in an
// open-top box (4 wide, or `width`), moving with `velocities` and spinning with `spins` if
// given.
fs::path start_file(const std::vector<Eigen::Vector3d>& centres = {{0.0, 0.0, 0.5}},
                    const std::vector<Eigen::Vector3d>& velocities = {}, double width = 4.0,
                    const std::vector<Eigen::Vector3d>& spins = {}) {
  const fs::path p =
      fs::temp_directory_path() / ("granpipe_dem_start_" + std::to_string(::getpid()) + ".h5");
  fs::remove(p);
  Frame f;
  f.resize(static_cast<Eigen::Index>(centres.size()), 3);
  f.radius().setConstant(0.5);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    f.position().row(static_cast<Eigen::Index>(k)) = centres[k].transpose().array();
  }
  if (!velocities.empty()) {
    f.add("velocity");
    for (std::size_t k = 0; k < velocities.size(); ++k) {
      f.table<double>("velocity").row(static_cast<Eigen::Index>(k)) =
          velocities[k].transpose().array();
    }
  }
  if (!spins.empty()) {
    f.add("angular_velocity");
    for (std::size_t k = 0; k < spins.size(); ++k) {
      f.table<double>("angular_velocity").row(static_cast<Eigen::Index>(k)) =
          spins[k].transpose().array();
    }
  }
  const double h = 0.5 * width;
  f.container = Container::open_top_box(3, Eigen::Vector3d(-h, -h, 0), Eigen::Vector3d(h, h, 10));
  FrameWriter w(p, "{}");
  w.append(f);
  w.close();
  return p;
}

// The message of the InputError that making the source with these parameters throws.
std::string refusal(const nlohmann::json& params) {
  return test::input_error_of([&] {
    const auto ctx = test::make_context(dem::schema(), params);
    dem::DemSource source(*ctx);
  });
}

// The steps of the frames the source emits with these parameters, at most `most` of them.
std::vector<std::int64_t> emitted_steps(const nlohmann::json& params, std::size_t most = 1000) {
  const auto ctx = test::make_context(dem::schema(), params);
  dem::DemSource source(*ctx);
  Frame f;
  std::vector<std::int64_t> steps;
  while (steps.size() < most && source.next(f)) steps.push_back(f.step);
  return steps;
}

// The message of the blow-up that running the source to its end throws, after the frames
// it emitted (counted in `frames`).
std::string blow_up(const nlohmann::json& params, int& frames) {
  const auto ctx = test::make_context(dem::schema(), params);
  dem::DemSource source(*ctx);
  Frame f;
  frames = 0;
  try {
    while (source.next(f)) ++frames;
  } catch (const dem::BlowUp& e) {
    return e.what();
  }
  return "no blow-up";
}

}  // namespace

TEST(DemSource, ASphereOnTheBaseSettlesAtTheOverlapOfItsWeight) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(
      dem::schema(), {{"initial_file", file.string()}, {"duration", 2.0}, {"save_every", 5000}});
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

// The count of species a start frame needs was its largest species + 1 in int, which at
// 2^31 - 1 overflowed and read -2147483648.
TEST(DemSource, AStartFrameOfTheLargestSpeciesNumberIsRefusedWithItsCount) {
  const fs::path file =
      fs::temp_directory_path() / ("granpipe_dem_species_" + std::to_string(::getpid()) + ".h5");
  fs::remove(file);
  Frame f;
  f.resize(1, 3);
  f.radius().setConstant(0.5);
  f.position().row(0) << 0.0, 0.0, 0.5;
  f.species()[0] = std::numeric_limits<std::int32_t>::max();
  f.container = Container::open_top_box(3, Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 10));
  FrameWriter w(file, "{}");
  w.append(f);
  w.close();
  EXPECT_EQ(refusal({{"initial_file", file.string()}}),
            "params.species: expected an entry for every species of the start frame "
            "(2147483648), got 1");
  fs::remove(file);
}

// A skin of 10^12 diameters listed every pair: memory grew as N^2, unseen by the memory check.
TEST(DemSource, ASkinWiderThanTwoDiametersIsRefused) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"skin", 1e12}}),
            "test: params.skin: expected a number > 0 and <= 2, got 1000000000000.0");
  fs::remove(file);
}

TEST(DemSource, ATimeStepAboveTheShortestContactTimeIsRefusedNamingDt) {
  const fs::path file = start_file();
  try {
    const auto ctx =
        test::make_context(dem::schema(), {{"initial_file", file.string()}, {"dt", 1e-2}});
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
    const auto ctx = test::make_context(
        dem::schema(), {{"initial_file", file.string()}, {"duration", 1.0}, {"save_from", 2.0}});
    dem::DemSource source(*ctx);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "params.save_from: expected a time within the duration (1), got 2");
  }
  fs::remove(file);
}

TEST(DemSource, TheTimingTableCountsEveryStepOnceAndItsPartsFitInIt) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(
      dem::schema(), {{"initial_file", file.string()}, {"duration", 1.0}, {"save_every", 2000}});
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
      dem::schema(),
      {{"initial_file", file.string()},
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

// Without a drive a run has no cycles: 0 put every frame at cycle 0 (the intruder's
// heights then plotted at one x).
TEST(DemSource, FramesWithoutADriveHaveNoCycles) {
  const fs::path file = start_file();
  const auto ctx = test::make_context(
      dem::schema(), {{"initial_file", file.string()}, {"duration", 0.2}, {"save_every", 500}});
  dem::DemSource source(*ctx);
  Frame f;
  ASSERT_TRUE(source.next(f));
  EXPECT_TRUE(std::isnan(*f.real_observable("cycles")));
  EXPECT_EQ(*f.real_observable("container_velocity"), 0.0);
  fs::remove(file);
}

// The next frame's step was rounded up through step + save_every - 1, which overflowed for
// a save_every near 2^63: frames of step 0 without end, the file growing.
TEST(DemSource, ASaveEveryOfTheLargestIntegerEmitsTheLastFrameOnly) {
  const fs::path file = start_file();
  EXPECT_EQ(emitted_steps({{"initial_file", file.string()},
                           {"duration", 0.2},
                           {"save_every", INT64_MAX},
                           {"save_from", 0.01}},
                          10),
            std::vector<std::int64_t>{1000});
  fs::remove(file);
}

// Relaxation was checked only between frames: with a frame every 1000 steps or less, never
// (a threshold of 1e300 ran the whole duration, and the end said "not reached").
TEST(DemSource, RelaxationIsCheckedAtFramesEvery1000StepsOrLess) {
  for (const int save_every : {250, 1000}) {
    const fs::path file = start_file();
    const std::vector<std::int64_t> steps = emitted_steps({{"initial_file", file.string()},
                                                           {"duration", 1.0},
                                                           {"save_every", save_every},
                                                           {"relaxed_kinetic_energy", 1e300}});
    EXPECT_EQ(steps.back(), 1000) << save_every;  // the first check, on a frame's step
    fs::remove(file);
  }
}

// A duration of 1e300 wrapped the step count round to a negative one, refused as a
// save_from past the duration.
TEST(DemSource, ADurationOfMoreStepsThanCanBeCountedIsRefusedByName) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"duration", 1e300}}),
            "params.duration: expected fewer than 9007199254740992 time steps, got 5e+303 "
            "(duration / dt, dt 0.0002)");
  fs::remove(file);
}

// A save_from of 1e16 (within the 2^53 steps a duration may have, but past this one's)
// wrapped round to a negative step and saved every frame from t = 0, exit 0.
TEST(DemSource, ASaveFromPastTheDurationIsRefusedHoweverFarPast) {
  const fs::path file = start_file();
  for (const double save_from : {1.0, 1e16, 1e300}) {
    EXPECT_EQ(
        refusal({{"initial_file", file.string()}, {"duration", 0.03}, {"save_from", save_from}}),
        "params.save_from: expected a time within the duration (0.03), got " +
            format_number(save_from))
        << save_from;
  }
  fs::remove(file);
}

// A duration shorter than one step ran a whole step (t = 2e-4 for 1e-6), exit 0 and no
// word.
TEST(DemSource, ADurationShorterThanAStepIsRefused) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"duration", 1e-6}}),
            "params.duration: expected at least one time step (dt 0.0002), got 1e-06");
  fs::remove(file);
}

// A drag that reversed the velocities every step blew the run up, and the message blamed
// dt against the contacts and the initial overlaps, never the damping.
TEST(DemSource, ADragFasterThanAStepIsRefusedByName) {
  const fs::path file = start_file();
  const std::string refused = refusal({{"initial_file", file.string()}, {"air_damping", 12000.0}});
  EXPECT_EQ(refused.substr(0, refused.find(" (mass")),
            "params.air_damping: expected a drag that takes at least a time step to stop the "
            "lightest sphere");
  EXPECT_NE(refused.find(", got 12000 (b dt / m = "), std::string::npos) << refused;
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"background_damping", 1.0}}), "no refusal");
  fs::remove(file);
}

// Two spheres started 0.1 into each other (20 % of their radius, within the start's
// max_overlap) without gravity: the spring releases k 0.1^2 / 2 = 1000 where the scene's
// speeds (nothing moves, nothing falls) allow 1e-4. That is the start's energy, not a
// blow-up (it was called one, "reduce dt"): the spheres part with at most that energy.
TEST(DemSource, OverlapsOfTheStartSpringApartWithTheirEnergy) {
  const fs::path file = start_file({{0.0, 0.0, 0.5}, {0.9, 0.0, 0.5}});
  const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                      {"duration", 0.01},
                                                      {"gravity", {0.0, 0.0, 0.0}},
                                                      {"friction", false},
                                                      {"save_every", 50}});
  dem::DemSource source(*ctx);
  Frame f;
  while (source.next(f)) {
  }
  const auto& v = f.table<double>("velocity");
  const double mass = 1.91 * std::numbers::pi / 6.0;  // the default density, d = 1
  const double kinetic =
      0.5 * mass * (v.row(0).matrix().squaredNorm() + v.row(1).matrix().squaredNorm());
  const double released = 0.5 * 2e5 * 0.1 * 0.1;
  EXPECT_GT(kinetic, 0.5 * released);  // mostly kept (e = 0.9 against the paper's dashpot)
  EXPECT_LE(kinetic, released);
  fs::remove(file);
}

TEST(DemSource, ASphereDroppedOntoTheBaseIsNoBlowUp) {
  // Started 10 diameters above the base it lands at sqrt(2 g h) = 4.4: the bound counts the
  // drop from the walls, not only the particles' own spread (none for one sphere).
  const fs::path file = start_file({{0.0, 0.0, 10.5}});
  const auto ctx = test::make_context(
      dem::schema(), {{"initial_file", file.string()}, {"duration", 6.0}, {"save_every", 100}});
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

// GRANPIPE_DEM_INSTRUCTION_SET set to `value` (unset when null) while it lives, as before after.
class InstructionSetVariable {
 public:
  explicit InstructionSetVariable(const char* value) {
    if (const char* old = std::getenv(kName)) old_ = old;
    if (value) {
      ::setenv(kName, value, 1);
    } else {
      ::unsetenv(kName);
    }
  }
  ~InstructionSetVariable() {
    if (old_) {
      ::setenv(kName, old_->c_str(), 1);
    } else {
      ::unsetenv(kName);
    }
  }
  InstructionSetVariable(const InstructionSetVariable&) = delete;
  InstructionSetVariable& operator=(const InstructionSetVariable&) = delete;

 private:
  static constexpr const char* kName = "GRANPIPE_DEM_INSTRUCTION_SET";
  std::optional<std::string> old_;
};

TEST(DemSource, AnInstructionSetThisProcessorLacksIsRefusedNamingTheParameter) {
  const fs::path file = start_file();
  const InstructionSetVariable unset(nullptr);
  for (const auto path : {dem::InstructionSet::Avx2, dem::InstructionSet::Avx512}) {
    if (dem::runs_here(path)) continue;
    EXPECT_EQ(refusal({{"initial_file", file.string()}, {"instruction_set", dem::name_of(path)}}),
              std::string("params.instruction_set: expected an instruction set this processor "
                          "runs, found \"") +
                  dem::name_of(path) + "\" (" + dem::label_of(path) +
                  " is missing here; \"auto\" takes the widest it has)");
  }
  fs::remove(file);
}

// The pipeline says "auto": the results say which path ran (its last bits are its own).
TEST(DemSource, TheResultsNameThePathThatRanByItsWidth) {
  const fs::path file = start_file();
  const InstructionSetVariable unset(nullptr);
  for (const auto& [path, width] : {std::pair{dem::InstructionSet::Baseline, 2},
                                    {dem::InstructionSet::Avx2, 4},
                                    {dem::InstructionSet::Avx512, 8}}) {
    if (!dem::runs_here(path)) continue;
    const auto ctx = test::make_context(dem::schema(), {{"initial_file", file.string()},
                                                        {"duration", 0.01},
                                                        {"instruction_set", dem::name_of(path)}});
    dem::DemSource source(*ctx);
    Frame f;
    while (source.next(f)) {
    }
    Results results;
    source.finish(results);
    EXPECT_EQ(results.scalars().at("force_loop_width").value, width) << dem::name_of(path);
  }
  fs::remove(file);
}

TEST(DemSource, AMistypedInstructionSetVariableIsRefusedEvenBesideAnExplicitParameter) {
  const fs::path file = start_file();
  for (const char* value : {"AVX2", "garbage", "3"}) {
    const InstructionSetVariable set(value);
    for (const char* param : {"auto", "baseline"}) {
      EXPECT_EQ(refusal({{"initial_file", file.string()}, {"instruction_set", param}}),
                std::string("GRANPIPE_DEM_INSTRUCTION_SET: expected one of auto, baseline, avx2, "
                            "avx512, found \"") +
                    value + "\"")
          << param;
    }
  }
  {
    // Empty is unset; a valid value gives way to an explicit parameter.
    const InstructionSetVariable empty("");
    EXPECT_EQ(refusal({{"initial_file", file.string()}, {"instruction_set", "baseline"}}),
              "no refusal");
  }
  const InstructionSetVariable widest("avx512");
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"instruction_set", "baseline"}}),
            "no refusal");
  fs::remove(file);
}

// A start the run could not treat soundly is refused, naming what is wrong and where.
TEST(DemSource, AStartWithASphereOutsideItsContainerIsRefusedNamingItAndTheWall) {
  // The second sphere's centre 0.3 past the box's x_high side; the first rests on the base.
  const fs::path file = start_file({{0.0, 0.0, 0.5}, {2.3, 0.0, 0.5}});
  const std::string m = refusal({{"initial_file", file.string()}});
  EXPECT_EQ(m.rfind("params.initial_file: ", 0), 0u) << m;
  const std::string tail = m.substr(m.find(": frame 0: "));
  EXPECT_EQ(tail,
            ": frame 0: particle 1 (id 1) at (2.3, 0, 0.5) reaches 0.8 past wall x_high "
            "(160 % of its radius): expected particles inside the container, touching its "
            "walls by at most 30 % of their radius");
  fs::remove(file);
  // Pressed 0.1 into the wall (20 % of its radius), as a saved frame of a run may hold it.
  const fs::path touching = start_file({{1.6, 0.0, 0.5}});
  EXPECT_EQ(refusal({{"initial_file", touching.string()}}), "no refusal");
  fs::remove(touching);
}

TEST(DemSource, AStartSpeedASingleStepCannotResolveIsRefusedNamingTheParticle) {
  // At dt = 2e-4 a sphere of radius 0.5 may move 0.15 a step: up to 750.
  const std::vector<Eigen::Vector3d> centres{{0.0, 0.0, 0.5}, {0.0, 0.0, 5.0}};
  const fs::path file = start_file(centres, {{0.0, 0.0, 0.0}, {0.0, 0.0, -1e200}});
  const std::string m = refusal({{"initial_file", file.string()}});
  EXPECT_EQ(m.rfind("params.initial_file: ", 0), 0u) << m;
  EXPECT_EQ(m.substr(m.find(": frame 0: ")),
            ": frame 0: particle 1 (id 1) moves at 1e+200, 2e+196 a step of dt = 0.0002 "
            "(4e+198 % of its radius): expected speeds <= 750 (30 % of the radius a step; a "
            "longer step cannot resolve its contacts)");
  fs::remove(file);
  const fs::path fast = start_file(centres, {{0.0, 0.0, 0.0}, {0.0, 0.0, -749.0}});
  EXPECT_EQ(refusal({{"initial_file", fast.string()}}), "no refusal");
  fs::remove(fast);
}

// The run holds a fixed species' particles with the container: a start moving one had its
// velocity dropped without a word.
TEST(DemSource, AFixedParticleStartingToMoveIsRefused) {
  const nlohmann::json held = {{{"name", "held"}, {"density", 1.91}, {"fixed", true}}};
  const fs::path file = start_file({{0.0, 0.0, 0.5}}, {{-0.5, 0.0, 0.0}});
  const std::string m = refusal({{"initial_file", file.string()}, {"species", held}});
  EXPECT_EQ(m.substr(m.find(": frame 0: ")),
            ": frame 0: particle 0 (id 0) of fixed species 0 moves at (-0.5, 0, 0), spinning at "
            "(0, 0, 0): expected it held by the container, moving as the container does, at (0, "
            "0, 0), without spin");
  fs::remove(file);
  // Spinning, in a file without velocities (the check looked only where velocities were).
  {
    const fs::path spinning = start_file({{0.0, 0.0, 0.5}}, {}, 4.0, {{0.0, 0.0, 2.0}});
    const std::string spun = refusal({{"initial_file", spinning.string()}, {"species", held}});
    EXPECT_EQ(spun.substr(spun.find(": frame 0: ")),
              ": frame 0: particle 0 (id 0) of fixed species 0 moves at (0, 0, 0), spinning at "
              "(0, 0, 2): expected it held by the container, moving as the container does, at "
              "(0, 0, 0), without spin");
    fs::remove(spinning);
  }
  const fs::path resting = start_file({{0.0, 0.0, 0.5}});  // no velocities at all
  EXPECT_EQ(refusal({{"initial_file", resting.string()}, {"species", held}}), "no refusal");
  fs::remove(resting);
  // A container at rest starts any drive, a held particle setting off with it at A w.
  const double speed = 0.01 * 2.0 * std::numbers::pi;
  const fs::path setting_off = start_file({{0.0, 0.0, 0.5}}, {{0.0, 0.0, speed}});
  EXPECT_EQ(refusal({{"initial_file", setting_off.string()},
                     {"species", held},
                     {"drive", {{"form", "sine"}, {"amplitude", 0.01}, {"frequency", 1.0}}}}),
            "no refusal");
  fs::remove(setting_off);
}

TEST(DemSource, AnEmptyStartIsRefused) {
  const fs::path file = start_file({});
  const std::string m = refusal({{"initial_file", file.string()}});
  EXPECT_EQ(m.substr(m.find(": frame 0: ")), ": frame 0: expected at least one particle, got none");
  fs::remove(file);
}

TEST(DemSource, AStartWithSpheresOverlappingPastTheLimitIsRefused) {
  // Centres 0.65 apart: an overlap of 0.35, 70 % of the radius.
  const fs::path file = start_file({{0.0, 0.0, 0.5}, {0.65, 0.0, 0.5}});
  const std::string m = refusal({{"initial_file", file.string()}});
  EXPECT_EQ(m.substr(m.find(": frame 0: ")),
            ": frame 0: particles 0 and 1 (ids 0 and 1) overlap by 70 % of the smaller radius: "
            "expected overlaps of at most 30 %");
  fs::remove(file);
}

TEST(DemSource, ADriveWithTooFewStepsPerPeriodIsRefused) {
  const fs::path file = start_file();
  const std::string expected =
      "params.drive.frequency: 1000 gives 5 steps of dt = 0.0002 per period: expected at least "
      "50 (frequency <= 100)";
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 0.02}, {"frequency", 1000.0}}}}),
            expected);
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 1e6}, {"frequency", 1000.0}}}}),
            expected);
  // The bound itself, 50 steps, rounded through 2 pi f to 49.999...: refused by its own words.
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 1e-5}, {"frequency", 100.0}}}}),
            "no refusal");
  fs::remove(file);
}

TEST(DemSource, ADriveWhosePeakSpeedWouldCrushASphereIsRefused) {
  // A 2 pi f = 6.28e5 against k_n = 2e5: a unit-mass sphere hit at that speed would go
  // v sqrt(m / k_n) = 1405 deep. The largest speed allowed: 0.3 R sqrt(k_n / m) = 67.1.
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 1e6}, {"frequency", 0.1}}}}),
            "params.drive: amplitude 1e+06 and frequency 0.1 move the walls at up to A 2 pi f = "
            "6.28e+05, which would press a sphere of species 0 (radius 0.5) hit by wall z_low "
            "1.41e+03 deep (2.81e+05 % of its radius; a sound run stays within 30 %): expected "
            "A 2 pi f <= 67.1");
  // A speed that is no number: the bound read "A 2 pi f <= -nan".
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 1e308}, {"frequency", 10.0}}}}),
            "params.drive: amplitude 1e+308 and frequency 10: expected a finite peak wall speed "
            "A 2 pi f, got inf");
  fs::remove(file);
}

// A drive without a frequency stands still: its periods did not end the run, its amplitude
// moved nothing, and neither was said.
TEST(DemSource, ADriveWithoutAFrequencyTakesNoOtherValue) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"drive", {{"periods", 5}}}}),
            "test: params.drive.periods: expected its default 0 (it acts only with frequency > "
            "0; here frequency is 0), got 5");
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"drive", {{"amplitude", 0.5}}}}),
            "test: params.drive.amplitude: expected its default 0 (it acts only with frequency > "
            "0; here frequency is 0), got 0.5");
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"drive", {{"amplitude", 0.001}, {"frequency", 0.5}, {"periods", 5}}}}),
            "no refusal");
  fs::remove(file);
}

TEST(DemSource, AGravityThatWouldCrushASphereRestingOnTheBaseIsRefused) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"gravity", {0.0, 0.0, -1e300}}}),
            "params.gravity: |g| = 1e+300 would press a sphere of species 0 (radius 0.5) resting "
            "on wall z_low 5e+294 deep (1e+297 % of its radius; a sound run stays within 30 %): "
            "expected |g| <= 3e+04");
  // An overlap past the range of doubles gave the bound |g| <= 0.
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"gravity", {1e308, 0.0, 0.0}}}),
            "params.gravity: |g| = 1e+308 would press a sphere of species 0 (radius 0.5) resting "
            "on wall x_high 5e+302 deep (1e+305 % of its radius; a sound run stays within 30 %): "
            "expected |g| <= 3e+04");
  // Gravity presses onto the walls it points at: up, onto an open top, nothing (it was
  // checked against the base, and refused).
  EXPECT_EQ(refusal({{"initial_file", file.string()}, {"gravity", {0.0, 0.0, 1e5}}}), "no refusal");
  fs::remove(file);
}

TEST(DemSource, AnAbsurdDensityIsRefusedNamingIt) {
  const fs::path file = start_file();
  EXPECT_EQ(refusal({{"initial_file", file.string()},
                     {"species", {{{"name", "small"}, {"density", 1e-300}}}}}),
            "test: params.species[0].density: expected a number in [1e-20, 1e+20], got 1e-300");
  fs::remove(file);
}

TEST(DemSource, TheHertzTimeStepCheckCountsTheStartVelocities) {
  // Two spheres approaching at 1, no gravity: the Hertz contact time at impact speed 1.
  const fs::path file =
      start_file({{-1.0, 0.0, 5.0}, {1.0, 0.0, 5.0}}, {{0.5, 0.0, 0.0}, {-0.5, 0.0, 0.0}});
  const double mass = 1.91 * std::numbers::pi / 6.0;
  const double t_c = dem::hertz_contact_time(2e5, 1.0, 0.5 * mass, 1.0);
  const auto check = [&](double steps_per_contact) {
    return refusal({{"initial_file", file.string()},
                    {"law", "hertz"},
                    {"gravity", {0.0, 0.0, 0.0}},
                    {"dt", t_c / steps_per_contact}});
  };
  for (const double steps : {5.1, 3.0}) {
    const std::string m = check(steps);
    const std::string ratio = "is t_c/" + format_number(steps) +
                              " for the shortest contact "
                              "(species 0 and species 0, t_c = " +
                              format_number(t_c) + ")";
    EXPECT_NE(m.find(ratio), std::string::npos) << m;
    EXPECT_EQ(m.rfind("params.dt: ", 0), 0u) << m;
  }
  EXPECT_EQ(check(25.0), "no refusal");
  fs::remove(file);
}

// Contacts that go past the overlap limit while the run goes stop it with one line,
// after the frames emitted before.
TEST(DemSource, TwoSpheresMeetingTooFastToStopAreStoppedBeforePassingThrough) {
  for (const char* law : {"linear", "hertz"}) {
    const fs::path file = start_file({{-2.0, 0.0, 5.0}, {2.0, 0.0, 5.0}},
                                     {{500.0, 0.0, 0.0}, {-500.0, 0.0, 0.0}}, 100.0);
    int frames = 0;
    const std::string m = blow_up({{"initial_file", file.string()},
                                   {"law", law},
                                   {"gravity", {0.0, 0.0, 0.0}},
                                   {"duration", 0.1}},
                                  frames);
    EXPECT_EQ(m.rfind("dem: step 16 (t = 0.0032): particles 0 and 1 overlap by ", 0), 0u) << m;
    EXPECT_EQ(frames, 1);  // the start
    fs::remove(file);
  }
}

TEST(DemSource, ASphereDroppedFromFarTooHighIsStoppedAtTheBase) {
  // From z = 1e4 it lands at 141: 59 % (linear) or 84 % (Hertz) of its radius deep.
  for (const char* law : {"linear", "hertz"}) {
    const fs::path file = start_file({{0.0, 0.0, 1e4}});
    int frames = 0;
    const std::string m = blow_up({{"initial_file", file.string()},
                                   {"law", law},
                                   {"duration", 150.0},
                                   {"save_every", 1000000}},
                                  frames);
    EXPECT_NE(m.find("): particle 0 overlaps wall z_low by "), std::string::npos) << m;
    EXPECT_EQ(frames, 1);
    fs::remove(file);
  }
}

TEST(DemSource, AScenePastTheAvailableMemoryIsRefusedBeforeAnythingIsAllocated) {
  const double available = granpipe::available_memory();
  ASSERT_GT(available, 0.0);  // /proc/meminfo
  try {
    dem::check_memory("params.bed.small", 1e15);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("params.bed.small: 1e+15 spheres need about 2e+09 GB (2 kB each), this "
                      "machine (or the process's memory limit) has ",
                      0),
              0u)
        << m;
    EXPECT_NE(m.find(" GB available: expected at most "), std::string::npos) << m;
  }
  EXPECT_NO_THROW(dem::check_memory("params.bed.small", 1000.0));
}

// Under prlimit --as 8 GB a start of 8e6 spheres passed the check against the machine's
// 24 GB and failed 22 s later with std::bad_alloc, exit 1.
TEST(DemSource, TheMemoryCheckHeedsTheProcesssAddressSpaceLimit) {
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  statm >> pages;
  const double size = pages * static_cast<double>(sysconf(_SC_PAGESIZE)), room = 1e9;
  rlimit lowered = before;
  lowered.rlim_cur = static_cast<rlim_t>(size + room);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &lowered), 0);
  const double available = granpipe::available_memory();
  ASSERT_EQ(setrlimit(RLIMIT_AS, &before), 0);
  EXPECT_LE(available, room);
  EXPECT_GT(available, 0.5 * room);
}
