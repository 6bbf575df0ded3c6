// Inverse kinematics: the two-link arm's 2, 1 or 0 solutions strictly inside, exactly on and just
// outside its annulus (boundaries a double's last bit away decided right), three links with an end
// orientation, n links by damped least squares (and FABRIK), joint limits kept, and an unreachable
// target answered with the arm stretched towards it. Every solution's error is measured here by
// forward kinematics.
#include "arm/arm_fixtures.hpp"

#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/inverse_kinematics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace polyplan {
namespace {

using test::arm_of;

double error_of(const Arm& arm, const JointAngles& q, Eigen::Vector2d target) {
  return (joint_positions(arm, q).back() - target).norm();
}

TEST(InverseKinematics, TwoLinksInsideTheAnnulusHaveBothElbows) {
  const Arm arm = arm_of({1, 0.5});
  const Eigen::Vector2d target(0.9, 0.7);
  const IkAnswer answer = two_link_ik(arm, target);
  ASSERT_TRUE(answer.found);
  ASSERT_EQ(answer.solutions.size(), 2u);
  for (const IkSolution& s : answer.solutions) {
    EXPECT_LT(error_of(arm, s.angles, target), 1e-14);
    EXPECT_NEAR(s.error, error_of(arm, s.angles, target), 1e-18);
  }
  EXPECT_LT(answer.solutions[0].angles[1] * answer.solutions[1].angles[1], 0);  // elbow up, elbow down
}

// l1 = 0.75, l2 = 0.5: the annulus is 0.25 ≤ d ≤ 1.25, and (0.75, 1) lies at exactly 1.25.
TEST(InverseKinematics, TwoLinksOnTheAnnulusHaveOneSolutionAndBeyondItNone) {
  const Arm arm = arm_of({0.75, 0.5});
  const IkAnswer outer = two_link_ik(arm, {0.75, 1});
  ASSERT_TRUE(outer.found);
  ASSERT_EQ(outer.solutions.size(), 1u);
  EXPECT_EQ(outer.solutions[0].angles[1], 0);
  EXPECT_LT(outer.solutions[0].error, 1e-14);
  const IkAnswer inner = two_link_ik(arm, {0, 0.25});
  ASSERT_TRUE(inner.found);
  ASSERT_EQ(inner.solutions.size(), 1u);
  EXPECT_NEAR(std::abs(inner.solutions[0].angles[1]), M_PI, 1e-15);
  // One ulp beyond 1.25 is outside; one ulp inside has two solutions.
  const double beyond = std::nextafter(1.25, 2.0), within = std::nextafter(1.25, 0.0);
  const IkAnswer out = two_link_ik(arm, {beyond, 0});
  EXPECT_FALSE(out.found);
  ASSERT_EQ(out.solutions.size(), 1u);  // the arm stretched towards it
  EXPECT_EQ(out.solutions[0].angles, (JointAngles{0, 0}));
  EXPECT_NE(out.why_not.find("farther"), std::string::npos);
  EXPECT_EQ(two_link_ik(arm, {within, 0}).solutions.size(), 2u);
  EXPECT_FALSE(two_link_ik(arm, {0.1, 0}).found);  // inside the hole of radius 0.25
  // 1.25² + 2⁻⁶⁰ is 1.25² in doubles, which would call (1.25, 2⁻³⁰) on the boundary: it is outside.
  const Eigen::Vector2d grazing(1.25, std::ldexp(1.0, -30));
  ASSERT_EQ(grazing.squaredNorm(), 1.5625);
  EXPECT_FALSE(two_link_ik(arm, grazing).found);
}

// Lengths 0.2 and 0.3 and the target (0.3, 0.4) as written: |target| = 1/2 = l1 + l2 exactly, one
// solution; their doubles put the target beyond the doubles' sum. (0.06, 0.08) lies exactly on the
// inner circle, 1/10 = l2 − l1. Arm files and `polyplan ik --target` keep the values as written.
TEST(InverseKinematics, DecimalLengthsAndTargetsAreDecidedOnTheValuesWritten) {
  Arm arm = arm_of({0.2, 0.3});
  EXPECT_FALSE(two_link_ik(arm, {0.3, 0.4}).found) << "the doubles alone";
  arm.exact_links = {Rational(1, 5), Rational(3, 10)};
  const IkAnswer outer = two_link_ik(arm, {0.3, 0.4}, ExactPoint{Rational(3, 10), Rational(2, 5)});
  ASSERT_TRUE(outer.found) << outer.why_not;
  ASSERT_EQ(outer.solutions.size(), 1u);
  EXPECT_EQ(outer.solutions[0].angles[1], 0);
  EXPECT_LT(outer.solutions[0].error, 1e-15);
  IkOptions options;
  options.exact_target = ExactPoint{Rational(3, 50), Rational(2, 25)};
  const IkAnswer inner = inverse_kinematics(arm, {0.06, 0.08}, options);
  ASSERT_TRUE(inner.found) << inner.why_not;
  ASSERT_EQ(inner.solutions.size(), 1u);
  EXPECT_NEAR(std::abs(inner.solutions[0].angles[1]), M_PI, 1e-15);
  EXPECT_LT(inner.solutions[0].error, 1e-15);
}

TEST(InverseKinematics, ThreeLinksReachAPointWithAnOrientation) {
  const Arm arm = arm_of({1, 0.8, 0.3});
  for (const double orientation : {0.0, 1.0, -2.5}) {
    const Eigen::Vector2d target(0.6, 1.1);
    const IkAnswer answer = three_link_ik(arm, target, orientation);
    ASSERT_TRUE(answer.found) << answer.why_not;
    for (const IkSolution& s : answer.solutions) {
      EXPECT_LT(error_of(arm, s.angles, target), 1e-14);
      EXPECT_NEAR(std::remainder(end_orientation(s.angles) - orientation, 2 * M_PI), 0, 1e-14);
    }
  }
}

TEST(InverseKinematics, NumericReachesRandomTargetsOfSixLinksWithinLimits) {
  const Arm arm = arm_of({1, 0.9, 0.8, 0.7, 0.6, 0.5});
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int k = 0; k < 50; ++k) {
    JointAngles q(6);
    for (double& a : q) a = angle(random);
    const Eigen::Vector2d target = joint_positions(arm, q).back();  // reachable by construction
    const IkAnswer answer = numeric_ik(arm, target);
    ASSERT_TRUE(answer.found) << answer.why_not;
    EXPECT_LE(error_of(arm, answer.solutions[0].angles, target), 1e-9);
    IkOptions oriented;
    oriented.orientation = end_orientation(q);
    const IkAnswer with = numeric_ik(arm, target, oriented);
    ASSERT_TRUE(with.found) << with.why_not;
    EXPECT_LE(error_of(arm, with.solutions[0].angles, target), 1e-9);
    EXPECT_NEAR(std::remainder(end_orientation(with.solutions[0].angles) - *oriented.orientation, 2 * M_PI), 0, 1e-9);
  }
  IkOptions limited, all;
  limited.limits.assign(6, {-1.0, 1.0});
  const IkAnswer kept = numeric_ik(arm, {2.5, 2.0}, limited);
  ASSERT_TRUE(kept.found) << kept.why_not;
  for (const double a : kept.solutions[0].angles) EXPECT_LE(std::abs(a), 1.0);
  all.all = true;
  const IkAnswer several = numeric_ik(arm, {1.5, 1.0}, all);
  EXPECT_GE(several.solutions.size(), 2u);  // distinct by more than 1e-6
}

TEST(InverseKinematics, AnUnreachableTargetStretchesTheArmTowardsIt) {
  const Arm arm = arm_of({1, 1, 1});
  const Eigen::Vector2d target(3, 4);  // 5 away, the arm reaches 3
  const IkAnswer answer = numeric_ik(arm, target);
  EXPECT_FALSE(answer.found);
  ASSERT_EQ(answer.solutions.size(), 1u);
  EXPECT_NEAR(answer.solutions[0].error, 2, 1e-9);
  const IkSolution pulled = fabrik(arm, target, {0.3, 0.3, 0.3});
  EXPECT_NEAR(pulled.angles[0], std::atan2(4.0, 3.0), 1e-12);
  EXPECT_NEAR(pulled.angles[1], 0, 1e-12);
  EXPECT_NEAR(pulled.angles[2], 0, 1e-12);
  EXPECT_NEAR(pulled.error, 2, 1e-12);
  // Within reach FABRIK gets there, the links' lengths kept (the joints' positions from its angles).
  const IkSolution reached = fabrik(arm, {1.2, 1.9}, {0.3, 0.3, 0.3});
  EXPECT_LE(reached.error, 1e-9);
}

}  // namespace
}  // namespace polyplan
