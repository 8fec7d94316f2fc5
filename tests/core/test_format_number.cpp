// Numbers in messages: %g with the digits asked for.
#include <gtest/gtest.h>

#include <cmath>

#include "granpipe/format_number.hpp"

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
