// The h5md source: frame selection (first, last, stride) through the Source interface.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "granpipe/frame_store.hpp"
#include "granpipe/property.hpp"
#include "h5md_source.hpp"
#include "plugin_harness.hpp"

namespace fs = std::filesystem;
using namespace granpipe;

namespace {

class H5mdSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        fs::temp_directory_path() / ("granpipe_h5md_" + std::to_string(getpid()) + "_" + t->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Frame k holds step 10 k and particle positions k + i, so a frame names itself.
  fs::path write(long frames, bool close = true) {
    const fs::path p = dir_ / "frames.h5";
    FrameWriter w(p, "{}");
    for (long k = 0; k < frames; ++k) {
      Frame f;
      f.resize(3, 2);
      for (Eigen::Index i = 0; i < 3; ++i) f.position()(i, 0) = static_cast<double>(k + i);
      f.radius().setConstant(0.5);
      f.container =
          Container::periodic_box(2, Eigen::Vector3d(-1, -5, 0), Eigen::Vector3d(99, 5, 0));
      f.add("velocity");
      f.step = 10 * k;
      w.append(f);
    }
    if (close) w.close();
    return p;
  }

  std::unique_ptr<h5md::H5mdSource> source(const fs::path& file, std::int64_t first,
                                           std::int64_t last, std::int64_t stride,
                                           double max_overlap = 1e-6) {
    harness_ = granpipe::test::make_context("h5md", {{"file", file.string()},
                                                     {"first", first},
                                                     {"last", last},
                                                     {"stride", stride},
                                                     {"max_overlap", max_overlap}});
    return std::make_unique<h5md::H5mdSource>(*harness_);
  }

  // Steps of every frame the source yields.
  static std::vector<std::int64_t> steps_of(Source& s) {
    std::vector<std::int64_t> steps;
    Frame f;
    while (s.next(f)) {
      EXPECT_EQ(f.position()(2, 0), static_cast<double>(f.step / 10 + 2));
      steps.push_back(f.step);
    }
    return steps;
  }

  fs::path dir_;
  std::unique_ptr<granpipe::test::PluginHarness> harness_;  // outlives the source it made
};

using Steps = std::vector<std::int64_t>;

TEST_F(H5mdSourceTest, ReadsEveryFrameByDefault) {
  auto s = source(write(5), 0, -1, 1);
  EXPECT_EQ(s->work().total, 5.0);
  EXPECT_EQ(steps_of(*s), (Steps{0, 10, 20, 30, 40}));
}

TEST_F(H5mdSourceTest, SelectsFirstLastAndStride) {
  const fs::path p = write(10);
  auto a = source(p, 2, 8, 3);
  EXPECT_EQ(a->work().total, 3.0);
  EXPECT_EQ(steps_of(*a), (Steps{20, 50, 80}));
  auto b = source(p, 1, 7, 3);  // last is not on the stride: stops before it
  EXPECT_EQ(b->work().total, 3.0);
  EXPECT_EQ(steps_of(*b), (Steps{10, 40, 70}));
  auto c = source(p, 9, -1, 4);
  EXPECT_EQ(c->work().total, 1.0);
  EXPECT_EQ(steps_of(*c), (Steps{90}));
}

TEST_F(H5mdSourceTest, ContentComesFromTheFile) {
  auto s = source(write(2), 0, -1, 1);
  const FrameContent c = s->content();
  EXPECT_EQ(c.dim, 2);
  std::vector<std::string> names;
  for (const auto& p : c.columns) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"radius", "id", "species", "velocity"}));
  EXPECT_FALSE(c.contacts);
}

TEST_F(H5mdSourceTest, SelectionOutsideTheFileIsAnInputError) {
  const fs::path p = write(4);
  auto message = [&](std::int64_t first, std::int64_t last) {
    return granpipe::test::input_error_of([&] { source(p, first, last, 1); });
  };
  EXPECT_EQ(message(4, -1), "params.first: expected a frame index below 4, got 4 (" + p.string() +
                                " holds 4 frames)");
  EXPECT_EQ(message(0, 4), "params.last: expected -1 or a frame index below 4, got 4 (" +
                               p.string() + " holds 4 frames)");
  EXPECT_EQ(message(3, 2), "params.last: expected -1 or an index >= first (3), got 2");
}

