// Periodic geometry of a container: minimum image and wrapping, on periodic and walled axes;
// the checks of its values and walls a frame makes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "granpipe/container.hpp"
#include "granpipe/container_check.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/property.hpp"
#include "granpipe/separation.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

TEST(Container, MinimumImageOnPeriodicAxesOnly) {
  Container c = Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 10, 0));
  c.boundary[1] = {Boundary::Wall, Boundary::Open};
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 3.5), -0.5);  // period 4
  EXPECT_DOUBLE_EQ(c.minimum_image(0, -2.5), 1.5);
  EXPECT_DOUBLE_EQ(c.minimum_image(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(c.minimum_image(1, 7.0), 7.0);  // walls: unchanged
}

// Two disks touching through the periodic side x: 0.5 apart, not 3.5; y is walled.
TEST(Container, SeparationOfTwoParticlesTakesTheNearerImage) {
  Frame f;
  f.resize(2, 2);
  f.container = Container::periodic_box(2, Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(3, 10, 0));
  f.container.boundary[1] = {Boundary::Wall, Boundary::Wall};
  f.position() << -0.75, 1.0, 2.75, 9.0;
  EXPECT_EQ(separation(f, 0, 1), Eigen::Vector3d(-0.5, 8.0, 0.0));
  EXPECT_EQ(separation(f, 1, 0), Eigen::Vector3d(0.5, -8.0, 0.0));
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

// Numbers that are no numbers (an edge of inf, a wall offset of NaN from another tool or an
// edited file) made every fraction 0 or NaN, exit 0; an axis periodic at one end only was
// periodic to the measures and a wall to the overlap check. Frame::check refuses them.
TEST(ContainerCheck, ValuesMustBeFiniteAndInOrder) {
  Container c = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 8));
  EXPECT_NO_THROW(check_container_values(c, 3, "f"));
  c.hi[1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected a finite upper side along y of the container, got inf");
  c.hi[1] = 4.0;
  c.wall_offset[2] = std::nan("");
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected a finite wall offset along z of the container, got nan");
  c.wall_offset[2] = 0.0;
  // Finite sides, an infinite volume: packing's phi read 0 for a base at -1e308.
  c.lo[2] = -1e308;
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected a container of finite volume, got sides of 4 x 4 x 1e+308");
  c.hi[2] = 1e308;
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected a container of finite volume, got sides of 4 x 4 x inf");
  c.lo[2] = 0.0;
  c.hi[2] = 8.0;
  c.lo[0] = 4.0;
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected the container's sides along x in order (lo < hi), got 4 to 4");
  c.lo[0] = 0.0;
  c.boundary[0] = {Boundary::Periodic, Boundary::Wall};
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected both sides along x periodic or neither (a periodic axis joins its "
            "ends), got periodic and wall");
  c.boundary[0] = {Boundary::Wall, Boundary::Wall};
  c.shape = ContainerShape::Cylinder;
  c.cylinder_radius = -1.0;
  EXPECT_EQ(test::input_error_of([&] { check_container_values(c, 3, "f"); }),
            "f: expected a finite cylinder radius > 0, got -1");
  // A 2D frame's z entries mean nothing and are not checked.
  Container flat = Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 0));
  EXPECT_NO_THROW(check_container_values(flat, 2, "f"));
}

