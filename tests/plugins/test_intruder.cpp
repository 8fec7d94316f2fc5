// The Brazil-nut observables on hand-made frames whose answers are known.
#include <gtest/gtest.h>

#include <vector>

#include "intruder_analyzer.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

namespace {

// An intruder of radius 1.5 at z = 4, two bed spheres of radius 0.5 at z = 0.5 and 1.5 (one
// on the other, the lower on the base), the base lifted by the drive to z = 0.25.
Frame bed() {
  Frame f;
  f.resize(3, 3);
  f.radius() << 0.5, 1.5, 0.5;
  f.position() << 0, 0, 0.75, 3, 0, 4.25, 0, 0, 1.75;
  f.container = Container::open_top_box(3, Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 10));
  f.container.wall_offset = Eigen::Vector3d(0, 0, 0.25);
  f.add_contacts(2);
  f.contact_i() << 0, 0;
  f.contact_j() << 2, partner::wall(Wall::ZLow);
  return f;
}

// The intruder analyzer's results after it consumed `frames` in order.
Results analyze(const std::vector<Frame>& frames) {
  const auto ctx = test::make_context("intruder");
  intruder::IntruderAnalyzer analyzer(*ctx);
  FrameCache cache;
  for (const Frame& f : frames) analyzer.consume(f, cache);
  Results r;
  analyzer.finish(r);
  return r;
}

}  // namespace

TEST(Intruder, HeightsAreAboveTheMovingBaseAndCoordinationCountsPairsOnly) {
  const intruder::BedState s = intruder::measure_bed(bed(), "test");
  EXPECT_DOUBLE_EQ(s.intruder_height, 4.0);
  EXPECT_DOUBLE_EQ(s.bed_height, 1.0);          // mean of 0.5 and 1.5
  EXPECT_DOUBLE_EQ(s.coordination, 2.0 / 3.0);  // one pair contact, three particles
}

// Rows of zero normal force (another code's neighbour pairs) touch nothing: the coordination
// counted them (3.31 where force_network's z_mean was 0), and a base row of none made the
// stage compression.
TEST(Intruder, ContactsWithoutANormalForceAreNotCounted) {
  Frame f = bed();
  f.contacts->add(*find_standard("normal_force", Scope::Contact));
  auto& force = f.contacts->get<Coordinates>("normal_force");
  force.row(0) << 0.0, 0.0, 1.0;  // the pair loaded
  force.row(1).setZero();         // the base row not
  const intruder::BedState s = intruder::measure_bed(f, "test");
  EXPECT_DOUBLE_EQ(s.coordination, 2.0 / 3.0);
  EXPECT_EQ(s.base_contacts, 0);
  force.row(0).setZero();
  EXPECT_DOUBLE_EQ(intruder::measure_bed(f, "test").coordination, 0.0);
}

TEST(Intruder, TheAnalyzerStreamsOneRowPerFrame) {
  Frame later = bed();
  later.time = 1.5;
  later.position()(1, 2) += 1.0;
  const Results r = analyze({bed(), later});
  const Table& t = r.tables().at("per_frame");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.column("intruder_height")[1], 5.0);
  EXPECT_EQ(t.column("time")[1], 1.5);
  EXPECT_EQ(r.plots().at("heights").x, "time");  // no cycles counted: against time
}

TEST(Intruder, AFrameWithoutABedIsRefused) {
  Frame f;
  f.resize(1, 3);
  f.radius().setConstant(0.5);
  try {
    intruder::measure_bed(f, "frame 3");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "frame 3: expected an intruder and a bed (2 particles or more), got 1");
  }
}

// With every radius equal there is no intruder: particle 0 is not one.
TEST(Intruder, ABedWithoutAnIntruderIsRefused) {
  Frame f = bed();
  f.radius().setConstant(0.5);
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyze({f}); }),
            "frame 0: expected an intruder (one particle larger than every other), "
            "got 3 particles of the largest radius 0.5 (a bed without an intruder?)");
  // Two large spheres: neither is the intruder. Radii equal to float precision are equal.
  f.radius() << 1.5, 1.5 * (1.0 + 1e-8), 0.5;
  EXPECT_THROW(intruder::measure_bed(f, "frame 0"), InputError);
}

// A polydisperse bed's largest grain was taken for the intruder (r = 0.5499 beside 0.5474
// in a bed of 0.45 to 0.55), exit 0. An intruder stands apart by more than the bed's spread.
TEST(Intruder, APolydisperseBedsLargestGrainIsNoIntruder) {
  Frame f = bed();
  f.radius() << 0.45, 0.56, 0.55;
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyze({f}); }),
            "frame 0: expected an intruder (one particle larger than every other, of a species "
            "of its own or by more than the bed's own radii spread), got a largest radius 0.56 "
            "beside the bed's 0.45 to 0.55 (a polydisperse bed without an intruder?)");
  f.radius() << 0.45, 1.5, 0.55;
  EXPECT_EQ(intruder::find_intruder(f, "test"), 1);
  // Its own species names it, however close: a bed of radii 1.05 to 1.5 with an intruder
  // of 1.9 was refused.
  f.radius() << 1.05, 1.9, 1.5;
  f.species() << 0, 1, 0;
  EXPECT_EQ(intruder::find_intruder(f, "test"), 1);
}

