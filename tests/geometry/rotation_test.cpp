// Exact rotations: sin² + cos² = 1 exactly, within the stated tolerance of the angle asked for.
#include <polyplan/geometry/rotation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

// The angle between two angles in radians, the short way.
double apart(double a_degrees, double b_degrees) {
  const double d = std::remainder(a_degrees - b_degrees, 360.0);
  return std::abs(d) * pi / 180;
}

TEST(ExactRotation, IsOnTheUnitCircleAndWithinTheToleranceForEveryAngleTried) {
  for (double degrees = -720; degrees <= 720; degrees += 0.37) {
    const Rotation r = exact_rotation(degrees);
    EXPECT_EQ(r.sin * r.sin + r.cos * r.cos, 1) << degrees;
    EXPECT_LE(apart(degrees_of(r), degrees), rotation_tolerance_radians) << degrees;
  }
}

TEST(ExactRotation, QuarterTurnsAreExact) {
  EXPECT_EQ(exact_rotation(0), (Rotation{0, 1}));
  EXPECT_EQ(exact_rotation(90), (Rotation{1, 0}));
  EXPECT_EQ(exact_rotation(-180), (Rotation{0, -1}));
  EXPECT_EQ(exact_rotation(630), (Rotation{-1, 0}));
}

TEST(ExactRotation, SmallAnglesAreNotRoundedToZero) {
  const Rotation r = exact_rotation(0.001);
  EXPECT_NE(r.sin, 0);
  EXPECT_LE(apart(degrees_of(r), 0.001), rotation_tolerance_radians);
}

TEST(ExactRotation, AnglesNearAQuarterTurnHaveSmallNumbers) {
  // Continued fractions reach the tolerance in a few dozen terms: small denominators, at once
  // (CGAL's one-mediant-at-a-time walk took seconds for 359.99999°).
  for (double degrees : {1e-9, 1e-6, 1e-3, 359.99999, 89.9999999, -0.0000123, 45.0, 1e6 + 0.3}) {
    const Rotation r = exact_rotation(degrees);
    EXPECT_EQ(r.sin * r.sin + r.cos * r.cos, 1) << degrees;
    EXPECT_LE(apart(degrees_of(r), degrees), rotation_tolerance_radians) << degrees;
    EXPECT_LE(mpz_sizeinbase(r.cos.get_den_mpz_t(), 10), 25u) << degrees;
  }
}

TEST(ExactRotation, RefusesAnAngleThatIsNotANumber) {
  EXPECT_THROW(exact_rotation(std::nan("")), std::invalid_argument);
  EXPECT_THROW(exact_rotation(INFINITY), std::invalid_argument);
}

TEST(ExactRotation, RotatesPointsKeepingTheirDistanceExactly) {
  const Rotation r = exact_rotation(60);
  const ExactPoint p{Rational(3), Rational(-7, 2)};
  const ExactPoint q = rotate(p, r);
  EXPECT_EQ(q.x * q.x + q.y * q.y, p.x * p.x + p.y * p.y);
  EXPECT_NEAR(to_double(q.x), 3 * std::cos(pi / 3) + 3.5 * std::sin(pi / 3), 1e-9);
}

TEST(TurnDegrees, IsTheShortWayBetweenTwoRotations) {
  EXPECT_NEAR(turn_degrees(exact_rotation(10), exact_rotation(350)), -20, 1e-8);
  EXPECT_NEAR(turn_degrees(exact_rotation(350), exact_rotation(10)), 20, 1e-8);
  EXPECT_NEAR(turn_degrees(exact_rotation(0), exact_rotation(135)), 135, 1e-8);
  EXPECT_EQ(turn_degrees(exact_rotation(33), exact_rotation(33)), 0);
}

TEST(Pose, NamesItselfWithItsAngle) {
  EXPECT_EQ(to_string(Pose{{Rational(3, 2), Rational(7)}, exact_rotation(60), 60}), "[3/2, 7, 60°]");
}

}  // namespace
}  // namespace polyplan
