// arm/arm_motion: certified motions (conservative advancement) and the sampled check they replace,
// on hand-built cases, on the shipped data/arms files, and against dense independent sampling.
#include <polyplan/arm/arm_motion.hpp>
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

// ---------------------------------------------------------------- the sampled check

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

// ---------------------------------------------------------------- shipped arms

TEST(ArmData, TwoLinkPointsQueriesAreFreeAndTheStraightMotionsAreAsDesigned) {
  const ArmProblem p = read_arm_problem(arm_data_file("two_link_points.json"));
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
    const ArmProblem p = read_arm_problem(arm_data_file(f.file));
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

