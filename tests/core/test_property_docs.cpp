// The file-format page lists every standard column: the table in core/src/property.cpp
// and the users' documentation cannot drift apart.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "granpipe/property.hpp"

using namespace granpipe;

TEST(PropertyDocs, FileFormatPageListsEveryStandardColumnWithItsTypeAndUnit) {
  std::ifstream in(std::string(GRANPIPE_SOURCE_DIR) + "/docs/file-format.md");
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  for (const Property& p : standard_properties()) {
    std::ostringstream row;
    row << "| " << to_string(p.scope) << " | `" << p.name << "` | "
        << (p.type == ValueType::Real      ? "real"
            : p.type == ValueType::Integer ? "integer"
                                           : "small");
    if (p.components == kDimComponents) row << "[dim]";
    if (p.components == kSpinComponents) row << "[spin]";
    if (p.components > 1) row << "[" << p.components << "]";
    row << " |" << (p.unit.empty() ? "" : " " + p.unit) << " |";
    EXPECT_NE(text.str().find(row.str()), std::string::npos) << "missing row: " << row.str();
  }
}

TEST(PropertyDocs, StandardNamesAreValidColumnNamesAndUnique) {
  const auto all = standard_properties();
  for (std::size_t a = 0; a < all.size(); ++a) {
    EXPECT_TRUE(is_valid_column_name(all[a].name)) << all[a].name;
    for (std::size_t b = a + 1; b < all.size(); ++b) {
      EXPECT_FALSE(all[a].name == all[b].name && all[a].scope == all[b].scope) << all[a].name;
    }
  }
}