// A bed periodic along z (a dump of a box "pp pp pp") has no base: its heights were taken
// from the box's lower side and its stage was expansion forever, exit 0.
TEST(Intruder, AContainerWithoutABaseIsRefused) {
  Frame f = bed();
  f.container.boundary[2][0] = f.container.boundary[2][1] = Boundary::Periodic;
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyze({f}); }),
            "frame 0: expected a base (a wall at the bottom along z) to measure heights and "
            "the stage from, got a container periodic along z (state the wall where the "
            "source allows it)");
  f.container.boundary[2][0] = Boundary::Open;
  EXPECT_EQ(granpipe::test::input_error_of([&] { intruder::measure_bed(f, "frame 0"); }),
            "frame 0: expected a base (a wall at the bottom along z) to measure heights and "
            "the stage from, got a container open at the bottom along z (state the wall where "
            "the source allows it)");
}

// The bed's centre of mass weights by r^3, its mass only at one density: a bed of two
// species was weighted as one (8 too low with densities 1.91 and 20).
TEST(Intruder, ABedOfTwoSpeciesIsRefusedAnIntruderOfItsOwnIsNot) {
  Frame f = bed();
  f.species() << 0, 1, 0;  // the intruder its own species: the paper's scene
  EXPECT_DOUBLE_EQ(intruder::measure_bed(f, "frame 0").bed_height, 1.0);
  f.species() << 0, 1, 2;
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyze({f}); }),
            "frame 0: expected a bed of one species (the frame carries no densities to weight "
            "its centre of mass by), got species 0 (particle 0) and 2 (particle 2)");
}

// The intruder is the largest particle wherever it sits in the frame.
TEST(Intruder, TheIntruderIsTheOneLargestParticle) {
  Frame f = bed();
  EXPECT_EQ(intruder::find_intruder(f, "test"), 1);
  f.radius() << 0.5, 0.5, 0.51;
  EXPECT_EQ(intruder::find_intruder(f, "test"), 2);
}

TEST(Intruder, VelocitiesAreTheIntrudersAndTheBedsCentreOfMass) {
  Frame f = bed();
  auto& v = f.add("velocity").as<Coordinates>();
  v.setZero();
  v(0, 2) = 1.0;   // small, radius 0.5
  v(1, 2) = -2.0;  // intruder
  v(2, 2) = 3.0;   // small, radius 0.5
  const intruder::BedState s = intruder::measure_bed(f, "test");
  EXPECT_DOUBLE_EQ(s.intruder_velocity, -2.0);
  EXPECT_DOUBLE_EQ(s.bed_velocity, 2.0);
  EXPECT_EQ(s.base_contacts, 1);
  EXPECT_EQ(s.stage, intruder::Stage::Compression);
}

// A bed of radius 1e-5 beside an intruder of radius 1: the bed's mean taken as the sum over
// all less the intruder's term cancelled to a velocity of 0 (and a height off by 2e-3).
TEST(Intruder, ATinyBedBesideAHeavyIntruderKeepsItsMeans) {
  Frame f = bed();
  f.radius() << 1e-5, 1.0, 1e-5;
  f.position()(0, 2) = 0.25 + 1e-5;
  f.position()(2, 2) = 0.25 + 3e-5;
  auto& v = f.add("velocity").as<Coordinates>();
  v.setZero();
  v(0, 2) = 2e-5;
  v(1, 2) = 3.0;
  v(2, 2) = 4e-5;
  const intruder::BedState s = intruder::measure_bed(f, "test");
  EXPECT_NEAR(s.bed_velocity, 3e-5, 1e-18);
  EXPECT_NEAR(s.bed_height, 2e-5, 1e-15);  // the positions known to an ulp of 0.25
}

TEST(Intruder, LiftOffAndImpactAreTheMidpointsOfTheFramesWhereTheBaseContactChanges) {
  const Property cycles{"cycles", Scope::Frame, ValueType::Real, 1, "1", "drive periods"};
  Frame lifted = bed();
  lifted.contact_j()[1] = 1;  // the base contact becomes a pair contact: nothing on the base
  std::vector<Frame> frames = {bed(), bed(), lifted, lifted, bed()};
  for (std::size_t k = 0; k < frames.size(); ++k) {
    frames[k].time = static_cast<double>(k);
    frames[k].set_observable(cycles, 0.1 * static_cast<double>(k));
  }
  const Results r = analyze(frames);
  const Table& t = r.tables().at("transitions");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.column("time")[0], 1.5);
  EXPECT_EQ(t.column("stage")[0], 0.0);  // lift-off
  EXPECT_DOUBLE_EQ(t.column("cycles")[1], 0.35);
  EXPECT_EQ(t.column("stage")[1], 1.0);  // impact
  EXPECT_EQ(r.tables().at("per_frame").column("stage")[2], 0.0);
  EXPECT_EQ(r.plots().at("heights").x, "cycles");  // the paper's height per cycle
}
