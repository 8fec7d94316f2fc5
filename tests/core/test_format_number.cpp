// Numbers, points and quoted text in messages: %g with the digits asked for.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "granpipe/format_number.hpp"
#include "granpipe/text_words.hpp"

using namespace granpipe;

TEST(FormatNumber, IsPercentGWithTheDigitsAskedFor) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(1e-9), "1e-09");
  EXPECT_EQ(format_number(12345.678), "12345.7");
  EXPECT_EQ(format_number(12345.678, 15), "12345.678");
  EXPECT_EQ(format_number(0.1, 17), "0.10000000000000001");
  EXPECT_EQ(format_number(std::nan("")), "nan");
  EXPECT_EQ(format_number(-INFINITY), "-inf");
}

TEST(FormatPoint, WritesEveryCoordinateAsFormatNumberDoes) {
  EXPECT_EQ(format_point(Eigen::Vector3d(0.1, -2.0, 1e-9)), "(0.1, -2, 1e-09)");
  EXPECT_EQ(format_point(Eigen::Vector3d(1.0 / 3.0, 0.0, 0.0).head(2), 4), "(0.3333, 0)");
  Eigen::ArrayXXd rows(2, 3);
  rows << 1, 2, 3, 4.5, std::nan(""), INFINITY;
  EXPECT_EQ(format_point(rows.row(1)), "(4.5, nan, inf)");
  EXPECT_EQ(format_point(std::vector<double>{}), "()");
}

// UTF-8 text is quoted as it is (a unit "µm" read "??m"); a binary file's bytes are not.
TEST(Quoted, KeepsUtf8AndHidesOtherBytes) {
  EXPECT_EQ(granpipe::quoted("\u00b5m"), "\"\u00b5m\"");
  EXPECT_EQ(granpipe::quoted("\u00c5 and \u03bcm"), "\"\u00c5 and \u03bcm\"");
  EXPECT_EQ(granpipe::quoted(std::string("a\xff\x01z")), "\"a??z\"");
  EXPECT_EQ(granpipe::quoted(std::string("\xc3")), "\"?\"");  // a character cut short
  // A C1 control (CSI, which terminals obey), an overlong form and a surrogate are not text.
  EXPECT_EQ(granpipe::quoted(std::string("\xc2\x9b")), "\"??\"");
  EXPECT_EQ(granpipe::quoted(std::string("\xe0\x80\xaf")), "\"???\"");
  EXPECT_EQ(granpipe::quoted(std::string("\xed\xa0\x80")), "\"???\"");
  // Bidirectional controls reorder the terminal's line (a unit "nm\u202e..."): one '?' each.
  EXPECT_EQ(granpipe::quoted("nm\u202eabc"), "\"nm?abc\"");
  // Characters of no width: a byte-order mark before a dump's first line read "expected
  // ITEM: TIMESTEP, got ITEM: TIMESTEP".
  EXPECT_EQ(granpipe::quoted("\ufeffITEM: TIMESTEP"), "\"?ITEM: TIMESTEP\"");
  EXPECT_EQ(granpipe::quoted("a\u200bb\u2060c"), "\"a?b?c\"");
  EXPECT_EQ(granpipe::quoted("\u2010"), "\"\u2010\"");  // a hyphen is shown
  EXPECT_EQ(granpipe::quoted("\u2066x\u2069\u200f\u061c"), "\"?x???\"");
  EXPECT_EQ(granpipe::quoted("a\u2014b"), "\"a\u2014b\"");  // an em dash is text
}
