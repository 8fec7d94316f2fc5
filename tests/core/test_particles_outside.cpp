// Particles outside their container: through a wall by more than the tolerance, beyond an
// open side, through a displaced cylinder; periodic sides and a cylinder's box bound nothing.
#include <gtest/gtest.h>

#include "granpipe/particles_outside.hpp"

using namespace granpipe;

namespace {

// Spheres of radius 0.5 at these (x, y, z), in an open-top box [0, 4]^2 x [0, 10].
Frame spheres(std::initializer_list<Eigen::Vector3d> at) {
  Frame f;
  f.resize(static_cast<Eigen::Index>(at.size()), 3);
  f.radius().setConstant(0.5);
  Eigen::Index k = 0;
  for (const Eigen::Vector3d& x : at) f.position().row(k++) = x.transpose().array();
  f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 10));
  return f;
}

}  // namespace

TEST(ParticlesOutside, TouchingWithinTheToleranceIsInside) {
  // On the base, and pressed into the x_high wall by 0.04 of the radius.
  const Frame f = spheres({{1, 1, 0.5}, {3.52, 1, 2}});
  EXPECT_FALSE(first_particle_outside(f, 0.05));
  const auto out = first_particle_outside(f, 0.01);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->particle, 1);
  EXPECT_EQ(out->wall, Wall::XHigh);
  EXPECT_NEAR(out->depth, 0.02, 1e-12);
}

TEST(ParticlesOutside, TheFirstParticleThroughAWallIsNamedWithItsOverlap) {
  Frame f = spheres({{1, 1, 1}, {1, -3, 1}, {5, 1, 1}});
  const auto out = first_particle_outside(f, 0.05);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->particle, 1);
  EXPECT_EQ(out->wall, Wall::YLow);
  EXPECT_DOUBLE_EQ(out->depth, 3.5);  // its far side is 3.5 beyond y = 0
  f.id()[1] = 42;
  EXPECT_EQ(describe(f, *out, 0.05),
            "at (1, -3, 1), radius 0.5: expected an overlap with the wall y_low (y = 0) of at "
            "most 0.025 (0.05 of its radius), got 3.5");
}

TEST(ParticlesOutside, AboveTheOpenTopIsOutsideByItsCentre) {
  const Frame touching_top = spheres({{1, 1, 9.8}});
  EXPECT_FALSE(first_particle_outside(touching_top, 0.05));
  const Frame f = spheres({{1, 1, 12}});
  const auto out = first_particle_outside(f, 0.05);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->wall, Wall::ZHigh);
  EXPECT_DOUBLE_EQ(out->depth, 2.0);
  EXPECT_EQ(describe(f, *out, 0.05),
            "at (1, 1, 12), radius 0.5: expected its centre inside the open side z_high (z = 10), "
            "got it 2 beyond");
}

TEST(ParticlesOutside, PeriodicSidesBoundNothing) {
  Frame f = spheres({{-3, 7, 1}});
  f.container.boundary[0] = f.container.boundary[1] = {Boundary::Periodic, Boundary::Periodic};
  EXPECT_FALSE(first_particle_outside(f, 0.05));
}

// The cylinder moves with the drive's offset; its box's x and y sides are no walls.
TEST(ParticlesOutside, TheCylinderIsWhereTheFrameShowsIt) {
  Frame f = spheres({{0, 0, 1}, {-1.5, 0, 1}});
  f.container.lo = Eigen::Vector3d(-2, -2, 0);
  f.container.hi = Eigen::Vector3d(2, 2, 10);
  f.container.shape = ContainerShape::Cylinder;
  f.container.cylinder_radius = 2.0;
  EXPECT_FALSE(first_particle_outside(f, 0.05)) << "a sphere at 1.5 of the axis touches the wall";
  f.container.wall_offset = Eigen::Vector3d(0.5, 0, 0.25);
  const auto out = first_particle_outside(f, 0.05);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->particle, 1);
  EXPECT_EQ(out->wall, Wall::CylinderSide);
  EXPECT_DOUBLE_EQ(out->depth, 0.5);  // 2 from the displaced axis: 0.5 - (2 - 2)
}

TEST(ParticlesOutside, TwoDimensionalFramesHaveNoZSides) {
  Frame f;
  f.resize(1, 2);
  f.radius().setConstant(0.5);
  f.position() << 1, 0.5;
  f.container = Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 5, 0));
  EXPECT_FALSE(first_particle_outside(f, 0.05));
}
