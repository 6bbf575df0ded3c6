// arm/arm_collision: the exact collision convention and the clearances (lower bounds of distances)
// that certified motions advance by. Expected values are worked out by hand in the comments, or
// re-computed independently (long double geometry with a safety margin).
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm.hpp>
#include <polyplan/io/arm_reader.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace polyplan;
using namespace polyplan::test;

TEST(Collision, PointOnASegmentLinkCollidesOneUlpBesideItDoesNot) {
  const Arm arm = arm_of({2});
  auto free_with_point = [&](double x, double y, double theta) {
    return ArmCollisionChecker(arm, {}, {Eigen::Vector2d(x, y)}).is_free({theta});
  };
  EXPECT_FALSE(free_with_point(1, 0, 0));
  EXPECT_TRUE(free_with_point(1, up(0.0), 0));
  EXPECT_FALSE(free_with_point(2, 0, 0));  // the tip is part of the closed link
  EXPECT_TRUE(free_with_point(up(2.0), 0, 0));
  EXPECT_FALSE(free_with_point(0, 0, 0));  // the base too
  // A slanted link: half of the computed tip is exactly on the computed segment (halving is
  // exact), one ulp above it is not. An epsilon test would call both collisions.
  const double theta = 0.7;
  const Eigen::Vector2d tip = joint_positions(arm, {theta})[1];
  EXPECT_FALSE(free_with_point(tip.x() / 2, tip.y() / 2, theta));
  EXPECT_TRUE(free_with_point(tip.x() / 2, up(tip.y() / 2), theta));
  EXPECT_TRUE(free_with_point(tip.x() / 2, down(tip.y() / 2), theta));
}

TEST(Collision, RectangleLinkCatchesPointsWithinHalfTheWidth) {
  const Arm arm = arm_of({2}, 0.5);
  auto free_with_point = [&](double x, double y) { return ArmCollisionChecker(arm, {}, {Eigen::Vector2d(x, y)}).is_free({0}); };
  EXPECT_FALSE(free_with_point(1, 0.24));
  EXPECT_FALSE(free_with_point(1, -0.24));
  EXPECT_FALSE(free_with_point(1, 0.25));  // on the long side: closed
  EXPECT_TRUE(free_with_point(1, up(0.25)));
  EXPECT_TRUE(free_with_point(1, 0.26));
  EXPECT_FALSE(free_with_point(2, 0.25));  // the corner
  EXPECT_TRUE(free_with_point(2.01, 0));   // no end caps: the rectangle ends at the joint
  EXPECT_TRUE(free_with_point(-0.01, 0));
}

TEST(Collision, RectangleAgreesWithIndependentDistancesOnTheTwoLinkData) {
  // For random configurations, a point is inside link k's rectangle exactly when its projection
  // falls within the link and its distance to the link's line is at most w/2. Recomputed in long
  // double; configurations whose margin is under 1e-9 are skipped as too close to call.
  const ArmProblem problem = read_arm_problem(arm_data_file("two_link_points.json"));
  const ArmCollisionChecker checker(problem);
  const double half = problem.arm.link_width / 2;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, two_pi);
  int decided = 0, colliding = 0;
  for (int i = 0; i < 20000; ++i) {
    const JointAngles q{angle(rng), angle(rng)};
    long double heading = 0, x = 0, y = 0;
    bool inside = false, close = false;
    for (std::size_t k = 0; k < 2; ++k) {
      heading += q[k];
      const long double dx = std::cos(heading), dy = std::sin(heading), l = problem.arm.links[k];
      for (const Eigen::Vector2d& p : problem.points) {
        const long double along = (p.x() - x) * dx + (p.y() - y) * dy;
        const long double across = std::fabs(-(p.x() - x) * dy + (p.y() - y) * dx);
        const long double margin = std::min({along, l - along, half - across});
        if (std::fabs(margin) < 1e-9) close = true;
        if (margin > 0) inside = true;
      }
      x += l * dx;
      y += l * dy;
    }
    if (close) continue;
    ++decided;
    colliding += inside;
    ASSERT_EQ(checker.is_free(q), !inside) << q[0] << " " << q[1];
  }
  EXPECT_GT(decided, 19900);
  EXPECT_GT(colliding, 1000);  // both outcomes occur
  EXPECT_LT(colliding, 19000);
}

TEST(Collision, PolygonBoundaryInteriorAndHoles) {
  // A 10×10 square with a 6×6 hole: the hole's interior is free, its boundary is not.
  PolygonWithHoles frame = square(5);
  frame.holes.push_back(ring({{-3, -3}, {-3, 3}, {3, 3}, {3, -3}}));
  for (int k = 0; k < 36; ++k) EXPECT_TRUE(ArmCollisionChecker(arm_of({2}), {frame}, {}).is_free({k * two_pi / 36})) << k;
  const ArmCollisionChecker three(arm_of({3}), {frame}, {});
  EXPECT_FALSE(three.is_free({0}));        // the tip (3, 0) is on the hole's boundary
  EXPECT_TRUE(three.is_free({kPi / 4}));   // the tip (2.12, 2.12) is inside the hole
  const auto contact = ArmCollisionChecker(arm_of({1, 3}), {frame}, {}).first_contact({0, 0});
  ASSERT_TRUE(contact);
  EXPECT_EQ(contact->describe(), "link 2 meets obstacles[0]");
  // A link deep inside an obstacle crosses no edge: still a collision.
  EXPECT_FALSE(ArmCollisionChecker(arm_of({1}), {square(10)}, {}).is_free({1.0}));
  // An obstacle deep inside a wide link: a collision; beside a thin link: none.
  const PolygonWithHoles small = {ring({{1.9, 0.4}, {2.1, 0.4}, {2.0, 0.6}}), {}};
  EXPECT_FALSE(ArmCollisionChecker(arm_of({4}, 2), {small}, {}).is_free({0}));
  EXPECT_TRUE(ArmCollisionChecker(arm_of({4}), {small}, {}).is_free({0}));
  // Out of reach, dropped at construction, never a collision.
  EXPECT_TRUE(ArmCollisionChecker(arm_of({1}), {square(0.5, 10, 10)}, {}).is_free({kPi / 4}));
}

