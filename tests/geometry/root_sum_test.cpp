// Sums of square roots compared exactly: ties that doubles get wrong (0.85 + 0.85 against 1.7,
// whose doubles sum to 1.7000000000000002), differences far below a double's resolution
// (√(n+1) + √(n−1) against 2√n, n = 10^12: 2.5·10^−19 apart), equal sums of different roots
// (√2 + √8 = √18), and bounds that always hold the value.
#include <polyplan/geometry/root_sum.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace polyplan {
namespace {

Rational number(const char* text) { return *parse_rational(text); }

RootSum roots(std::initializer_list<const char*> squares) {
  RootSum sum;
  for (const char* q : squares) sum.add(number(q));
  return sum;
}

TEST(RootSum, ATieDoublesBreakIsATie) {
  // A tether round the apex of a 3-4-5 triangle scaled by 0.17: 0.85 + 0.85 long.
  const RootSum tether = RootSum::polyline({{0, 0}, {number("0.51"), number("0.68")}, {number("1.02"), 0}});
  ASSERT_GT(std::hypot(0.51, 0.68) + std::hypot(0.51, 0.68), 1.7);  // what doubles say
  EXPECT_EQ(compare(tether, number("1.7")), 0);
  EXPECT_EQ(compare(tether, number("1.700000000000001")), -1);
  EXPECT_EQ(compare(tether, number("1.699999999999999")), 1);
  EXPECT_EQ(compare(tether, number("1.7") + Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000)), -1);
  EXPECT_EQ(compare(tether, Rational(-1)), 1);
}

TEST(RootSum, DifferencesBelowADoublesResolutionAreSeen) {
  const RootSum apart = roots({"1000000000001", "999999999999"}), middle = roots({"4000000000000"});
  EXPECT_EQ(compare(apart, middle), -1);  // concave: the two roots sum below twice the middle one
  EXPECT_EQ(compare(middle, apart), 1);
  EXPECT_EQ(compare(apart, apart), 0);
}

TEST(RootSum, EqualSumsOfDifferentRootsAreEqual) {
  EXPECT_EQ(compare(roots({"2", "8"}), roots({"18"})), 0);
  EXPECT_EQ(compare(roots({"2", "8"}), roots({"18", "1/1000000000000000000000000000000"})), -1);
  EXPECT_EQ(compare(roots({"1/4", "9/4"}), Rational(2)), 0);  // rational roots
  EXPECT_EQ(compare(RootSum{}, Rational(0)), 0);
}

TEST(RootSum, BoundsHoldTheValue) {
  const RootSum sum = roots({"2", "3", "1/3", "1e-40", "1e40"});
  const double value = std::sqrt(2.0) + std::sqrt(3.0) + std::sqrt(1.0 / 3) + 1e-20 + 1e20;
  EXPECT_LE(sum.bounds().lower, value);
  EXPECT_GE(sum.bounds().upper, value);
  EXPECT_LT(sum.bounds().upper - sum.bounds().lower, 1e20 * 1e-14);
  // The bounds of one root hold it, checked exactly, and are adjacent doubles.
  const LengthBounds two = root_bounds(2);
  EXPECT_LE(Rational(two.lower) * Rational(two.lower), 2);
  EXPECT_GE(Rational(two.upper) * Rational(two.upper), 2);
  EXPECT_EQ(std::nextafter(two.lower, 2.0), two.upper);
  EXPECT_EQ(root_bounds(4).lower, 2);
  EXPECT_EQ(root_bounds(4).upper, 2);
}

// Bounds from the doubles nearest the coordinates hold the exact distance: points with decimal
// coordinates far from the origin and close together, where the rounding of the coordinates
// dominates.
TEST(RootSum, BoundsFromRoundedCoordinatesHoldTheExactDistance) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<long> digits(-999999999, 999999999);
  for (int i = 0; i < 20000; ++i) {
    const int scale = i % 3 == 0 ? 1 : (i % 3 == 1 ? 1000 : 1000000000);
    const Rational offset(digits(random), 1000);  // far from the origin: 1e6 or so
    const ExactPoint a{offset + Rational(digits(random), scale * 1000L), Rational(digits(random), scale)};
    const ExactPoint b{a.x + Rational(digits(random) % 1000, scale * 1000L),
                       a.y + Rational(digits(random) % 1000, scale)};
    const LengthBounds bounds = distance_bounds(to_double(a.x), to_double(a.y), to_double(b.x), to_double(b.y));
    const Rational square = squared_distance(a, b);
    ASSERT_LE(Rational(bounds.lower) * Rational(bounds.lower), square) << i;
    ASSERT_GE(Rational(bounds.upper) * Rational(bounds.upper), square) << i;
  }
}

}  // namespace
}  // namespace polyplan
