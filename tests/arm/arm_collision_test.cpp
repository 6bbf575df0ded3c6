// arm/arm_collision: the exact collision convention and the clearances (lower bounds of distances)
// that certified motions advance by. Expected values are worked out by hand in the comments, or
// re-computed independently (long double geometry with a safety margin).
#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/arm_collision.hpp>
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
  auto free_with_point = [&](double x, double y) {
    return ArmCollisionChecker(arm, {}, {Eigen::Vector2d(x, y)}).is_free({0});
  };
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
  for (int k = 0; k < 36; ++k)
    EXPECT_TRUE(ArmCollisionChecker(arm_of({2}), {frame}, {}).is_free({k * two_pi / 36})) << k;
  const ArmCollisionChecker three(arm_of({3}), {frame}, {});
  EXPECT_FALSE(three.is_free({0}));       // the tip (3, 0) is on the hole's boundary
  EXPECT_TRUE(three.is_free({kPi / 4}));  // the tip (2.12, 2.12) is inside the hole
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
  const auto second =
      ArmCollisionChecker(arm_of({3, 3}), {}, {Eigen::Vector2d(1, 1), Eigen::Vector2d(4, 0)}).first_contact({0, 0});
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

// ---------------------------------------------------------------- clearances

namespace {

// Every clearance is a lower bound of the true distance and, away from contact, within 1e-9 of it
// (the safety margin is about 1e-11 here).
void expect_lower_bound_of(double clearance, double distance) {
  EXPECT_LE(clearance, distance);
  EXPECT_GE(clearance, distance - 1e-9);
}

}  // namespace

TEST(Clearance, SegmentLinkToAPointByHand) {
  // Link [2] along +x, width 0: (1, 1.5) is 1.5 above its middle, (−1, 1) is √2 from the base,
  // (2.5, 0) — beyond the reach box, dropped — does not count.
  const Arm arm = arm_of({2});
  std::vector<double> c;
  ArmCollisionChecker(arm, {}, {Eigen::Vector2d(1, 1.5)}).clearances({0}, c);
  ASSERT_EQ(c.size(), 1u);
  expect_lower_bound_of(c[0], 1.5);
  ArmCollisionChecker(arm, {}, {Eigen::Vector2d(-1, 1), Eigen::Vector2d(1, 1.5)}).clearances({0}, c);
  expect_lower_bound_of(c[0], std::sqrt(2.0));
  // Turned up by π/2 the link runs along the y axis: (−1, 1) is 1 away.
  ArmCollisionChecker(arm, {}, {Eigen::Vector2d(-1, 1)}).clearances({kPi / 2}, c);
  expect_lower_bound_of(c[0], 1.0);
  // Nothing within reach: nothing limits the link.
  ArmCollisionChecker(arm, {}, {Eigen::Vector2d(2.5, 0)}).clearances({0}, c);
  EXPECT_EQ(c[0], std::numeric_limits<double>::infinity());
}

TEST(Clearance, RectangleLinkToAPolygonByHand) {
  // Link [2] 0.5 wide along +x: the rectangle [0, 2] × [−0.25, 0.25].
  const Arm arm = arm_of({2}, 0.5);
  std::vector<double> c;
  // The square [0.5, 1] × [0.75, 1.25] is 0.5 above the long side.
  ArmCollisionChecker(arm, {square(0.25, 0.75, 1.0)}, {}).clearances({0}, c);
  expect_lower_bound_of(c[0], 0.5);
  // The triangle's vertex (2.1, 0.6) is nearest to the corner (2, 0.25): √(0.1² + 0.35²).
  const PolygonWithHoles triangle = {ring({{2.1, 0.6}, {2.3, 0.6}, {2.1, 0.9}}), {}};
  ArmCollisionChecker(arm, {triangle}, {}).clearances({0}, c);
  expect_lower_bound_of(c[0], std::sqrt(0.1325));
  // Two obstacles: the nearer one counts. A point 0.1 beyond the tip is nearer still.
  ArmCollisionChecker(arm, {square(0.25, 0.75, 1.0), triangle}, {Eigen::Vector2d(2.1, 0)}).clearances({0}, c);
  expect_lower_bound_of(c[0], 0.1);
}