TEST(ContainerCheck, WallsAreTheSolidSidesAndTheCylinder) {
  Container c = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 8));
  c.boundary[0] = {Boundary::Periodic, Boundary::Periodic};
  EXPECT_FALSE(has_wall(c, 3, Wall::XLow));
  EXPECT_TRUE(has_wall(c, 3, Wall::YHigh));
  EXPECT_TRUE(has_wall(c, 3, Wall::ZLow));
  EXPECT_FALSE(has_wall(c, 3, Wall::ZHigh));  // the open top
  EXPECT_FALSE(has_wall(c, 3, Wall::CylinderSide));
  c.shape = ContainerShape::Cylinder;
  c.cylinder_radius = 2.0;
  EXPECT_TRUE(has_wall(c, 3, Wall::CylinderSide));
  EXPECT_FALSE(has_wall(c, 3, Wall::YHigh));  // the cylinder's box only bounds its cell grid
  // A 2D frame's z sides (walls in what disks2d_tap writes) are none: a contact with z_low
  // was read, its particle's z read past the end of a table of two columns.
  Container flat = Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 0));
  flat.boundary[2] = {Boundary::Wall, Boundary::Wall};
  EXPECT_TRUE(has_wall(flat, 2, Wall::YLow));
  EXPECT_FALSE(has_wall(flat, 2, Wall::ZLow));
  flat.shape = ContainerShape::Cylinder;
  flat.cylinder_radius = 2.0;
  EXPECT_FALSE(has_wall(flat, 2, Wall::CylinderSide));
}

// A contact naming a wall the container does not have was counted as a wall contact, and
// NaN velocities were read and written on (exit 0).
TEST(ContainerCheck, FramesRefuseContactsWithMissingWallsAndMotionThatIsNoNumber) {
  Frame f;
  f.resize(1, 3);
  f.position() << 0.5, 0.5, 0.5;
  f.radius().setConstant(0.5);
  f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 8));
  PropertyTable& contacts = f.add_contacts(1);
  contacts.column(0).as<IndexArray>()[0] = 0;
  contacts.column(1).as<IndexArray>()[0] = partner::wall(Wall::ZLow);
  EXPECT_NO_THROW(f.check("f"));
  contacts.column(1).as<IndexArray>()[0] = partner::wall(Wall::CylinderSide);
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contact 0: expected a wall of the box container as second partner, got cylinder "
            "(code -8), which it does not have");
  contacts.column(1).as<IndexArray>()[0] = partner::wall(Wall::ZLow);
  f.add("velocity").as<Coordinates>()(0, 1) = std::nan("");
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: particle 0 (id 0): expected a finite velocity, got nan in component 1");
}

// A table listing each pair both ways (or a row twice) doubled every coordination and
// network count of the h5md source's frames (exit 0). A particle touching one wall in two
// rows (two facets of a mesh wall) is no duplicate.
TEST(ContainerCheck, FramesRefuseAPairListedTwice) {
  Frame f;
  f.resize(3, 3);
  f.position() << 0.5, 0.5, 0.5, 1.5, 0.5, 0.5, 2.5, 0.5, 0.5;
  f.radius().setConstant(0.5);
  f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 8));
  PropertyTable& contacts = f.add_contacts(4);
  contacts.column(0).as<IndexArray>() << 0, 1, 0, 0;
  contacts.column(1).as<IndexArray>() << 1, 2, partner::wall(Wall::ZLow), partner::wall(Wall::ZLow);
  EXPECT_NO_THROW(f.check("f"));
  contacts.column(0).as<IndexArray>()[3] = 1;
  contacts.column(1).as<IndexArray>()[3] = 0;
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contacts 0 and 3: expected each pair of particles once, got 0 and 1 in both (a "
            "table listing each pair both ways?)");
  // A simulator's own order, (i, j) increasing with i < j (the dem source's, wall rows
  // first), takes a shortcut that must not pass a row repeated right after itself, nor one
  // that goes back.
  const std::int64_t base = partner::wall(Wall::ZLow);
  contacts.column(0).as<IndexArray>() << 0, 0, 0, 1;
  contacts.column(1).as<IndexArray>() << base, 1, 2, 2;
  EXPECT_NO_THROW(f.check("f"));
  contacts.column(0).as<IndexArray>() << 0, 0, 1, 1;
  contacts.column(1).as<IndexArray>() << base, 1, 2, 2;
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contacts 2 and 3: expected each pair of particles once, got 1 and 2 in both (a "
            "table listing each pair both ways?)");
  contacts.column(0).as<IndexArray>() << 0, 1, 0, 0;
  contacts.column(1).as<IndexArray>() << 1, 2, 2, 1;
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contacts 0 and 3: expected each pair of particles once, got 0 and 1 in both (a "
            "table listing each pair both ways?)");
}

