// The extended XYZ writer: exact lines for a hand-made frame, and a pipeline whose .xyz
// holds, to the last bit, the frames that frames.h5 holds.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "granpipe/frame_store.hpp"
#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"
#include "granpipe/version.hpp"
#include "xyz_writer.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

Frame two_disks() {
  Frame f;
  f.resize(2, 2);
  f.container = Container::periodic_box(2, Eigen::Vector3d(-1, 0.5, 0), Eigen::Vector3d(3, 3, 0));
  f.position() << 0.5, 1.0, 2.25, 1.0;
  f.radius() << 0.5, 0.25;
  f.species() << 0, 1;
  auto& supports = f.particles.add<ValueTable<std::int64_t>>(
      {"supports", Scope::Particle, ValueType::Integer, 2, "", "left, right"});
  supports << -1, -4, 0, -4;
  f.time = 1.5;
  f.step = 7;
  return f;
}

}  // namespace

TEST(Xyz, CommentLineListsTheBoxItsOriginThePeriodicSidesAndEveryColumn) {
  EXPECT_EQ(xyz::comment_line(two_disks()),
            "Lattice=\"4 0 0 0 2.5 0 0 0 1\" Origin=\"-1 0.5 0\" "
            "Properties=pos:R:3:radius:R:1:id:I:1:species:I:1:"
            "supports:I:2 pbc=\"T T F\" Time=1.5 Step=7");
}

TEST(Xyz, AColumnOfTheNameOfPositionsOrVelocitiesIsWrittenApart) {
  Frame f = two_disks();
  for (const char* name : {"pos", "velo", "pos_column"})
    f.particles.add({name, Scope::Particle, ValueType::Real, 1, "", ""});
  const std::string line = xyz::comment_line(f);
  EXPECT_NE(line.find("Properties=pos:R:3:radius:R:1:id:I:1:species:I:1:supports:I:2:"
                      "pos_column_column:R:1:velo_column:R:1:pos_column:R:1 "),
            std::string::npos)
      << line;
}

// A vibrated container's walls move by wall_offset; a periodic side does not.
TEST(Xyz, TheOriginIsWhereTheWallsAreAtTheFrame) {
  Frame f = two_disks();
  f.container.wall_offset = Eigen::Vector3d(0.25, 0.125, 0.0);
  EXPECT_NE(xyz::comment_line(f).find("Lattice=\"4 0 0 0 2.5 0 0 0 1\" Origin=\"-1 0.5 0\""),
            std::string::npos);
  f.container.boundary[1] = {Boundary::Wall, Boundary::Wall};
  EXPECT_NE(xyz::comment_line(f).find("Lattice=\"4 0 0 0 2.5 0 0 0 1\" Origin=\"-1 0.625 0\""),
            std::string::npos);
}

TEST(Xyz, ParticleLinesHoldEveryColumnWithZEqualZeroIn2D) {
  const Frame f = two_disks();
  EXPECT_EQ(xyz::particle_line(f, 0, 17), "0.5 1 0 0.5 0 0 -1 -4");
  EXPECT_EQ(xyz::particle_line(f, 1, 17), "2.25 1 0 0.25 1 1 0 -4");
}

TEST(Xyz, APipelineWritesTheFramesThatFramesH5Holds) {
  Registry r;
  load_plugins(r, plugin_search_path());
  const Pipeline p = Pipeline::parse(R"({"seed": 4,
      "source": {"plugin": "lattice", "params": {"lattice": "bcc", "cells": [2, 2, 2], "jitter": 0.1,
                                                 "frames": 3}},
      "writers": [{"plugin": "xyz", "name": "movie"}]})",
                                     "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o;
  o.progress = false;
  o.out = fs::temp_directory_path() / ("granpipe_test_xyz_" + std::to_string(::getpid()));
  p.run(o, log);

  FrameReader frames(*o.out / "frames.h5");
  std::ifstream in(*o.out / "movie.xyz");
  ASSERT_TRUE(in.good());
  EXPECT_FALSE(fs::exists(*o.out / "movie.partial.xyz"));
  for (long k = 0; k < frames.frames(); ++k) {
    const Frame f = frames.read(k);
    std::string line;
    std::getline(in, line);
    ASSERT_EQ(line, std::to_string(f.size()));
    std::getline(in, line);
    EXPECT_EQ(line, xyz::comment_line(f) + " granpipe=\"granpipe " + version() + " commit " +
                        git_commit() + " pipeline p seed 4\"");
    for (Eigen::Index i = 0; i < f.size(); ++i) {
      std::getline(in, line);
      std::istringstream values(line);
      double x, y, z, radius;
      values >> x >> y >> z >> radius;
      EXPECT_EQ(x, f.position()(i, 0));  // 17 digits: the same double
      EXPECT_EQ(y, f.position()(i, 1));
      EXPECT_EQ(z, f.position()(i, 2));
      EXPECT_EQ(radius, f.radius()[i]);
    }
  }
  std::string rest;
  EXPECT_FALSE(std::getline(in, rest)) << "more lines than frames";
  fs::remove_all(*o.out);
}
