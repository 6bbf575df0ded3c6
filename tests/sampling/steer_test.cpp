// SamplingSpace::steer, the one steering of the sampling planners: at most `step` along the motion,
// the target itself when nearer, from either end; on the arm's torus each joint the short way
// round across the 0 = 2π seam, a half turn counted as +π. Expected points computed here by hand.
#include <polyplan/arm/arm_sampling_space.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/sampling/polygon_sampling_space.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace polyplan {
namespace {

constexpr double pi = std::numbers::pi;

TEST(Steer, EuclideanGoesAtMostTheStepAlongTheSegmentOrToTheTarget) {
  const World world =
      test::world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [], "start": [1, 1], "goal": [4, 5]})");
  const CSpace cspace(world);
  const auto space = polygon_sampling_space(cspace);
  const std::array<double, 2> a{1, 1}, b{4, 5};  // 5 apart: (0.6, 0.8) per unit
  std::array<double, 2> out{};
  EXPECT_EQ(space->steer(a, b, 2, out), 5);
  EXPECT_NEAR(out[0], 2.2, 1e-15);
  EXPECT_NEAR(out[1], 2.6, 1e-15);
  EXPECT_NEAR(space->distance(a, out), 2, 1e-14);
  space->steer(a, b, 5, out);  // exactly as far: the target itself, bit for bit
  EXPECT_EQ(out, b);
  space->steer(a, b, 0, out);  // 0: all the way
  EXPECT_EQ(out, b);
  space->steer(a, b, 2, out, SteerFrom::end);  // 2 before b on a → b
  EXPECT_NEAR(out[0], 2.8, 1e-15);
  EXPECT_NEAR(out[1], 3.4, 1e-15);
  space->steer(a, b, 7, out, SteerFrom::end);
  EXPECT_EQ(out, a);
}

TEST(Steer, TheArmsTorusTurnsEachJointTheShortWayAcrossTheSeam) {
  const ArmProblem problem = read_arm_problem(std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/two_link_points.json");
  const auto space = arm_sampling_space(problem);
  const std::array<double, 2> a{6.0, 0.5}, b{0.2, 3.0};
  // Joint 1 goes up through 2π (0.2 + 2π − 6 ≈ 0.483), joint 2 up by 2.5: the distance is their sum.
  const double turn1 = 0.2 + 2 * pi - 6.0, turn2 = 2.5, d = turn1 + turn2;
  std::array<double, 2> out{};
  EXPECT_NEAR(space->steer(a, b, 1, out), d, 1e-12);
  EXPECT_NEAR(out[0], std::fmod(6.0 + turn1 / d, 2 * pi), 1e-12);
  EXPECT_NEAR(out[1], 0.5 + turn2 / d, 1e-12);
  EXPECT_NEAR(space->distance(a, out), 1, 1e-12);
  space->steer(a, b, 10, out);
  EXPECT_EQ(out, b);
  // A half turn is +π: from 0 toward π, a quarter of the way goes up, not down.
  const std::array<double, 2> zero{0, 0}, half{pi, 0};
  space->steer(zero, half, pi / 4, out);
  EXPECT_NEAR(out[0], pi / 4, 1e-15);
  // Going down across the seam: from 0.1 toward 6.0 is −(0.1 + 2π − 6.0).
  const std::array<double, 2> low{0.1, 1}, high{6.0, 1};
  space->steer(low, high, 0.15, out);
  EXPECT_NEAR(out[0], 2 * pi - 0.05, 1e-12);
  EXPECT_NEAR(out[1], 1, 1e-15);
}

}  // namespace
}  // namespace polyplan
