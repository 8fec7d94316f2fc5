// The loaded pair contacts of a frame and the frame choice made on them: one rule for mst
// and force_network, with bad rows refused and frames without contacts counting none.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "granpipe/loaded_pair_contacts.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

namespace {

// Four particles; rows: 0-1 loaded, 1-2 zero force, 2-wall loaded, 2-3 loaded.
Frame frame_with_forces() {
  Frame f;
  f.resize(4, 3);
  f.add_contacts(4);
  f.contact_i() << 0, 1, 2, 2;
  f.contact_j() << 1, 2, partner::wall(Wall::ZLow), 3;
  ValueTable<double>& force =
      f.contacts->add<ValueTable<double>>(*find_standard("normal_force", Scope::Contact));
  force << 0, 0, 1,  //
      0, 0, 0,       //
      0, 0, 2,       //
      0, -3, 0;
  return f;
}

std::string error_of(const Frame& f) {
  return test::input_error_of([&] { loaded_pair_contacts(f, "frame 7"); });
}

}  // namespace

TEST(LoadedPairContacts, AreTheParticlePairsWithANonZeroNormalForce) {
  EXPECT_EQ(loaded_pair_contacts(frame_with_forces(), "t"), (std::vector<Eigen::Index>{0, 3}));
}

TEST(LoadedPairContacts, WithoutANormalForceColumnEveryPairRowCounts) {
  Frame f = frame_with_forces();
  f.contacts->remove("normal_force");
  EXPECT_EQ(loaded_pair_contacts(f, "t"), (std::vector<Eigen::Index>{0, 1, 3}));
}

TEST(LoadedPairContacts, AFrameWithoutContactsHasNone) {
  Frame f = frame_with_forces();
  f.contacts.reset();
  EXPECT_TRUE(loaded_pair_contacts(f, "t").empty());
  f.add_contacts(0);
  EXPECT_TRUE(loaded_pair_contacts(f, "t").empty());
}

TEST(LoadedPairContacts, ANaNForceIsRefusedNamingItsRow) {
  Frame f = frame_with_forces();
  f.contacts->get<ValueTable<double>>("normal_force")(1, 1) = std::nan("");
  EXPECT_EQ(error_of(f),
            "frame 7: contact 1: expected a finite normal_force, got nan in component y");
}

TEST(LoadedPairContacts, AnInfiniteForceOnAWallRowIsRefusedToo) {
  Frame f = frame_with_forces();
  f.contacts->get<ValueTable<double>>("normal_force")(2, 2) = INFINITY;
  EXPECT_EQ(error_of(f),
            "frame 7: contact 2: expected a finite normal_force, got inf in component z");
}

TEST(LoadedPairContacts, ARowJoiningAParticleToItselfIsRefused) {
  Frame f = frame_with_forces();
  f.contact_j()[3] = 2;
  EXPECT_EQ(error_of(f),
            "frame 7: contact 3: expected two different particles, got particle 2 twice");
  f.contacts->remove("normal_force");
  EXPECT_EQ(error_of(f),
            "frame 7: contact 3: expected two different particles, got particle 2 twice");
}

TEST(MostLoadedFrame, KeepsTheFrameWithTheMostTheEarliestOfEquals) {
  MostLoadedFrame chosen;
  EXPECT_EQ(chosen.frame(), -1);
  EXPECT_TRUE(chosen.offer(0, 0));  // the first frame, even without loaded contacts
  EXPECT_TRUE(chosen.offer(1, 5));
  EXPECT_FALSE(chosen.offer(2, 5));
  EXPECT_FALSE(chosen.offer(3, 4));
  EXPECT_EQ(chosen.frame(), 1);
  EXPECT_EQ(chosen.loaded(), 5);
}
