// arm/: angles, forward kinematics, the exact collision convention, checked motions, arm files and
// the shipped data/arms files. Expected values are worked out by hand in the comments, or
// re-computed independently (long double geometry with a safety margin, seed 001's formulas).
#include <polyplan/arm/angles.hpp>
#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace polyplan;

namespace {

constexpr double kPi = two_pi / 2;

// seed 001's angular_distance, written as the seed wrote it: an independent re-check.
double seed_angular_distance(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), two_pi);
  return std::min(d, two_pi - d);
}

double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

Ring ring(const std::vector<std::pair<double, double>>& points) {
  Ring r;
  for (auto [x, y] : points) r.push_back({Rational(x), Rational(y)});
  return r;
}

PolygonWithHoles square(double half, double cx = 0, double cy = 0) {
  return {ring({{cx - half, cy - half}, {cx + half, cy - half}, {cx + half, cy + half}, {cx - half, cy + half}}), {}};
}

Arm arm_of(std::vector<double> links, double width = 0, bool self_collision = false) {
  Arm arm;
  arm.links = std::move(links);
  arm.link_width = width;
  arm.self_collision = self_collision;
  return arm;
}

std::string data_file(const std::string& name) { return std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/" + name; }

}  // namespace

// ---------------------------------------------------------------- angles

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
  // seed 001 prints angular_distance(1, 5) = 2.2831853071795862.
  EXPECT_EQ(angular_distance(1, 5), 2.2831853071795862);
  EXPECT_EQ(angular_distance(5, 1), 2.2831853071795862);
  // seed 000's torus heuristic: between 2π − 0.1 and 0.1 the distance is 0.2.
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

// ---------------------------------------------------------------- kinematics

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

// ---------------------------------------------------------------- collision

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
  const ArmProblem problem = read_arm_problem(data_file("two_link_points.json"));
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

// ---------------------------------------------------------------- motions

TEST(Motion, SampleCountAndStepSize) {
  // Joint 0 turns 1 rad, joint 1 half of that: k = ceil(1 / 0.25) = 4 steps, 5 samples.
  const JointAngles from{0, 0}, to{1, 0.5};
  const auto samples = motion_samples(from, to, 0.25);
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(motion_step_count(from, to, 0.25), 4u);
  EXPECT_EQ(samples.front(), from);
  EXPECT_EQ(samples.back(), to);
  EXPECT_NEAR(samples[2][0], 0.5, 1e-15);
  EXPECT_NEAR(samples[2][1], 0.25, 1e-15);
  EXPECT_EQ(motion_samples(from, to, 0.3).size(), 5u);  // ceil(3.33) = 4
  EXPECT_EQ(motion_samples(from, to, 5).size(), 2u);    // at least one step
  EXPECT_EQ(motion_samples(from, from, 0.1).size(), 2u);
  // The ends are the given values bit for bit, even unnormalised.
  const auto raw = motion_samples({7.0}, {-1.0}, 0.01);
  EXPECT_EQ(raw.front(), JointAngles{7.0});
  EXPECT_EQ(raw.back(), JointAngles{-1.0});
  // Across 0 the short way, every step at most the resolution.
  const double resolution = 0.013;
  const JointAngles a{0.1, 3.0, 5.0}, b{two_pi - 0.1, 0.2, 5.0};
  const auto wrap = motion_samples(a, b, resolution);
  EXPECT_EQ(wrap.size(), static_cast<std::size_t>(std::ceil(angular_distance(3.0, 0.2) / resolution)) + 1);
  for (std::size_t i = 1; i < wrap.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) ASSERT_LE(angular_distance(wrap[i - 1][j], wrap[i][j]), resolution * (1 + 1e-12));
  for (const auto& s : wrap) ASSERT_LE(angular_distance(s[0], 0), 0.1 + 1e-15);
  EXPECT_THROW(motion_samples(a, b, 0), std::invalid_argument);
  EXPECT_THROW(motion_samples(a, b, std::nan("")), std::invalid_argument);
  EXPECT_THROW(motion_samples(a, b, 1e-12), std::invalid_argument);  // over 10^9 samples
  EXPECT_THROW(motion_samples(a, {0.0}, 0.1), std::invalid_argument);
}