// A stride past the end reads the first frame only; one that would overflow the frame
// index is refused (it read frame -2^63, an internal error).
TEST_F(H5mdSourceTest, StrideIsAtMostTheNumberOfFrames) {
  const fs::path p = write(4);
  EXPECT_EQ(steps_of(*source(p, 1, -1, 4)), (Steps{10}));
  try {
    source(p, 1, -1, std::numeric_limits<std::int64_t>::max());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "params.stride: expected at most the number of frames, got 9223372036854775807 (" +
                  p.string() + " holds 4 frames)");
  }
}

TEST_F(H5mdSourceTest, ReadsTheFinishedFramesOfAnUnfinishedFile) {
  const fs::path p = write(3, false);
  auto s = source(p, 0, -1, 1);
  EXPECT_EQ(steps_of(*s), (Steps{0, 10, 20}));
}

}  // namespace

namespace {
// One frame of two disks of radius 0.5 whose centres are `distance` apart.
fs::path write_pair(const fs::path& dir, double distance) {
  const fs::path p = dir / "pair.h5";
  FrameWriter w(p, "{}");
  Frame f;
  f.resize(2, 2);
  f.position()(1, 0) = distance;
  f.radius().setConstant(0.5);
  f.container = Container::periodic_box(2, Eigen::Vector3d(-1, -5, 0), Eigen::Vector3d(9, 5, 0));
  w.append(f);
  w.close();
  return p;
}

// Makes the source and reads every frame: the first frame is checked when the source is
// made (at validation), later ones as they are read.
template <class Make>
std::string error_of(Make&& make) {
  try {
    auto s = make();
    Frame f;
    while (s->next(f)) {
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}
}  // namespace

TEST_F(H5mdSourceTest, OverlappingParticlesAreRefusedWithThePair) {
  const fs::path p = write_pair(dir_, 0.9);  // overlap 0.1 = 20% of the radius
  EXPECT_EQ(error_of([&] { return source(p, 0, -1, 1); }),
            p.string() +
                ": frame 0: particles 0 and 1 (ids 0, 1) overlap by 0.2 of the smaller "
                "radius, expected at most 1e-06 (raise params.max_overlap for soft-particle data)");
  EXPECT_EQ(error_of([&] { return source(p, 0, -1, 1, 0.25); }), "(no InputError)");
}

// A contact between particles far apart entered the networks as a bond (a contact to a
// particle 80 diameters away joined it to the largest network), exit 0. Particles 0 and 2
// of frame k lie 1 apart across the periodic side, 99 inside the box: touching.
TEST_F(H5mdSourceTest, AContactBetweenParticlesApartIsRefused) {
  const auto with_contact = [&](std::int64_t j) {
    const fs::path p = dir_ / ("contact_" + std::to_string(j) + ".h5");
    FrameWriter w(p, "{}");
    Frame f;
    f.resize(3, 2);
    f.position().col(0) << -0.5, 1.5, 98.5;
    f.position().col(1).setZero();
    f.radius().setConstant(0.5);
    f.container = Container::periodic_box(2, Eigen::Vector3d(-1, -5, 0), Eigen::Vector3d(99, 5, 0));
    f.add_contacts(1);
    f.contact_i()[0] = 0;
    f.contact_j()[0] = j;
    w.append(f);
    w.close();
    return p;
  };
  EXPECT_EQ(error_of([&] { return source(with_contact(2), 0, -1, 1); }), "(no InputError)");
  const fs::path apart = with_contact(1);
  EXPECT_EQ(error_of([&] { return source(apart, 0, -1, 1); }),
            apart.string() +
                ": frame 0: contact 0: expected particles that touch, got 0 and 1 (ids 0, 1), "
                "whose surfaces are 1 apart (more than the smaller radius, 0.5)");
}

// A pair contact's point a million radii from the pair made the force network's F(r) bins
// of that contact NaN, exit 0. Particles 0 and 1 touch at (0, 0).
TEST_F(H5mdSourceTest, APairContactsPointAwayFromThePairIsRefused) {
  const auto with_point = [&](const Eigen::Vector2d& point) {
    const fs::path p = dir_ / ("pair_point_" + std::to_string(point[0]) + ".h5");
    FrameWriter w(p, "{}");
    Frame f;
    f.resize(2, 2);
    f.position() << -0.5, 0.0, 0.5, 0.0;
    f.radius().setConstant(0.5);
    f.container = Container::open_top_box(2, Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 0));
    f.add_contacts(1);
    f.contact_i()[0] = 0;
    f.contact_j()[0] = 1;
    f.contacts->add(*find_standard("point", Scope::Contact)).as<Coordinates>().row(0) =
        point.transpose();
    w.append(f);
    w.close();
    return p;
  };
  EXPECT_EQ(error_of([&] { return source(with_point({0.0, 0.0}), 0, -1, 1); }), "(no InputError)");
  const fs::path far = with_point({4.0, 0.0});
  EXPECT_EQ(error_of([&] { return source(far, 0, -1, 1); }),
            far.string() +
                ": frame 0: contact 0: expected its point where particles 0 and 1 touch, got it "
                "4 from the surface of particle 0 (id 0; more than the smaller radius, 0.5)");
}

// A "base contact" of a particle 86 above the base was counted among the intruder's base
// contacts, exit 0. In a box with a floor at y = 0 and a wall at x = 10 (offset by 0.25),
// particle 0 rests on the floor and particle 1 touches nothing.
TEST_F(H5mdSourceTest, AWallContactOfAParticleAwayFromTheWallIsRefused) {
  // With a contact point, the wall was where the point says (a mesh, a moving base the
  // stated container only approximates).
  const auto with_contact = [&](std::int64_t i, Wall wall,
                                std::optional<Eigen::Vector2d> point = std::nullopt) {
    const fs::path p = dir_ / ("wall_contact_" + std::to_string(i) + to_string(wall) +
                               (point ? "_point" + std::to_string((*point)[1]) : "") + ".h5");
    FrameWriter w(p, "{}");
    Frame f;
    f.resize(2, 2);
    f.position() << 1.0, 0.5, 6.0, 3.5;
    f.radius().setConstant(0.5);
    f.container = Container::open_top_box(2, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 20, 0));
    f.container.wall_offset.x() = 0.25;
    f.add_contacts(1);
    f.contact_i()[0] = i;
    f.contact_j()[0] = partner::wall(wall);
    if (point) {
      f.contacts->add(*find_standard("point", Scope::Contact)).as<Coordinates>().row(0) =
          point->transpose();
    }
    w.append(f);
    w.close();
    return p;
  };
  EXPECT_EQ(error_of([&] { return source(with_contact(0, Wall::YLow), 0, -1, 1); }),
            "(no InputError)");
  const fs::path above = with_contact(1, Wall::YLow);
  EXPECT_EQ(error_of([&] { return source(above, 0, -1, 1); }),
            above.string() +
                ": frame 0: contact 0: expected particle 1 (id 1) to touch the wall y_low, got "
                "its surface 3 from it (more than its radius, 0.5)");
  // 10.25 - 6 - 0.5 from the displaced wall (3.5 from where it stands at rest).
  const fs::path side = with_contact(1, Wall::XHigh);
  EXPECT_EQ(error_of([&] { return source(side, 0, -1, 1); }),
            side.string() +
                ": frame 0: contact 0: expected particle 1 (id 1) to touch the wall x_high, got "
                "its surface 3.75 from it (more than its radius, 0.5)");
  EXPECT_EQ(error_of([&] {
              return source(with_contact(1, Wall::YLow, {{6.0, 3.0}}), 0, -1, 1);
            }),
            "(no InputError)");
  const fs::path far = with_contact(1, Wall::YLow, {{6.0, 0.0}});
  EXPECT_EQ(error_of([&] { return source(far, 0, -1, 1); }),
            far.string() +
                ": frame 0: contact 0: expected particle 1 (id 1) to touch the wall y_low, got "
                "its surface 3 from the contact's point (more than its radius, 0.5)");
}

