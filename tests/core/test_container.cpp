// Periodic geometry of a container: minimum image and wrapping, on periodic and walled axes.
#include <gtest/gtest.h>

#include "granpipe/container.hpp"

using namespace granpipe;

TEST(Container, MinimumImageOnPeriodicAxesOnly) {
  Container c = Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 10, 0));
  c.boundary[1] = {Boundary::Wall, Boundary::Open};
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 3.5), -0.5);  // period 4
  EXPECT_DOUBLE_EQ(c.minimum_image(0, -2.5), 1.5);
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(c.minimum_image(1, 7.0), 7.0);  // walls: unchanged
}

TEST(Container, WrapIntoTheHalfOpenBox) {
  const Container c =
      Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 2, 0));
  EXPECT_DOUBLE_EQ(c.wrap(0, 3.5), -0.5);
  EXPECT_DOUBLE_EQ(c.wrap(0, -1.0), -1.0);
  EXPECT_DOUBLE_EQ(c.wrap(0, 3.0), -1.0);  // hi belongs to the next image
  EXPECT_DOUBLE_EQ(c.wrap(0, -9.0), -1.0);
  // Just below lo: x - L * floor(...) can round to hi exactly; it must come back as lo.
  const double below = std::nextafter(0.0, -1.0);
  const double w = c.wrap(1, below);
  EXPECT_GE(w, 0.0);
  EXPECT_LT(w, 2.0);
  const Container walls =
      Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(walls.wrap(0, 5.0), 5.0);
}