TEST(Motion, APointBetweenTwoFreeConfigurationsBlocksTheMotion) {
  // A point at (0, 1) and a link [2] 0.2 wide: the link holds the point while |θ − π/2| ≤
  // asin(0.1 / 1) = 0.1002. θ = π/2 ± 0.3 are both free; only the motion sweeps the point.
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(0, 1)});
  const JointAngles before{kPi / 2 - 0.3}, after{kPi / 2 + 0.3};
  ASSERT_TRUE(checker.is_free(before));
  ASSERT_TRUE(checker.is_free(after));
  EXPECT_FALSE(checker.is_free({kPi / 2 + 0.1}));
  EXPECT_TRUE(checker.is_free({kPi / 2 + 0.101}));
  EXPECT_FALSE(motion_is_free(checker, before, after, 0.01));
  EXPECT_FALSE(motion_is_free(checker, after, before, 0.01));
  EXPECT_FALSE(motion_is_free(checker, before, after, 0.2));  // samples at π/2 ± 0.1: both held
  // At resolution 0.7 the motion is one step: only its two free ends are checked, and it is
  // accepted. The resolution is part of the answer, as documented.
  EXPECT_EQ(motion_samples(before, after, 0.7).size(), 2u);
  EXPECT_TRUE(motion_is_free(checker, before, after, 0.7));
  // A motion that does not sweep the point: free. Every sample counts as a check.
  const std::size_t before_checks = checker.checks();
  EXPECT_TRUE(motion_is_free(checker, {0.2}, {0.4}, 0.05));
  EXPECT_EQ(checker.checks() - before_checks, 5u);
}

TEST(Motion, WrapsAroundTheShortWay) {
  // A point at (−1, 0) holds a link [2] 0.2 wide for |θ − π| ≤ 0.1002. From 3.0 to 3.3 the
  // short way passes π: blocked. From 0.1 to 2π − 0.1 the short way passes 0, far from π: free
  // (the long way round would have been blocked).
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(-1, 0)});
  ASSERT_TRUE(checker.is_free({3.0}));
  ASSERT_TRUE(checker.is_free({3.3}));
  EXPECT_FALSE(motion_is_free(checker, {3.0}, {3.3}, 0.01));
  EXPECT_TRUE(motion_is_free(checker, {0.1}, {two_pi - 0.1}, 0.01));
  EXPECT_FALSE(motion_is_free(checker, {two_pi - 0.1}, {kPi}, 0.01));  // ends on the point
}

// ---------------------------------------------------------------- arm files

