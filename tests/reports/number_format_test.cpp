#include "reports/number_format.h"

#include <gtest/gtest.h>

#include <limits>

namespace gib::reports {
namespace {

TEST(NumberFormat, PlainDecimalsWithSignificantDigitsAndNoTrailingZeros) {
  EXPECT_EQ(formatNumber(0.0123456), "0.01235");
  EXPECT_EQ(formatNumber(197.3), "197.3");
  EXPECT_EQ(formatNumber(0.5), "0.5");
  EXPECT_EQ(formatNumber(12345.6), "12346");
  EXPECT_EQ(formatNumber(9.99996), "10");
  EXPECT_EQ(formatNumber(-0.25), "-0.25");
  EXPECT_EQ(formatNumber(0), "0");
  EXPECT_EQ(formatNumber(-1e-20, 1), "-1e-20");
}

TEST(NumberFormat, ScientificOutsideTheEverydayRange) {
  EXPECT_EQ(formatNumber(1.23e-5), "1.23e-5");
  EXPECT_EQ(formatNumber(2.5e7), "2.5e7");
  EXPECT_EQ(formatNumber(1e6), "1e6");
}

TEST(NumberFormat, NonFiniteValuesAreNamed) {
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::quiet_NaN()), "NaN");
  EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(NumberFormat, ChangesSharesAndMinusSigns) {
  EXPECT_EQ(formatChange(0.125), "+12.5%");
  EXPECT_EQ(formatChange(-0.03), "-3.0%");
  EXPECT_EQ(formatShare(0.25), "25.0%");
  EXPECT_EQ(withMinusSign("-0.98"), "\u22120.98");
  EXPECT_EQ(withMinusSign("0.98"), "0.98");
}

TEST(NumberFormat, DurationsInMillisecondsOrMicrosecondsWhicheverReadsBetter) {
  EXPECT_EQ(formatMilliseconds(436), "436 ms");
  EXPECT_EQ(formatMilliseconds(1.0), "1 ms");
  EXPECT_EQ(formatMilliseconds(0.052), "52 \u00b5s");
  EXPECT_EQ(formatMilliseconds(0), "0 ms");
  EXPECT_EQ(formatMilliseconds(std::numeric_limits<double>::quiet_NaN()), "NaN");
  EXPECT_STREQ(timeUnitFor(0.99).symbol, "\u00b5s");
  EXPECT_EQ(timeUnitFor(0.99).per_ms, 1000.0);
  EXPECT_STREQ(timeUnitFor(20).symbol, "ms");
}

}  // namespace
}  // namespace gib::reports
