// Periodic geometry of a container: minimum image and wrapping, on periodic and walled axes.
#include <gtest/gtest.h>

#include <cmath>

#include "granpipe/container.hpp"

using namespace granpipe;

TEST(Container, MinimumImageOnPeriodicAxesOnly) {
  Container c = Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 10, 0));
  c.boundary[1] = {Boundary::Wall, Boundary::Open};
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 3.5), -0.5);   // period 4
  EXPECT_DOUBLE_EQ(c.minimum_image(0, -2.5), 1.5);
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(c.minimum_image(1, 7.0), 7.0);    // walls: unchanged
}

TEST(Container, WrapIntoTheHalfOpenBox) {
  const Container c = Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 2, 0));
  EXPECT_DOUBLE_EQ(c.wrap(0, 3.5), -0.5);
  EXPECT_DOUBLE_EQ(c.wrap(0, -1.0), -1.0);
  EXPECT_DOUBLE_EQ(c.wrap(0, 3.0), -1.0);  // hi belongs to the next image
  EXPECT_DOUBLE_EQ(c.wrap(0, -9.0), -1.0);
  // Just below lo: x - L * floor(...) can round to hi exactly; it must come back as lo.
  const double below = std::nextafter(0.0, -1.0);
  const double w = c.wrap(1, below);
  EXPECT_GE(w, 0.0);
  EXPECT_LT(w, 2.0);
  const Container walls = Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(walls.wrap(0, 5.0), 5.0);
}

// Particles outside their container: the first one past a wall by more than the
// tolerance (a fraction of its radius), with the wall and the depth; touching is inside.
TEST(Container, TheFirstParticleOutsideNamesItsWallAndDepth) {
  Container box = Container::open_top_box(3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 4, 4));
  Eigen::ArrayXXd x(3, 3);
  x << 2, 2, 0.5,    // resting on the base
      2, 2, 9.0,     // above the open top: inside
      3.8, 2, 2;     // 0.3 into the x_high wall
  const Eigen::ArrayXd r = Eigen::ArrayXd::Constant(3, 0.5);
  const auto out = first_particle_outside(box, 3, x, r, 0.5);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->index, 2);
  EXPECT_EQ(out->wall, Wall::XHigh);
  EXPECT_NEAR(out->depth, 0.3, 1e-12);
  EXPECT_FALSE(first_particle_outside(box, 3, x, r, 0.61).has_value());  // 0.3 < 0.61 * 0.5
}

TEST(Container, ACylinderHoldsItsParticlesWithItsWallsDisplaced) {
  Container c;
  c.shape = ContainerShape::Cylinder;
  c.cylinder_radius = 2.0;
  c.lo = Eigen::Vector3d(-2, -2, 0);
  c.hi = Eigen::Vector3d(2, 2, 10);
  c.boundary[2] = {Boundary::Wall, Boundary::Open};
  c.wall_offset = Eigen::Vector3d(0, 0, 1.0);  // the base is at z = 1
  Eigen::ArrayXXd x(2, 3);
  x << 0, 0, 1.5,   // on the displaced base
      1.2, 1.2, 5;  // centre 1.70 from the axis: 0.2 into the cylinder
  const Eigen::ArrayXd r = Eigen::ArrayXd::Constant(2, 0.5);
  const auto out = first_particle_outside(c, 3, x, r, 0.1);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->index, 1);
  EXPECT_EQ(out->wall, Wall::CylinderSide);
  EXPECT_NEAR(out->depth, 0.5 - (2.0 - std::hypot(1.2, 1.2)), 1e-12);
  x(0, 2) = 0.9;  // below the displaced base: its centre is outside
  EXPECT_EQ(first_particle_outside(c, 3, x, r, 0.1)->wall, Wall::ZLow);
  EXPECT_EQ(first_particle_outside(c, 3, x, r, 0.1)->index, 0);
}