// The radius for files without one did nothing for a file with radii, without a word.
TEST_F(H5mdSourceTest, ARadiusForAFileWithRadiiIsRefused) {
  const fs::path p = write(2);
  EXPECT_EQ(
      error_of([&] {
        harness_ = granpipe::test::make_context("h5md", {{"file", p.string()}, {"radius", 0.3}});
        return std::make_unique<h5md::H5mdSource>(*harness_);
      }),
      "params.radius: expected its default 0.5 for a file that stores radii (" + p.string() +
          "), got 0.3");
}

TEST_F(H5mdSourceTest, ExactlyTouchingParticlesAreAccepted) {
  EXPECT_EQ(error_of([&] { return source(write_pair(dir_, 1.0), 0, -1, 1); }), "(no InputError)");
}

// Every measure of an empty frame would be NaN.
TEST_F(H5mdSourceTest, FramesWithoutParticlesAreRefused) {
  const fs::path p = dir_ / "empty.h5";
  FrameWriter w(p, "{}");
  Frame f;
  f.resize(0, 2);
  w.append(f);
  w.close();
  EXPECT_EQ(error_of([&] { return source(p, 0, -1, 1); }),
            p.string() + ": frame 0: expected particles, got none");
}

// A particle through a wall was read, and measured in a container it is not in (a packing
// fraction of 0.02 for a block behind a wall, exit 0); one thrown above an open top is in
// its container, and read.
TEST_F(H5mdSourceTest, AParticleThroughAWallIsRefusedAndOneAboveAnOpenTopRead) {
  const fs::path p = dir_ / "walls.h5";
  Frame f;
  f.resize(2, 2);
  f.position() << 1.0, 0.5, 3.0, 7.0;  // the second far above the open top at y = 5
  f.radius().setConstant(0.5);
  f.container = Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(10, 5, 0));
  {
    FrameWriter w(p, "{}");
    w.append(f);
    w.close();
  }
  EXPECT_EQ(error_of([&] { return source(p, 0, -1, 1); }), "(no InputError)");
  fs::remove(p);
  f.position()(1, 0) = 10.2;
  FrameWriter w(p, "{}");
  w.append(f);
  w.close();
  EXPECT_EQ(error_of([&] { return source(p, 0, -1, 1); }),
            p.string() +
                ": frame 0: particle 1 (id 1) at (10.2, 7), radius 0.5: expected an overlap with "
                "the wall x_high (x = 10) of at most 5e-07 (1e-06 of its radius), got 0.7 "
                "(params.max_overlap sets the overlap accepted with a wall)");
}