namespace {

// Writes `text` to a fresh file in a temporary folder and returns its path.
class ArmFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("polyplan_arm_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // The InputError message for a bad file, or "" when it was accepted.
  std::string error_for(const std::string& name, const std::string& text) const {
    const std::string path = write(name, text);
    try {
      std::vector<std::string> warnings;
      read_arm_problem(path, &warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
};

}  // namespace

TEST_F(ArmFiles, ReadsEveryField) {
  std::vector<std::string> warnings;
  const ArmProblem p = read_arm_problem(write("arm.json", R"({
    "links": [1.5, "1/2"], "link_width": 0.1, "self_collision": true,
    "obstacles": [[[0, 3], [0.1, 3], [0, 3.1]], {"outer": [[5, 5], [6, 5], [6, 6], [5, 6]]}],
    "points": [[1, 2], [-0.5, 1e-1]],
    "start": [0, 7], "goal": [1, -1],
    "queries": [{"name": "easy", "start": [0, 0], "goal": [1, 1]}, {"start": [2, 2], "goal": [3, 3], "speed": 2}],
    "colour": "red"
  })"), &warnings);
  EXPECT_EQ(p.source, (dir_ / "arm.json").string());
  EXPECT_EQ(p.arm.links, (std::vector<double>{1.5, 0.5}));
  EXPECT_EQ(p.arm.link_width, 0.1);
  EXPECT_TRUE(p.arm.self_collision);
  ASSERT_EQ(p.obstacles.size(), 2u);
  EXPECT_EQ(p.obstacles[0].outer[1].x, Rational(1, 10));  // exact, counter-clockwise as given
  EXPECT_EQ(p.obstacle_names[1], "obstacles[1]");
  ASSERT_EQ(p.points.size(), 2u);
  EXPECT_EQ(p.points[1], Eigen::Vector2d(-0.5, 0.1));
  ASSERT_EQ(p.queries.size(), 3u);
  EXPECT_EQ(p.queries[0].name, "start/goal");
  EXPECT_EQ(p.queries[0].start, (JointAngles{0, 7}));  // not normalised: planners do that
  EXPECT_EQ(p.queries[1].name, "easy");
  EXPECT_EQ(p.queries[2].name, "queries[1]");
  EXPECT_EQ(p.queries[2].goal, (JointAngles{3, 3}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("arm: unknown field \"colour\" ignored"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("queries[1]: unknown field \"speed\" ignored"), std::string::npos) << warnings[1];
}

TEST_F(ArmFiles, WarningsGoToStderrWhenNotCollected) {
  const std::string path = write("arm.json", R"({"links": [1], "colour": "red"})");
  ::testing::internal::CaptureStderr();
  read_arm_problem(path);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err, "warning: " + path + ": arm: unknown field \"colour\" ignored\n");
}

TEST_F(ArmFiles, EachBadFileNamesTheFileTheObjectAndTheProblem) {
  struct Case {
    const char* name;
    const char* text;
    const char* message;  // after "<path>: "
  };
  const std::vector<Case> cases = {
      {"no_links", R"({"points": []})", "arm: missing field \"links\" (the link lengths, e.g. [1, 1])"},
      {"empty_links", R"({"links": []})", "links: expected at least one link length, got []"},
      {"links_not_a_list", R"({"links": 5})", "links: expected a list of link lengths, got 5"},
      {"negative_link", R"({"links": [1, -2.5]})", "links[1]: a link length must be positive, got -2.5"},
      {"zero_link", R"({"links": [0, 1]})", "links[0]: a link length must be positive, got 0"},
      {"infinite_link", R"({"links": ["1e999"]})", "links[0]: not a finite double: 1e999"},
      {"link_not_a_number", R"({"links": [true]})", "links[0]: not a number: true"},
      {"negative_width", R"({"links": [1], "link_width": -0.5})", "link_width: must be 0 (segments) or positive, got -0.5"},
      {"self_collision_string", R"({"links": [1], "self_collision": "yes"})", "self_collision: expected true or false, got \"yes\""},
      {"start_too_short", R"({"links": [1, 1], "start": [0], "goal": [0, 0]})",
       "start: expected 2 joint angles (one per link, radians), got 1"},
      {"query_goal_too_long", R"({"links": [1], "queries": [{"start": [0], "goal": [0, 1]}]})",
       "queries[0].goal: expected 1 joint angles (one per link, radians), got 2"},
      {"angle_not_finite", R"({"links": [1, 1], "start": [0, "-1e999"], "goal": [0, 0]})", "start[1]: not a finite double: -1e999"},
      {"angle_not_a_number", R"({"links": [1], "start": ["abc"], "goal": [0]})", "start[0]: not a number: \"abc\""},
      {"goal_missing", R"({"links": [1], "start": [0]})", "arm: missing field \"goal\" (start is given)"},
      {"query_start_missing", R"({"links": [1], "queries": [{"goal": [0]}]})", "queries[0]: missing field \"start\""},
      {"query_name_twice", R"({"links": [1], "queries": [{"name": "a", "start": [0], "goal": [0]}, {"name": "a", "start": [0], "goal": [0]}]})",
       "queries[1].name: the query name \"a\" is used twice"},
      {"point_three_numbers", R"({"links": [1], "points": [[0, 0], [1, 2, 3]]})", "points[1]: expected a point [x, y], got [1,2,3]"},
      {"point_coordinate_text", R"({"links": [1], "points": [[0, "x"]]})", "points[0][1]: not a number: \"x\""},
      {"points_not_a_list", R"({"links": [1], "points": {"x": 1}})", "points: expected a list of points [[x, y], ...], got {\"x\":1}"},
      {"obstacle_bowtie", R"({"links": [1], "obstacles": [[[0, 0], [2, 2], [2, 0], [0, 2]]]})",
       "obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 2] crosses edge 2 [2, 0]-[0, 2]"},
      {"top_level_array", R"([1, 2])", "arm: expected a JSON object at the top level"},
  };
  for (const Case& c : cases) {
    const std::string path = (dir_ / (std::string(c.name) + ".json")).string();
    const std::string message = error_for(std::string(c.name) + ".json", c.text);
    EXPECT_EQ(message, path + ": " + c.message) << c.name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
  }
  EXPECT_EQ(error_for("syntax.json", R"({"links": [1,]})").rfind((dir_ / "syntax.json").string() + ": invalid JSON at byte", 0), 0u);
  EXPECT_EQ(error_for("huge.json", R"({"links": [1e999]})").rfind((dir_ / "huge.json").string() + ": number out of range", 0), 0u);
  try {
    read_arm_problem((dir_ / "missing.json").string());
    FAIL() << "read a file that does not exist";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "missing.json").string() + ": cannot open file");
  }
}

// ---------------------------------------------------------------- data/arms

TEST(ArmData, TwoLinkPointsQueriesAreFreeAndTheStraightMotionsAreAsDesigned) {
  const ArmProblem p = read_arm_problem(data_file("two_link_points.json"));
  EXPECT_EQ(p.arm.links, (std::vector<double>{5, 5}));
  EXPECT_GT(p.arm.link_width, 0);
  EXPECT_GE(p.points.size(), 20u);
  EXPECT_LE(p.points.size(), 40u);
  const ArmCollisionChecker checker(p);
  ASSERT_EQ(p.queries.size(), 3u);
  const std::vector<std::string> names{"easy", "medium", "hard"};
  for (std::size_t i = 0; i < 3; ++i) {
    const ArmQuery& q = p.queries[i];
    EXPECT_EQ(q.name, names[i]);
    EXPECT_TRUE(checker.is_free(q.start)) << q.name;
    EXPECT_TRUE(checker.is_free(q.goal)) << q.name;
  }
  // easy on the torus: θ1 fixed, θ2 from 0.12 back through 0 to 6.00 (0.40 rad) is free...
  EXPECT_NEAR(total_angular_distance(p.queries[0].start, p.queries[0].goal), 0.4031853071795866, 1e-12);
  EXPECT_TRUE(motion_is_free(checker, p.queries[0].start, p.queries[0].goal, two_pi / 3600));
  // ...while the long way up at θ1 = 0.76 is blocked (by the group of points above the arm).
  bool long_way_blocked = false;
  for (int k = 0; k <= 1000 && !long_way_blocked; ++k) long_way_blocked = !checker.is_free({0.76, 0.12 + 5.88 * k / 1000});
  EXPECT_TRUE(long_way_blocked);
  // hard: the straight short-way motion crosses the wall that separates it on the bounded square.
  EXPECT_FALSE(motion_is_free(checker, p.queries[2].start, p.queries[2].goal, two_pi / 3600));
}

TEST(ArmData, ForestsAreSeed001sArmsAndTheirStartAndGoalAreFree) {
  struct Forest {
    const char* file;
    std::size_t links;
    JointAngles start, goal;
  };
  for (const Forest& f : {Forest{"three_link_forest.json", 3, {1.0, 0.5, 5.0}, {4.0, 1.0, 1.0}},
                          Forest{"four_link_forest.json", 4, {0.1, 0.2, 0.3, 0.4}, {5.0, 1.0, 5.0, 0.5}}}) {
    const ArmProblem p = read_arm_problem(data_file(f.file));
    EXPECT_EQ(p.arm.links, std::vector<double>(f.links, 1.0)) << f.file;
    EXPECT_EQ(p.arm.link_width, 0) << f.file;
    EXPECT_EQ(p.obstacles.size(), 4 * f.links) << f.file;
    for (const PolygonWithHoles& t : p.obstacles) {  // the seed's triangle on the half grid
      ASSERT_EQ(t.outer.size(), 3u);
      const Rational x = t.outer[0].x, y = t.outer[0].y;
      EXPECT_EQ(Rational(2 * x).get_den(), 1);
      EXPECT_EQ(Rational(2 * y).get_den(), 1);
      EXPECT_TRUE(x >= -static_cast<long>(f.links) && x < static_cast<long>(f.links));
      EXPECT_EQ(t.outer[1], (ExactPoint{x + Rational(1, 2), y}));
      EXPECT_EQ(t.outer[2], (ExactPoint{x + Rational(1, 4), y + Rational(1, 2)}));
    }
    ASSERT_EQ(p.queries.size(), 1u);
    EXPECT_EQ(p.queries[0].start, f.start);
    EXPECT_EQ(p.queries[0].goal, f.goal);
    const ArmCollisionChecker checker(p);
    EXPECT_TRUE(checker.is_free(f.start)) << f.file;
    EXPECT_TRUE(checker.is_free(f.goal)) << f.file;
    EXPECT_FALSE(motion_is_free(checker, f.start, f.goal, two_pi / 360)) << f.file << ": the straight motion should need planning";
  }
}
