// arm/arm.cpp: forward kinematics and link outlines, worked out by hand.
#include <polyplan/arm/arm.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace polyplan;
using polyplan::test::arm_of;
using polyplan::test::kPi;

TEST(Kinematics, TwoLinksByHand) {
  // Link 1 (length 2) straight up, link 2 (length 1) turned back by −π/2: pointing along +x.
  const auto p = joint_positions(arm_of({2, 1}), {kPi / 2, -kPi / 2});
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], Eigen::Vector2d(0, 0));
  EXPECT_NEAR(p[1].x(), 0, 1e-15);
  EXPECT_NEAR(p[1].y(), 2, 1e-15);
  EXPECT_NEAR(p[2].x(), 1, 1e-15);
  EXPECT_NEAR(p[2].y(), 2, 1e-15);
}

TEST(Kinematics, ThreeLinksByHand) {
  // Headings 0, π/2, π: (0,0) → (1,0) → (1,2) → (−2,2).
  const auto p = joint_positions(arm_of({1, 2, 3}), {0, kPi / 2, kPi / 2});
  ASSERT_EQ(p.size(), 4u);
  const std::vector<Eigen::Vector2d> expected{{0, 0}, {1, 0}, {1, 2}, {-2, 2}};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT((p[i] - expected[i]).norm(), 1e-14) << i;
  // The same configuration written with angles off by whole turns.
  const auto q = joint_positions(arm_of({1, 2, 3}), {two_pi, kPi / 2 - two_pi, kPi / 2 + 2 * two_pi});
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT((q[i] - expected[i]).norm(), 1e-13) << i;
}

TEST(Kinematics, LinkLengthsArePreservedAndBadInputThrows) {
  const Arm arm = arm_of({0.5, 1.5, 2.5, 3.5}, 0.2);
  EXPECT_DOUBLE_EQ(arm.reach(), 8.1);
  const auto p = joint_positions(arm, {0.3, -2.0, 4.0, 1.0});
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR((p[k + 1] - p[k]).norm(), arm.links[k], 1e-14);
  EXPECT_THROW(joint_positions(arm, {0.3, 0.1}), std::invalid_argument);
  EXPECT_THROW(joint_positions(arm, {0.3, 0.1, std::nan(""), 0}), std::invalid_argument);
  EXPECT_THROW(link_outline(arm, p, 4), std::invalid_argument);
}

TEST(Kinematics, LinkOutlineIsTheSegmentOrTheRectangleCounterClockwise) {
  const auto joints = joint_positions(arm_of({2}), {0});
  const auto segment = link_outline(arm_of({2}), joints, 0);
  ASSERT_EQ(segment.size(), 2u);
  EXPECT_EQ(segment[1], Eigen::Vector2d(2, 0));
  const auto rectangle = link_outline(arm_of({2}, 0.5), joints, 0);
  ASSERT_EQ(rectangle.size(), 4u);
  const std::vector<Eigen::Vector2d> expected{{0, -0.25}, {2, -0.25}, {2, 0.25}, {0, 0.25}};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(rectangle[i], expected[i]) << i;
  // Counter-clockwise and of area w·l for a slanted link too (shoelace).
  const Arm slanted = arm_of({3}, 0.4);
  const auto c = link_outline(slanted, joint_positions(slanted, {2.0}), 0);
  double area2 = 0;
  for (std::size_t i = 0; i < 4; ++i) area2 += c[i].x() * c[(i + 1) % 4].y() - c[(i + 1) % 4].x() * c[i].y();
  EXPECT_NEAR(area2 / 2, 1.2, 1e-14);
}