// An infinite periodic box gave phi = 0 with exit 0.
TEST_F(H5mdSourceTest, AnInfiniteBoxIsRefusedWithFileAndFrame) {
  const fs::path p = dir_ / "infinite.h5";
  FrameWriter w(p, "{}");
  Frame f;
  f.resize(2, 2);
  f.position()(1, 0) = 2.0;
  f.radius().setConstant(0.5);
  f.container =
      Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1e308, 1e308, 0));
  w.append(f);
  w.close();
  EXPECT_EQ(
      error_of([&] { return source(p, 0, -1, 1); }),
      p.string() + ": frame 0: expected a container of finite area, got sides of 1e+308 x 1e+308");
}

TEST_F(H5mdSourceTest, NanPositionsAreRefusedWithFileAndFrame) {
  const fs::path p = write_pair(dir_, std::nan(""));
  EXPECT_EQ(
      error_of([&] { return source(p, 0, -1, 1); }),
      p.string() +
          ": frame 0: particle 1 (id 1): expected a finite position, got nan in coordinate x");
}

namespace {

// A run split over sessions: each later part starts with the saved frame it continued from.
class RunPartsTest : public H5mdSourceTest {
 protected:
  // Frames k = first .. last (step 10 k, positions k + i, as write() makes them), velocity
  // `part` in every entry, so that a frame says which part it was read from.
  fs::path write_part(const std::string& name, long first, long last, double part,
                      Eigen::Index particles = 3) {
    std::vector<long> ks;
    for (long k = first; k <= last; ++k) ks.push_back(k);
    return write_frames(name, ks, part, particles);
  }