TEST(Clearance, ZeroWhenTouchingAndTheExactTestDecidesContact) {
  const Arm arm = arm_of({2}, 0.5);
  // The square [0.5, 1] × [0.25, 0.75] sits on the long side y = 0.25: touching is contact.
  const ArmCollisionChecker touching(arm, {square(0.25, 0.75, 0.5)}, {});
  ArmClearances split;
  touching.clearances({0}, split);
  EXPECT_EQ(split.links[0], 0.0);
  ASSERT_TRUE(split.contact);
  EXPECT_EQ(split.contact->describe(), "link 1 meets obstacles[0]");
  // One ulp above the side: free, and its clearance still 0 (closer than the true arm's radius
  // around the computed one proves nothing). A zero clearance is a lower bound, not a contact.
  const double y = up(0.25);
  const ArmCollisionChecker above(arm, {{ring({{0.5, y}, {1, y}, {1, 0.75}, {0.5, 0.75}}), {}}}, {});
  above.clearances({0}, split);
  EXPECT_TRUE(above.is_free({0}));
  EXPECT_FALSE(split.contact);
  EXPECT_EQ(split.links[0], 0.0);
  // A point on the tip edge: 0 and a contact; the point obstacle is reported by its index.
  const ArmCollisionChecker on_tip(arm, {}, {Eigen::Vector2d(-1, -1), Eigen::Vector2d(2, 0.1)});
  on_tip.clearances({0}, split);
  EXPECT_EQ(split.links[0], 0.0);
  ASSERT_TRUE(split.contact);
  EXPECT_EQ(split.contact->describe(), "link 1 meets points[1]");
}

TEST(Clearance, InsideAHoleAndInsideAnObstacle) {
  // A 10×10 square with a 6×6 hole: link [2] along +x lies in the hole, 1 from its side x = 3.
  PolygonWithHoles frame = square(5);
  frame.holes.push_back(ring({{-3, -3}, {-3, 3}, {3, 3}, {3, -3}}));
  std::vector<double> c;
  const ArmCollisionChecker in_hole(arm_of({2}), {frame}, {});
  in_hole.clearances({0}, c);
  expect_lower_bound_of(c[0], 1.0);
  in_hole.clearances({kPi / 4}, c);  // the tip (√2, √2) is 3 − √2 from the sides x = 3 and y = 3
  expect_lower_bound_of(c[0], 3 - std::sqrt(2.0));
  // A link deep inside an obstacle crosses no edge: it meets the region, clearance 0.
  ArmClearances split;
  ArmCollisionChecker(arm_of({1}), {square(10)}, {}).clearances({1.0}, split);
  EXPECT_EQ(split.links[0], 0.0);
  EXPECT_TRUE(split.contact);
}

TEST(Clearance, BetweenLinksWithSelfCollision) {
  // Link 1 from (0,0) to (2,0), link 2 up to (2,1), link 3 back to (0,1): links 1 and 3 are 1 apart.
  const JointAngles u_turn{0, kPi / 2, kPi / 2};
  ArmClearances split;
  const ArmCollisionChecker self(arm_of({2, 1, 2}, 0, true), {}, {});
  self.clearances(u_turn, split);
  ASSERT_EQ(split.pairs.size(), 9u);
  expect_lower_bound_of(split.pairs[0 * 3 + 2], 1.0);
  EXPECT_EQ(split.pairs[2 * 3 + 0], split.pairs[0 * 3 + 2]);
  for (std::size_t adjacent : {0 * 3 + 1, 1 * 3 + 0, 1 * 3 + 2, 2 * 3 + 1, 0 * 3 + 0})
    EXPECT_EQ(split.pairs[adjacent], std::numeric_limits<double>::infinity()) << adjacent;
  EXPECT_EQ(split.links, std::vector<double>(3, std::numeric_limits<double>::infinity()));  // no obstacles
  std::vector<double> c;
  self.clearances(u_turn, c);
  expect_lower_bound_of(c[0], 1.0);
  EXPECT_EQ(c[1], std::numeric_limits<double>::infinity());  // link 2 shares a joint with both
  expect_lower_bound_of(c[2], 1.0);
  // 0.3 wide, the rectangles are 0.7 apart; link 3 crossing link 1 makes it 0 and a contact.
  ArmCollisionChecker(arm_of({2, 1, 2}, 0.3, true), {}, {}).clearances(u_turn, split);
  expect_lower_bound_of(split.pairs[2], 0.7);
  self.clearances({0, kPi / 2, 3 * kPi / 4}, split);
  EXPECT_EQ(split.pairs[2], 0.0);
  ASSERT_TRUE(split.contact);
  EXPECT_EQ(split.contact->describe(), "link 1 meets link 3");
  // Without self-collision the pairs are not measured.
  ArmCollisionChecker(arm_of({2, 1, 2}), {}, {}).clearances(u_turn, split);
  EXPECT_TRUE(split.pairs.empty());
  EXPECT_FALSE(split.contact);
}