namespace {

// Two touching spheres on the base of an open box.
Frame two_on_the_base() {
  Frame f;
  f.resize(2, 3);
  f.position() << 0.5, 0.5, 0.5, 1.5, 0.5, 0.5;
  f.radius().setConstant(0.5);
  f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 4, 8));
  return f;
}

}  // namespace

// Two rows of one particle against one wall are two facets of a mesh wall where their
// values differ, and one row written twice where they do not (an H5MD file whose base
// contacts were each listed twice doubled the intruder's base contacts, exit 0).
TEST(ContainerCheck, FramesRefuseAWallContactWrittenTwice) {
  Frame f = two_on_the_base();
  PropertyTable& contacts = f.add_contacts(4);
  contacts.column(0).as<IndexArray>() << 1, 0, 1, 0;
  const std::int64_t base = partner::wall(Wall::ZLow);
  contacts.column(1).as<IndexArray>() << base, 1, base, base;
  EXPECT_NO_THROW(f.check("f"));  // i and j alone: facets or a repeat, who can tell
  auto& point = contacts.add(*find_standard("point", Scope::Contact)).as<Coordinates>();
  point.row(0) << 1.5, 0.5, 0.0;
  point.row(1) << 1.0, 0.5, 0.5;
  point.row(3) << 0.5, 0.5, 0.0;
  point.row(2) << 1.25, 0.5, 0.0;
  EXPECT_NO_THROW(f.check("f"));
  point.row(2) = point.row(0);
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contacts 0 and 2: expected each contact once, got particle 1 (id 1) against the "
            "wall z_low in both with the same values (a row written twice?)");
}

// An H5MD file's contact forces of inf and overlaps of NaN went into the networks' and the
// intruder's statistics, exit 0.
TEST(ContainerCheck, FramesRefuseContactValuesThatAreNotNumbers) {
  Frame f = two_on_the_base();
  PropertyTable& contacts = f.add_contacts(2);
  contacts.column(0).as<IndexArray>() << 0, 1;
  contacts.column(1).as<IndexArray>() << 1, partner::wall(Wall::ZLow);
  auto& overlap = contacts.add(*find_standard("overlap", Scope::Contact)).as<Values<double>>();
  auto& normal = contacts.add(*find_standard("normal_force", Scope::Contact)).as<Coordinates>();
  EXPECT_NO_THROW(f.check("f"));
  normal(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contact 1: expected a finite normal_force, got inf in component 2");
  normal(1, 2) = 1.0;
  overlap[0] = std::nan("");
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: contact 0: expected a finite overlap, got nan");
}

// With two or more particles the neighbour search refused such a box; a lone particle met
// no such search and a periodic box 0.1 wide gave a packing fraction of 52.
TEST(ContainerCheck, FramesRefuseAParticleWiderThanItsPeriodicBox) {
  Frame f;
  f.resize(1, 3);
  f.position() << 0, 0, 0.5;
  f.radius().setConstant(0.5);
  f.container =
      Container::periodic_box(3, Eigen::Vector3d(-0.5, -0.05, 0), Eigen::Vector3d(0.5, 0.05, 10));
  EXPECT_EQ(test::input_error_of([&] { f.check("f"); }),
            "f: particle 0 (id 0): expected a diameter of at most the periodic box's length along "
            "y, 0.1, got 1 (it would overlap its own image)");
  f.container.lo[1] = -0.5;  // touching its own image is allowed
  f.container.hi[1] = 0.5;
  EXPECT_NO_THROW(f.check("f"));
}