  // Frames k of `ks` in that order, made as write_part makes them.
  // Frames k at steps 10 k, with the times given (or 0).
  fs::path write_frames(const std::string& name, const std::vector<long>& ks, double part,
                        Eigen::Index particles = 3, const std::vector<double>& times = {}) {
    const fs::path p = dir_ / name;
    FrameWriter w(p, "{}");
    for (std::size_t n = 0; n < ks.size(); ++n) {
      const long k = ks[n];
      Frame f;
      f.resize(particles, 2);
      for (Eigen::Index i = 0; i < particles; ++i) f.position()(i, 0) = static_cast<double>(k + i);
      f.radius().setConstant(0.5);
      f.container =
          Container::periodic_box(2, Eigen::Vector3d(-1, -5, 0), Eigen::Vector3d(99, 5, 0));
      f.add("velocity");
      f.table<double>("velocity").setConstant(part);
      f.step = 10 * k;
      if (!times.empty()) f.time = times[n];
      w.append(f);
    }
    w.close();
    return p;
  }

  std::unique_ptr<h5md::H5mdSource> joined(const fs::path& first,
                                           const std::vector<fs::path>& later) {
    std::vector<std::string> files;
    for (const auto& p : later) files.push_back(p.string());
    harness_ =
        granpipe::test::make_context("h5md", {{"file", first.string()}, {"continued_in", files}});
    return std::make_unique<h5md::H5mdSource>(*harness_);
  }

  // The part each frame came from.
  static std::vector<double> parts_of(Source& s) {
    std::vector<double> parts;
    Frame f;
    while (s.next(f)) parts.push_back(f.table<double>("velocity")(0, 0));
    return parts;
  }
};

TEST_F(RunPartsTest, PartsReadAsOneRunEachFrameOnce) {
  const fs::path a = write_part("a.h5", 0, 2, 1), b = write_part("b.h5", 2, 4, 2),
                 c = write_part("c.h5", 4, 5, 3);
  EXPECT_EQ(steps_of(*joined(a, {b, c})), (Steps{0, 10, 20, 30, 40, 50}));
  // The saved frame at a join is read from the part that made it (its tap's observables).
  EXPECT_EQ(parts_of(*joined(a, {b, c})), (std::vector<double>{1, 1, 1, 2, 2, 3}));
  EXPECT_EQ(joined(a, {b, c})->work().total, 6.0);
}

TEST_F(RunPartsTest, AStartFromAnEarlierFrameDropsTheFramesAfterIt) {
  const fs::path a = write_part("a.h5", 0, 4, 1), b = write_part("b.h5", 2, 3, 2);
  EXPECT_EQ(steps_of(*joined(a, {b})), (Steps{0, 10, 20, 30}));
  EXPECT_EQ(parts_of(*joined(a, {b})), (std::vector<double>{1, 1, 1, 2}));
}

TEST_F(RunPartsTest, FrameSelectionAppliesToTheJoinedRun) {
  const fs::path a = write_part("a.h5", 0, 2, 1), b = write_part("b.h5", 2, 6, 2);
  harness_ = granpipe::test::make_context(
      "h5md", {{"file", a.string()}, {"continued_in", {b.string()}}, {"first", 1}, {"stride", 2}});
  h5md::H5mdSource s(*harness_);
  EXPECT_EQ(steps_of(s), (Steps{10, 30, 50}));
}

TEST_F(RunPartsTest, APartThatContinuesNoneIsRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1);
  const fs::path later = write_part("later.h5", 3, 4, 2);  // starts at step 30, a ends at 20
  EXPECT_EQ(error_of([&] { return joined(a, {later}); }),
            "params.continued_in[0]: " + later.string() +
                " starts at step 30, expected a frame that the parts before it hold (not a "
                "continuation of them; a part holds first the frame it started from, which a run "
                "saved without its start lacks)");
}

TEST_F(RunPartsTest, AnotherPackingAtTheJoinIsRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1);
  const fs::path moved = dir_ / "moved.h5";
  {
    FrameWriter w(moved, "{}");
    Frame f;
    f.resize(3, 2);
    f.position()(1, 0) = 7.0;
    f.radius().setConstant(0.5);
    f.add("velocity");
    f.step = 20;
    w.append(f);
    w.close();
  }
  EXPECT_EQ(error_of([&] { return joined(a, {moved}); }),
            "params.continued_in[0]: " + moved.string() +
                " starts at step 20, expected a frame that the parts before it hold, got another "
                "packing than " +
                a.string() + ": frame 2 (not a continuation of it)");
}

