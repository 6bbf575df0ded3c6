// Dubins paths: every word returned reaches the goal, the shortest is the least of them, and
// known answers (straight, U-turn, start = goal) come out exactly. OMPL's distances:
// steering_reference_test.cpp.
#include <polyplan/car/dubins.hpp>
#include <polyplan/geometry/input_error.hpp>
#include "car/steering_test_poses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace polyplan {
namespace {

TEST(Dubins, EveryWordReachesTheGoalAndTheShortestIsTheLeast) {
  for (const test::PosePair& p : test::every_test_pair()) {
    const auto paths = dubins_paths(p.from, p.to, p.radius);
    ASSERT_GE(paths.size(), 2u) << p.name;  // LSL and RSR always exist
    const SteeringPath shortest = shortest_dubins_path(p.from, p.to, p.radius);
    EXPECT_NEAR(dubins_distance(p.from, p.to, p.radius), shortest.length(), 1e-14 * std::max(1.0, shortest.length()))
        << p.name;
    EXPECT_LE(goal_miss(shortest, p.from, p.to, p.radius), test::miss_allowed(p)) << p.name << " " << shortest.word;
    for (const SteeringPath& path : paths) {
      EXPECT_LE(goal_miss(path, p.from, p.to, p.radius), test::miss_allowed(p)) << p.name << " " << path.word;
      EXPECT_LE(shortest.length(), path.length() * (1 + 1e-14)) << p.name;  // words are compared in radii, then scaled
      for (const SteeringSegment& s : path.segments) EXPECT_EQ(s.gear, 1);
    }
    // No path is shorter than the straight line.
    EXPECT_GE(shortest.length(), std::hypot(p.to.x - p.from.x, p.to.y - p.from.y) * (1 - 1e-15)) << p.name;
  }
}

TEST(Dubins, KnownAnswers) {
  EXPECT_EQ(shortest_dubins_path({0, 0, 0}, {5, 0, 0}, 1).word, "S");
  EXPECT_DOUBLE_EQ(shortest_dubins_path({0, 0, 0}, {5, 0, 0}, 1).length(), 5);
  // A U-turn onto the parallel lane 2R to the left: half a turn, pi R.
  const SteeringPath u_turn = shortest_dubins_path({0, 0, 0}, {0, 4, M_PI}, 2);
  EXPECT_EQ(u_turn.word, "L");
  EXPECT_NEAR(u_turn.length(), 2 * M_PI, 1e-12);
  EXPECT_EQ(shortest_dubins_path({1, 2, 0.3}, {1, 2, 0.3}, 1).length(), 0);
  // A goal 1e-9 behind: the car must loop (OMPL drives 1e-9 forward instead and misses it).
  const SteeringPath behind = shortest_dubins_path({5, 5, 0}, {5 - 1e-9, 5, 0}, 1);
  EXPECT_GT(behind.length(), 2 * M_PI);
  EXPECT_LE(goal_miss(behind, {5, 5, 0}, {5 - 1e-9, 5, 0}, 1), 1e-9);
}

TEST(Dubins, PoseAlongThePathRunsFromStartToGoal) {
  const CarPose from{1, -2, 0.7}, to{-4, 3, -2.5};
  const SteeringPath path = shortest_dubins_path(from, to, 1.5);
  const CarPose start = pose_along(path, from, 1.5, 0), end = pose_along(path, from, 1.5, path.length());
  EXPECT_DOUBLE_EQ(start.x, from.x);
  EXPECT_DOUBLE_EQ(start.theta, from.theta);
  EXPECT_LE(goal_miss(path, from, to, 1.5), 1e-9);
  EXPECT_NEAR(end.x, to.x, 1e-9);
  // Halfway along, the car is no farther from either end than half the path.
  const CarPose half = pose_along(path, from, 1.5, path.length() / 2);
  EXPECT_LE(std::hypot(half.x - from.x, half.y - from.y), path.length() / 2 + 1e-12);
  EXPECT_LE(std::hypot(half.x - to.x, half.y - to.y), path.length() / 2 + 1e-12);
}

TEST(Dubins, RefusesWhatIsNotACar) {
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, 0), InputError);
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, -1), InputError);
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, std::nan("")), InputError);
  EXPECT_THROW(shortest_dubins_path({0, std::numeric_limits<double>::infinity(), 0}, {1, 1, 0}, 1), InputError);
}

}  // namespace
}  // namespace polyplan
