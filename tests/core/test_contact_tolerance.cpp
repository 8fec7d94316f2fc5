// The plugins that find contacts by distance declare their tolerance alike, so that the
// pages quoting it (docs/arches.md, docs/mst.md) stay true for each.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "granpipe/contacts_by_distance.hpp"
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