TEST_F(RunPartsTest, TheSamePositionsWithOtherIdsSpeciesContainerOrTimeAreRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1);
  // Part a's frame 2 (step 20) with one thing changed.
  const auto join = [&](const std::string& name, const std::function<void(Frame&)>& change) {
    const fs::path p = write_part(name, 2, 2, 2);
    Frame f = FrameReader(p.string()).read(0);
    change(f);
    fs::remove(p);
    FrameWriter w(p, "{}");
    w.append(f);
    w.close();
    return error_of([&] { return joined(a, {p}); });
  };
  const auto refused = [&](const std::string& name, const std::string& difference,
                           const std::string& detail) {
    return "params.continued_in[0]: " + (dir_ / name).string() +
           " starts at step 20, expected a frame that the parts before it hold, got " + difference +
           " than " + a.string() + ": frame 2 (" + detail + "; not a continuation of it)";
  };
  EXPECT_EQ(join("ids.h5", [](Frame& f) { f.id() += 100; }),
            refused("ids.h5", "other particle ids", "row 0: 100, there 0"));
  EXPECT_EQ(join("species.h5", [](Frame& f) { f.species()[1] = 1; }),
            refused("species.h5", "other species", "row 1: 1, there 0"));
  EXPECT_EQ(join("walls.h5",
                 [](Frame& f) {
                   f.container.boundary[0] = {Boundary::Wall, Boundary::Wall};
                 }),
            refused("walls.h5", "another container", "boundary along x wall, there periodic"));
  EXPECT_EQ(
      join("time.h5", [](Frame& f) { f.time = 50.0; }),
      refused("time.h5", "another time", "time 50, there 0 (a converter run with another dt?)"));
  EXPECT_EQ(join("same.h5", [](Frame&) {}), "(no InputError)");
  // An undefined time (NaN: frames of a dump read without dt) is the same in both parts.
  const double nan = std::nan("");
  const fs::path undefined_a = write_frames("undefined_a.h5", {0, 1, 2}, 1, 3, {nan, nan, nan});
  const fs::path undefined_b = write_frames("undefined_b.h5", {2, 3}, 2, 3, {nan, nan});
  EXPECT_EQ(steps_of(*joined(undefined_a, {undefined_b})), (Steps{0, 10, 20, 30}));
}

TEST_F(RunPartsTest, OtherParticlesAreRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1), b = write_part("b.h5", 2, 3, 2, 4);
  EXPECT_EQ(error_of([&] { return joined(a, {b}); }),
            "params.continued_in[0]: " + b.string() + ": expected frames of 3 particles in 2D as " +
                a.string() + " holds, got 4 in 2D");
}

TEST_F(RunPartsTest, APartThatDropsAWholeListedPartIsRefused) {
  // c restarts from a's frame 1, before every frame b added: b would vanish unread.
  const fs::path a = write_part("a.h5", 0, 2, 1), b = write_part("b.h5", 2, 4, 2),
                 c = write_part("c.h5", 1, 3, 3);
  EXPECT_EQ(error_of([&] {
              return joined(a, {b, c});
            }),
            "params.continued_in[1]: " + c.string() +
                " starts at step 10, expected a frame that follows the part before it, got a step "
                "before every frame of " +
                b.string() + " (list the parts in the order of the run, leaving out any replaced)");
  // A restart within the part before it keeps that part's frames up to it.
  const fs::path d = write_part("d.h5", 3, 5, 4);
  EXPECT_EQ(steps_of(*joined(a, {b, d})), (Steps{0, 10, 20, 30, 40, 50}));
  EXPECT_EQ(parts_of(*joined(a, {b, d})), (std::vector<double>{1, 1, 1, 2, 4, 4}));
}

TEST_F(RunPartsTest, APartWithoutFramesIsRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1), empty = write_frames("empty.h5", {}, 2);
  EXPECT_EQ(error_of([&] { return joined(a, {empty}); }),
            "params.continued_in[0]: " + empty.string() +
                ": expected a part with frames (at least the one it started from), got none");
}

