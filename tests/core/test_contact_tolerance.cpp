// The plugins that find contacts by distance declare their tolerance alike, so that the
// pages quoting it (docs/arches.md, docs/mst.md) stay true for each.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

TEST(ContactTolerance, HasOneDefaultRangeAndText) {
  Schema s;
  declare_contact_tolerance(s);
  const ParamSpec& p = *s.find("contact_tolerance");
  EXPECT_EQ(std::get<double>(*p.default_value), 1e-9);
  EXPECT_EQ(p.min, 0.0);
  EXPECT_FALSE(p.min_exclusive);
  // 1e300 was refused by the neighbour search in its own terms, not as this parameter.
  EXPECT_EQ(p.max, 1.0);
  EXPECT_EQ(p.doc,
            "relative contact tolerance: two particles touch when their centre distance "
            "is at most (R_i + R_j)(1 + tol), a particle and a wall when the centre-wall "
            "distance is at most R_i (1 + tol)");
}

TEST(ContactTolerance, EveryPluginFindingContactsByDistanceDeclaresItAlike) {
  const std::string name = kContactToleranceName;
  for (const char* plugin : {"mst", "arches", "packing"}) {
    const PluginInfo* info = test::installed_plugins().find(plugin);
    if (!info) continue;  // left out of this build
    Schema expected;
    declare_contact_tolerance(expected);
    const ParamSpec* p = info->schema.find(name);
    ASSERT_NE(p, nullptr) << plugin;
    EXPECT_EQ(p->doc, expected.find(name)->doc) << plugin;
    EXPECT_EQ(std::get<double>(*p->default_value), kDefaultContactTolerance) << plugin;
    EXPECT_EQ(p->min, 0.0) << plugin;
    EXPECT_EQ(p->max, 1.0) << plugin;
  }
}

// An FCC lattice moved to 1e7 had z 9 for 12 (and at 1e8 no contact at all), without a
// word: its coordinates are rounded to 1.9e-9, coarser than the tolerance allows. Said; at
// the tolerance the message gives, every contact is found again.
TEST(ContactTolerance, PositionsRoundedCoarserThanItAreSaid) {
  Frame f;
  f.resize(3, 3);
  f.radius().setConstant(0.5);
  const double far = 1e7;
  f.position() << far, far, far, far + 1, far, far, far + 0.5, far + std::sqrt(0.75), far;
  f.container = Container::periodic_box(3, Eigen::Vector3d::Constant(far - 5),
                                        Eigen::Vector3d::Constant(far + 5));
  EXPECT_EQ(coarse_for_contacts(f, 1e-9),
            "positions up to 1e+07 from the origin are rounded to 1.86265e-09, more than half "
            "of contact_tolerance x the smallest contact distance (1e-09): touching particles "
            "may be missed; raise contact_tolerance to 7.45058e-09 or move the origin into the "
            "packing");
  EXPECT_EQ(coarse_for_contacts(f, 7.46e-9), "");
  EXPECT_EQ(find_contacts_by_distance(f, 7.46e-9).pairs, 3);
  f.position().array() -= far;  // near the origin the default tolerance is fine
  f.container =
      Container::periodic_box(3, Eigen::Vector3d::Constant(-5), Eigen::Vector3d::Constant(5));
  EXPECT_EQ(coarse_for_contacts(f, 1e-9), "");
}