TEST(Collision, EdgeGrazingIsContact) {
  // The link along the x axis touches the triangle's vertex (1, 0) exactly: a collision; the same
  // triangle moved up by one ulp of y is free.
  const PolygonWithHoles touching = {ring({{1, 0}, {2, 1}, {0, 1}}), {}};
  EXPECT_FALSE(ArmCollisionChecker(arm_of({2}), {touching}, {}).is_free({0}));
  const double y = up(0.0);
  const PolygonWithHoles above = {ring({{1, y}, {2, 1}, {0, 1}}), {}};
  EXPECT_TRUE(ArmCollisionChecker(arm_of({2}), {above}, {}).is_free({0}));
}

TEST(Collision, SelfCollisionOnlyWhenAskedAndNeverBetweenNeighbours) {
  // Link 1 along +x to (2,0), link 2 up to (2,1), link 3 heading 5π/4 from (2,1): it crosses the
  // x axis at x = 1, through link 1.
  const JointAngles crossing{0, kPi / 2, 3 * kPi / 4};
  EXPECT_TRUE(ArmCollisionChecker(arm_of({2, 1, 2}), {}, {}).is_free(crossing));
  const ArmCollisionChecker self(arm_of({2, 1, 2}, 0, true), {}, {});
  const auto contact = self.first_contact(crossing);
  ASSERT_TRUE(contact);
  EXPECT_EQ(contact->link, 0u);
  EXPECT_EQ(contact->with, ArmContact::With::link);
  EXPECT_EQ(contact->index, 2u);
  EXPECT_EQ(contact->describe(), "link 1 meets link 3");
  EXPECT_TRUE(self.is_free({0, kPi / 2, kPi / 2}));  // link 3 runs above link 1 (y = 1)
  // Folded back completely, neighbours overlap along their whole length: never counted.
  EXPECT_TRUE(ArmCollisionChecker(arm_of({2, 1}, 0.3, true), {}, {}).is_free({0, kPi}));
  // Wide links: link 3 passing 0.1 above link 1 touches it when the links are 0.3 wide.
  EXPECT_TRUE(self.is_free({0, kPi / 2, kPi / 2 + 0.05}));  // link 3 ends at (0.0025, 0.9)
  const ArmCollisionChecker wide(arm_of({2, 0.1, 2}, 0.3, true), {}, {});
  EXPECT_FALSE(wide.is_free({0, kPi / 2, kPi / 2}));
  EXPECT_TRUE(ArmCollisionChecker(arm_of({2, 0.4, 2}, 0.3, true), {}, {}).is_free({0, kPi / 2, kPi / 2}));
}

TEST(Collision, FirstContactOrderCountsAndBadArguments) {
  // Link 1 meets the point and the square; the polygon is reported first (documented order).
  ArmCollisionChecker checker(arm_of({3, 3}), {square(0.2, 2, 0)}, {Eigen::Vector2d(1, 0), Eigen::Vector2d(4, 0)});
  const auto contact = checker.first_contact({0, 0});
  ASSERT_TRUE(contact);
  EXPECT_EQ(contact->describe(), "link 1 meets obstacles[0]");
  const auto second = ArmCollisionChecker(arm_of({3, 3}), {}, {Eigen::Vector2d(1, 1), Eigen::Vector2d(4, 0)}).first_contact({0, 0});
  ASSERT_TRUE(second);
  EXPECT_EQ(second->describe(), "link 2 meets points[1]");
  EXPECT_EQ(checker.checks(), 1u);
  EXPECT_TRUE(checker.is_free({kPi / 2, 0}));
  EXPECT_EQ(checker.checks(), 2u);
  EXPECT_THROW(checker.is_free({0}), std::invalid_argument);
  EXPECT_THROW(checker.is_free({0, std::numeric_limits<double>::infinity()}), std::invalid_argument);
  EXPECT_THROW(ArmCollisionChecker(arm_of({}), {}, {}), std::invalid_argument);
  EXPECT_THROW(ArmCollisionChecker(arm_of({1, -1}), {}, {}), std::invalid_argument);
  EXPECT_THROW(ArmCollisionChecker(arm_of({1}, -0.1), {}, {}), std::invalid_argument);
  ArmCollisionChecker moved(std::move(checker));
  EXPECT_FALSE(moved.is_free({0, 0}));
  EXPECT_EQ(moved.checks(), 3u);
}