namespace {

long double point_segment_distance(long double px, long double py, long double ax, long double ay, long double bx,
                                   long double by) {
  const long double vx = bx - ax, vy = by - ay;
  const long double t = std::clamp(((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy), 0.0L, 1.0L);
  return std::hypot(px - ax - t * vx, py - ay - t * vy);
}

// Whether the checker keeps the obstacle: its box meets the box around the disc the arm reaches
// (which it widens by 1e-6 relative, see arm_collision.cpp).
bool within_reach_box(const PolygonWithHoles& polygon, double reach) {
  const double r = reach * (1 + 1e-6);
  const double inf = std::numeric_limits<double>::infinity();
  double xmin = inf, xmax = -inf, ymin = inf, ymax = -inf;
  for (const ExactPoint& v : polygon.outer) {
    xmin = std::min(xmin, to_double(v.x));
    xmax = std::max(xmax, to_double(v.x));
    ymin = std::min(ymin, to_double(v.y));
    ymax = std::max(ymax, to_double(v.y));
  }
  return xmin <= r && xmax >= -r && ymin <= r && ymax >= -r;
}

}  // namespace

TEST(Clearance, NeverAboveIndependentDistancesOnTheShippedArms) {
  // Random configurations of the two-link arm among points (rectangles) and of the three-link arm
  // in the forest (segments among triangles): the clearance of each link is at most its distance
  // recomputed in long double from the angles (and within 1e-9 of it); it is 0 exactly when the
  // link meets something, and then the contact is first_contact's.
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> angle(0, two_pi);
  {
    const ArmProblem p = read_arm_problem(arm_data_file("two_link_points.json"));
    const ArmCollisionChecker checker(p);
    const long double half = p.arm.link_width / 2;
    ArmClearances split;
    int colliding = 0;
    for (int i = 0; i < 5000; ++i) {
      const JointAngles q{angle(rng), angle(rng)};
      checker.clearances(q, split);
      long double heading = 0, x = 0, y = 0;
      for (std::size_t k = 0; k < 2; ++k) {
        heading += q[k];
        const long double dx = std::cos(heading), dy = std::sin(heading), l = p.arm.links[k];
        long double nearest = std::numeric_limits<long double>::infinity();
        for (const Eigen::Vector2d& o : p.points) {
          const long double along = (o.x() - x) * dx + (o.y() - y) * dy;
          const long double across = std::fabs(-(o.x() - x) * dy + (o.y() - y) * dx);
          nearest = std::min(nearest, std::hypot(std::max({0.0L, -along, along - l}), std::max(0.0L, across - half)));
        }
        if (nearest > 1e-9L) {
          ASSERT_LE(split.links[k], static_cast<double>(nearest)) << q[0] << " " << q[1] << " link " << k;
          ASSERT_GE(split.links[k], static_cast<double>(nearest) - 1e-9) << q[0] << " " << q[1] << " link " << k;
        }
        x += l * dx;
        y += l * dy;
      }
      const auto contact = checker.first_contact(q);
      ASSERT_EQ(split.contact.has_value(), contact.has_value());
      if (contact) {
        ++colliding;
        EXPECT_EQ(split.contact->describe(), contact->describe());
        EXPECT_EQ(split.links[contact->link], 0.0);
      } else {
        EXPECT_GT(std::min(split.links[0], split.links[1]), 0.0);  // nothing here is within 1e-9
      }
    }
    EXPECT_GT(colliding, 200);
    EXPECT_LT(colliding, 4800);
  }
  {
    const ArmProblem p = read_arm_problem(arm_data_file("three_link_forest.json"));
    const ArmCollisionChecker checker(p);
    std::vector<double> c;
    int free_configurations = 0;
    for (int i = 0; i < 3000; ++i) {
      const JointAngles q{angle(rng), angle(rng), angle(rng)};
      checker.clearances(q, c);
      if (!checker.is_free(q)) {
        EXPECT_EQ(*std::min_element(c.begin(), c.end()), 0.0);
        continue;
      }
      ++free_configurations;
      // Free segments are outside every triangle: their distance is the nearest pair of an end
      // point and a segment (link or triangle edge).
      long double heading = 0, x = 0, y = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        heading += q[k];
        const long double ex = x + std::cos(heading), ey = y + std::sin(heading);
        long double nearest = std::numeric_limits<long double>::infinity();
        for (const PolygonWithHoles& t : p.obstacles)
          for (std::size_t v = 0; v < 3 && within_reach_box(t, p.arm.reach()); ++v) {
            const long double ax = to_double(t.outer[v].x), ay = to_double(t.outer[v].y);
            const long double bx = to_double(t.outer[(v + 1) % 3].x), by = to_double(t.outer[(v + 1) % 3].y);
            nearest = std::min(
                {nearest, point_segment_distance(ax, ay, x, y, ex, ey), point_segment_distance(bx, by, x, y, ex, ey),
                 point_segment_distance(x, y, ax, ay, bx, by), point_segment_distance(ex, ey, ax, ay, bx, by)});
          }
        ASSERT_LE(c[k], static_cast<double>(nearest)) << k;
        ASSERT_GE(c[k], static_cast<double>(nearest) - 1e-9) << k;
        x = ex;
        y = ey;
      }
    }
    EXPECT_GT(free_configurations, 300);
  }
}

