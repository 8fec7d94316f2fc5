// The container a pipeline states for a file that records none (LAMMPS data files and
// dumps): its parameters checked together, the stated walls placed in the file's box, and
// the first particle outside named with the parameter that placed its wall.
#include <gtest/gtest.h>

#include "granpipe/stated_container.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

namespace {

Schema schema() {
  Schema s;
  declare_stated_container(s);
  return s;
}

// The refusal of these parameters, or "no refusal".
std::string refusal(nlohmann::json params) {
  return test::input_error_of([&] {
    auto harness = test::make_context(schema(), std::move(params));
    StatedContainer stated(*harness);
  });
}

// A box [0, 4] x [0, 4] x [0, 8], periodic along the axes given.
Container file_box(bool periodic_x, bool periodic_z) {
  Container c = Container::periodic_box(3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 4, 8));
  if (!periodic_x) c.boundary[0] = {Boundary::Open, Boundary::Open};
  c.boundary[1] = {Boundary::Open, Boundary::Open};
  if (!periodic_z) c.boundary[2] = {Boundary::Open, Boundary::Open};
  return c;
}

// Atoms 5 at (2, 2, 1) and 9 at `second`, radius 0.5, in the stated container placed in
// file_box(false, false).
Frame two_atoms(const StatedContainer& stated, const Eigen::Vector3d& second) {
  Frame f;
  f.resize(2, 3);
  f.radius().setConstant(0.5);
  f.position() << 2, 2, 1, second.x(), second.y(), second.z();
  f.id() << 5, 9;
  f.container = stated.place(file_box(false, false), "x");
  return f;
}

}  // namespace

TEST(StatedContainer, ParametersThatContradictEachOtherAreRefused) {
  EXPECT_EQ(refusal({{"side_walls", {0, 1, 0}}}),
            "params.side_walls: expected [] or [x_lo, x_hi, y_lo, y_hi], got 3 numbers");
  EXPECT_EQ(refusal({{"side_walls", {0, 1, 0, 1}}, {"cylinder_radius", 2.0}}),
            "params.side_walls: expected [] in a cylinder (params.cylinder_radius 2), got side "
            "walls");
  EXPECT_EQ(refusal({{"side_walls", {0, 1, 3, 3}}}),
            "params.side_walls: expected y_hi above y_lo, got 3 and 3");
  EXPECT_EQ(refusal({{"base", 2.0}, {"top", 1.0}}),
            "params.top: expected a height above base, got 1");
  // An axis without a cylinder placed nothing, without a word.
  EXPECT_EQ(refusal({{"cylinder_axis", {1.0, 2.0}}}),
            "test: params.cylinder_axis: expected its default [0, 0] (it acts only with "
            "cylinder_radius > 0; here cylinder_radius is 0), got [1.0,2.0]");
}

TEST(StatedContainer, StatedWallsReplaceTheFilesSides) {
  auto harness = test::make_context(
      schema(), {{"cylinder_radius", 1.5}, {"cylinder_axis", {2, 2.5}}, {"base", 1.0}});
  const StatedContainer stated(*harness);
  const Container c = stated.place(file_box(false, false), "x");
  EXPECT_EQ(c.shape, ContainerShape::Cylinder);
  EXPECT_EQ(c.cylinder_center, Eigen::Vector2d(2, 2.5));
  EXPECT_EQ(c.lo, Eigen::Vector3d(0.5, 1, 1));
  EXPECT_EQ(c.hi, Eigen::Vector3d(3.5, 4, 100));
  EXPECT_EQ(c.boundary[2][0], Boundary::Wall);
  EXPECT_EQ(c.boundary[2][1], Boundary::Open);
  // A box periodic along z keeps its z sides: base and top bound nothing there (and are
  // refused when given: ABaseOrTopForAZPeriodicBoxIsRefused).
  auto no_base = test::make_context(schema(), {{"cylinder_radius", 1.5}});
  const Container periodic_z = StatedContainer(*no_base).place(file_box(false, true), "x");
  EXPECT_TRUE(periodic_z.periodic(2));
  EXPECT_EQ(periodic_z.hi[2], 8.0);
  EXPECT_THROW(
      {
        try {
          stated.place(file_box(true, false), "x.dump: timestep 0, line 5");
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(),
                       "x.dump: timestep 0, line 5: params.cylinder_radius: expected no walls "
                       "across the periodic x sides of the box, got a cylinder");
          throw;
        }
      },
      InputError);
}

TEST(StatedContainer, TheFirstParticleOutsideNamesThePlacingParameter) {
  auto harness = test::make_context(schema(), {{"side_walls", {0, 4, 0, 4}}});
  const StatedContainer stated(*harness);
  // The second through the wall x = 0.
  Frame f = two_atoms(stated, Eigen::Vector3d(0.3, 2, 1));
  const auto out = stated.first_outside(f, file_box(false, false), "the file's box");
  ASSERT_TRUE(out);
  EXPECT_EQ(out->particle, 1);
  EXPECT_EQ(out->message,
            "atom 9 at (0.3, 2, 1), radius 0.5: expected an overlap with the wall x_low (x = 0) "
            "of at most 0.025 (0.05 of its radius), got 0.2 (the container of params.side_walls)");
}

// The base and top replace the file's z sides, but a centre beyond them was lost to the
// code that wrote the file (a z of 50 in a box to 8 was read as in the container to 100).
TEST(StatedContainer, ACentreBeyondTheFilesOwnBoxIsOutside) {
  auto harness = test::make_context(schema(), nlohmann::json::object());
  const StatedContainer stated(*harness);
  Frame f = two_atoms(stated, Eigen::Vector3d(2, 2, 50));
  const auto out = stated.first_outside(f, file_box(false, false), "the file's box");
  ASSERT_TRUE(out);
  EXPECT_EQ(out->particle, 1);
  EXPECT_EQ(out->message,
            "atom 9 at (2, 2, 50), radius 0.5: expected its centre inside the open side z_high (z "
            "= 8.5), got it 41.5 beyond (the file's box)");
  f.position()(1, 2) = 8.4;  // within a radius: where LAMMPS writes atoms between rebuilds
  EXPECT_FALSE(stated.first_outside(f, file_box(false, false), "the file's box"));
}

// A base or top given for a file periodic along z bounded nothing, exit 0.
TEST(StatedContainer, ABaseOrTopForAZPeriodicBoxIsRefused) {
  auto harness = test::make_context(schema(), {{"base", 3.0}});
  const StatedContainer stated(*harness);
  EXPECT_EQ(test::input_error_of([&] { stated.place(file_box(false, true), "x.dump: line 5"); }),
            "x.dump: line 5: params.base: expected its default 0 for a box periodic along z (it "
            "bounds nothing there), got 3");
  EXPECT_NO_THROW(stated.place(file_box(false, false), "x"));
}
