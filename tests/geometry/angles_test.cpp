// geometry/angles.hpp: normalisation, the short way between two angles, interpolation. Expected values
// are worked out by hand in the comments or re-computed with the course's arm and car planning report's own formula.
#include <polyplan/geometry/angles.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace polyplan;
using polyplan::test::down;
using polyplan::test::kPi;

namespace {

// the course's arm and car planning report's angular_distance, written as the seed wrote it: an independent re-check.
double seed_angular_distance(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), two_pi);
  return std::min(d, two_pi - d);
}

}  // namespace

TEST(Angles, NormalizeIntoZeroToTwoPi) {
  EXPECT_EQ(normalize_angle(-0.1), two_pi - 0.1);
  EXPECT_EQ(normalize_angle(two_pi), 0.0);
  EXPECT_EQ(normalize_angle(7), 7 - two_pi);  // fmod is exact and 7 − 2π is a double
  EXPECT_EQ(normalize_angle(3 * two_pi + 1), std::fmod(3 * two_pi + 1, two_pi));
  EXPECT_EQ(normalize_angle(-two_pi), 0.0);
  EXPECT_FALSE(std::signbit(normalize_angle(-0.0)));
  // −1e−300 + 2π rounds to 2π, which is outside the half-open interval: it becomes 0.
  EXPECT_EQ(normalize_angle(-1e-300), 0.0);
  EXPECT_LT(normalize_angle(down(0.0)), two_pi);
  EXPECT_THROW(normalize_angle(std::nan("")), std::invalid_argument);
  EXPECT_THROW(normalize_angle(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(Angles, SignedDifferenceTakesTheShortWay) {
  EXPECT_EQ(signed_angle_difference(1, 5), 4 - two_pi);  // backwards through 0: −2.2831853071795862
  EXPECT_EQ(signed_angle_difference(5, 1), two_pi - 4);
  EXPECT_EQ(signed_angle_difference(0, kPi), kPi);  // a half turn is +π either way round
  EXPECT_EQ(signed_angle_difference(kPi, 0), kPi);
  EXPECT_EQ(signed_angle_difference(-kPi, kPi), 0.0);  // the same angle
  EXPECT_NEAR(signed_angle_difference(0.1, two_pi - 0.1), -0.2, 1e-15);
  EXPECT_NEAR(signed_angle_difference(two_pi - 0.1, 0.1), 0.2, 1e-15);
  EXPECT_EQ(signed_angle_difference(1e300, 1e300), 0.0);  // no overflow for huge angles
  EXPECT_THROW(signed_angle_difference(0, std::nan("")), std::invalid_argument);
}

TEST(Angles, SeedFiguresForAngularDistance) {
  // the course's arm and car planning report prints angular_distance(1, 5) = 2.2831853071795862.
  EXPECT_EQ(angular_distance(1, 5), 2.2831853071795862);
  EXPECT_EQ(angular_distance(5, 1), 2.2831853071795862);
  // the course's graph-search homework's torus heuristic: between 2π − 0.1 and 0.1 the distance is 0.2.
  EXPECT_NEAR(angular_distance(two_pi - 0.1, 0.1), 0.2, 1e-15);
  EXPECT_EQ(angular_distance(0, kPi), kPi);
  // 0.2 + 0 + 0.2 + (0.4 − 6.2 + 2π) = 0.8831853071795865.
  const JointAngles a{0.1, 0.2, 0.3, 0.4}, b{0.3, 0.2, 0.1, 6.2};
  EXPECT_NEAR(total_angular_distance(a, b), 0.8831853071795865, 1e-14);
  double seed_sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) seed_sum += seed_angular_distance(a[i], b[i]);
  EXPECT_NEAR(total_angular_distance(a, b), seed_sum, 1e-14);
  EXPECT_THROW(total_angular_distance(a, {0.1}), std::invalid_argument);
}

TEST(Angles, DistanceAgreesWithTheSeedFormulaEverywhere) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> any(-20, 20);
  for (int i = 0; i < 10000; ++i) {
    const double a = any(rng), b = any(rng);
    const double d = angular_distance(a, b);
    ASSERT_GE(d, 0.0);
    ASSERT_LE(d, kPi);
    ASSERT_NEAR(d, seed_angular_distance(a, b), 1e-12) << a << " " << b;
    // Going the signed difference from a lands on b.
    ASSERT_NEAR(angular_distance(a + signed_angle_difference(a, b), b), 0.0, 1e-12);
  }
}

TEST(Angles, InterpolationGoesTheShortWay) {
  const JointAngles a{0.1, 1.0}, b{two_pi - 0.1, 2.0};
  EXPECT_EQ(interpolate_angles(a, b, 0), (JointAngles{0.1, 1.0}));
  EXPECT_EQ(interpolate_angles({7.0}, {1.0}, 0), JointAngles{normalize_angle(7.0)});
  const JointAngles end = interpolate_angles(a, b, 1);
  EXPECT_NEAR(angular_distance(end[0], b[0]), 0, 1e-15);
  EXPECT_NEAR(end[1], 2.0, 1e-15);
  // Joint 0 passes through 0, never through π: every intermediate angle is within 0.1 of 0.
  for (int k = 0; k <= 100; ++k) {
    const JointAngles mid = interpolate_angles(a, b, k / 100.0);
    ASSERT_LE(angular_distance(mid[0], 0), 0.1 + 1e-15) << k;
    ASSERT_GE(mid[0], 0.0);
    ASSERT_LT(mid[0], two_pi);
    ASSERT_NEAR(mid[1], 1.0 + k / 100.0, 1e-15);
  }
  EXPECT_NEAR(angular_distance(interpolate_angles(a, b, 0.5)[0], 0), 0, 1e-15);
  EXPECT_NEAR(interpolate_angles(a, b, 0.25)[0], 0.05, 1e-15);
  EXPECT_THROW(interpolate_angles(a, {0.0}, 0.5), std::invalid_argument);
}