TEST(Clearance, SafeStepIsTheSmallestClearanceOverSpeed) {
  // Link [2] 0.5 wide along +x, the square 0.5 above it and a point 0.1 beyond the tip.
  const ArmCollisionChecker checker(arm_of({2}, 0.5), {square(0.25, 0.75, 1.0)}, {Eigen::Vector2d(2.1, 0)});
  const std::vector<double> none;
  const ArmSafeStep step = checker.safe_step({0}, std::vector<double>{2.0}, none, 1.0);
  EXPECT_FALSE(step.contact);
  EXPECT_LE(step.step, 0.05);  // 0.1 at speed 2
  // Far from contact a step may rest on the fast distance, whose error bound is 2^-20 of the
  // largest coordinate (2.1 here): short of the true clearance by at most twice that.
  EXPECT_GE(step.step, (0.1 - 0x1p-19 * 2.1) / 2 - 1e-12);
  EXPECT_EQ(checker.safe_step({0}, std::vector<double>{2.0}, none, 0.01).step, 0.01);  // the horizon
  // A link that does not move keeps a positive clearance forever; 0 clearance lasts not at all.
  EXPECT_EQ(checker.safe_step({0}, std::vector<double>{0.0}, none, 1.0).step, 1.0);
  const ArmCollisionChecker grazed(arm_of({2}), {}, {Eigen::Vector2d(1, up(0.0))});
  EXPECT_TRUE(grazed.is_free({0}));
  EXPECT_EQ(grazed.safe_step({0}, std::vector<double>{0.0}, none, 1.0).step, 0.0);
  // In collision (pointing at the square's centre): step 0 and first_contact's contact.
  const JointAngles into_square{std::atan2(1.0, 0.75)};
  const ArmSafeStep hit = checker.safe_step(into_square, std::vector<double>{1.0}, none, 1.0);
  EXPECT_EQ(hit.step, 0.0);
  ASSERT_TRUE(hit.contact);
  EXPECT_EQ(hit.contact->describe(), "link 1 meets obstacles[0]");
  // Self-collision: the pair's own speed, not the links', limits the step.
  const ArmCollisionChecker self(arm_of({2, 1, 2}, 0, true), {}, {});
  std::vector<double> pair_speed(9, 0.0);
  pair_speed[0 * 3 + 2] = 4;
  const ArmSafeStep folded = self.safe_step({0, kPi / 2, kPi / 2}, std::vector<double>{1, 1, 1}, pair_speed, 1.0);
  EXPECT_LE(folded.step, 0.25);  // 1 apart at relative speed 4
  EXPECT_GE(folded.step, 0.25 - 1e-9);
  // Bad arguments.
  EXPECT_THROW(checker.safe_step({0}, std::vector<double>{1.0, 1.0}, none, 1.0), std::invalid_argument);
  EXPECT_THROW(checker.safe_step({0}, std::vector<double>{-1.0}, none, 1.0), std::invalid_argument);
  EXPECT_THROW(checker.safe_step({0}, std::vector<double>{1.0}, none, std::nan("")), std::invalid_argument);
  EXPECT_THROW(self.safe_step({0, 0, 0}, std::vector<double>{1, 1, 1}, none, 1.0), std::invalid_argument);
  EXPECT_THROW(checker.safe_step({0, 0}, std::vector<double>{1.0}, none, 1.0), std::invalid_argument);
  std::vector<double> c;
  EXPECT_THROW(checker.clearances({std::nan("")}, c), std::invalid_argument);
}