TEST_F(RunPartsTest, AFileNamedTwiceIsRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1), b = write_part("b.h5", 2, 4, 2);
  EXPECT_EQ(error_of([&] { return joined(a, {a}); }),
            "params.continued_in[0]: expected a later part of the run, got " + a.string() +
                ", the file params.file names");
  const fs::path b_again = dir_ / "." / "b.h5";  // another spelling of the same file
  EXPECT_EQ(error_of([&] {
              return joined(a, {b, b_again});
            }),
            "params.continued_in[1]: expected a later part of the run, got " + b_again.string() +
                ", the file params.continued_in[0] names");
}

TEST_F(RunPartsTest, APartThatIsNoFramesFileIsRefusedNamingIt) {
  const fs::path a = write_part("a.h5", 0, 2, 1), text = dir_ / "part.txt";
  std::ofstream(text) << "not frames\n";
  EXPECT_EQ(error_of([&] { return joined(a, {text}); }),
            "params.continued_in[0]: " + text.string() + ": not an HDF5 file (no HDF5 signature)");
}

TEST_F(RunPartsTest, StepsThatRepeatOrGoBackInALaterPartAreRefused) {
  const fs::path a = write_part("a.h5", 0, 2, 1);
  const fs::path repeated = write_frames("repeated.h5", {2, 2, 3}, 2);
  EXPECT_EQ(
      error_of([&] { return joined(a, {repeated}); }),
      "params.continued_in: " + repeated.string() + ": frame 1: expected a step above 20 (" +
          a.string() +
          ": frame 2, the frame read before it: the parts are one run, steps rising), got 20");
  const fs::path back = write_frames("back.h5", {2, 4, 3}, 2);
  EXPECT_EQ(
      error_of([&] { return joined(a, {back}); }),
      "params.continued_in: " + back.string() + ": frame 2: expected a step above 40 (" +
          back.string() +
          ": frame 1, the frame read before it: the parts are one run, steps rising), got 30");
}

TEST_F(RunPartsTest, StepsThatRepeatOrGoBackInOneFileAreRefused) {
  const fs::path back = write_frames("one_back.h5", {0, 2, 1}, 1);
  EXPECT_EQ(error_of([&] { return joined(back, {}); }),
            "params.file: " + back.string() + ": frame 2: expected a step above 20 (" +
                back.string() + ": frame 1, the frame read before it: a run's steps rise), got 10");
  const fs::path repeated = write_frames("one_repeated.h5", {0, 1, 1}, 1);
  EXPECT_EQ(error_of([&] { return joined(repeated, {}); }),
            "params.file: " + repeated.string() + ": frame 2: expected a step above 10 (" +
                repeated.string() +
                ": frame 1, the frame read before it: a run's steps rise), got 10");
  const fs::path rising = write_frames("one_rising.h5", {0, 1, 3}, 1);
  EXPECT_EQ(error_of([&] { return joined(rising, {}); }), "(no InputError)");
}

// Times that ran down while the steps rose (another tool's file) gave the intruder's
// lift-offs backwards, exit 0.
TEST_F(RunPartsTest, TimesThatGoBackAreRefused) {
  const auto with_times = [&](const std::string& name, const std::vector<double>& times) {
    return write_frames(name, {0, 1, 2}, 1, 3, times);
  };
  const fs::path back = with_times("times_back.h5", {3.0, 2.0, 1.0});
  EXPECT_EQ(error_of([&] { return joined(back, {}); }),
            "params.file: " + back.string() + ": frame 1: expected a time at or after 3 (" +
                back.string() + ": frame 0, the frame read before it), got 2");
  const fs::path level = with_times("times_level.h5", {1.0, 1.0, 2.0});
  EXPECT_EQ(error_of([&] { return joined(level, {}); }), "(no InputError)");
}

TEST_F(RunPartsTest, AMissingPartIsRefusedAtValidation) {
  const fs::path a = write_part("a.h5", 0, 2, 1);
  EXPECT_EQ(error_of([&] { return joined(a, {"nowhere_part.h5"}); }),
            "test: params.continued_in[0]: expected an existing file, got \"nowhere_part.h5\" (no "
            "such file)");
}

}  // namespace
