// euclidean_length (geometry/polyline.cpp): each segment's exact differences rounded once, then
// hypot; the cases are ones whose answers are exact doubles, worked out by hand.
#include <polyplan/geometry/polyline.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polyplan;
using polyplan::test::pt;

TEST(EuclideanLength, ThreeFourFiveIsFive) {
  EXPECT_EQ(euclidean_length({pt("0", "0"), pt("3", "4")}), 5.0);
  EXPECT_EQ(euclidean_length({pt("3", "4"), pt("0", "0")}), 5.0);  // either direction
  EXPECT_EQ(euclidean_length({pt("-1", "-1"), pt("-4", "-5")}), 5.0);
}

TEST(EuclideanLength, SumsTheSegments) {
  // 5 + 6 + 13 (the 5-12-13 triangle).
  EXPECT_EQ(euclidean_length({pt("0", "0"), pt("3", "4"), pt("3", "10"), pt("8", "22")}), 24.0);
}

TEST(EuclideanLength, EmptyAndOnePointPathsHaveLengthZero) {
  EXPECT_EQ(euclidean_length({}), 0.0);
  EXPECT_EQ(euclidean_length({pt("7/3", "-2")}), 0.0);
}

TEST(EuclideanLength, RepeatedPointsAddNothing) {
  EXPECT_EQ(euclidean_length({pt("0", "0"), pt("0", "0"), pt("3", "4"), pt("3", "4")}), 5.0);
}

TEST(EuclideanLength, DecimalDifferencesAreExactBeforeRounding) {
  // 0.3 - 0.1 is exactly 1/5, whose double is 0.2; the doubles of 0.3 and 0.1 differ by
  // 0.19999999999999998.
  ASSERT_NE(0.3 - 0.1, 0.2);
  EXPECT_EQ(euclidean_length({pt("0.1", "7"), pt("0.3", "7")}), 0.2);
  // 3/10 and 4/10 across: hypot of the doubles nearest them.
  EXPECT_EQ(euclidean_length({pt("0.1", "0.2"), pt("0.4", "0.6")}), std::hypot(0.3, 0.4));
  EXPECT_NEAR(euclidean_length({pt("0.1", "0.2"), pt("0.4", "0.6")}), 0.5, 1e-16);
}

TEST(EuclideanLength, UnitStepFarFromTheOriginIsOne) {
  // In doubles both x coordinates are 1e20 and the step vanishes; exactly, it is 1.
  ASSERT_EQ(to_double(*parse_rational("100000000000000000001")), 1e20);
  EXPECT_EQ(euclidean_length({pt("100000000000000000001", "0"), pt("100000000000000000000", "0")}), 1.0);
}

TEST(EuclideanLength, IrrationalLengthIsTheNearestDouble) {
  EXPECT_EQ(euclidean_length({pt("0", "0"), pt("1", "1")}), std::sqrt(2.0));
  EXPECT_EQ(euclidean_length({pt("1/3", "0"), pt("1/3", "1")}), 1.0);
}
