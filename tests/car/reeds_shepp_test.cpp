// Reeds–Shepp paths: every word returned reaches the goal, the shortest is the least of them,
// the distance is symmetric, never longer than Dubins', and known answers come out exactly.
// OMPL's distances: steering_reference_test.cpp.
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/input_error.hpp>
#include "car/steering_test_poses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace polyplan {
namespace {

TEST(ReedsShepp, EveryWordReachesTheGoalAndTheShortestIsTheLeast) {
  std::set<std::string> words;
  for (const test::PosePair& p : test::every_test_pair()) {
    const SteeringPath shortest = shortest_reeds_shepp_path(p.from, p.to, p.radius);
    EXPECT_NEAR(reeds_shepp_distance(p.from, p.to, p.radius), shortest.length(),
                1e-14 * std::max(1.0, shortest.length()))
        << p.name;
    EXPECT_LE(goal_miss(shortest, p.from, p.to, p.radius), test::miss_allowed(p)) << p.name << " " << shortest.word;
    for (const SteeringPath& path : reeds_shepp_paths(p.from, p.to, p.radius)) {
      EXPECT_LE(goal_miss(path, p.from, p.to, p.radius), test::miss_allowed(p)) << p.name << " " << path.word;
      EXPECT_LE(shortest.length(), path.length() * (1 + 1e-14)) << p.name;  // words are compared in radii, then scaled
      words.insert(path.word);
    }
    EXPECT_LE(shortest.length(), shortest_dubins_path(p.from, p.to, p.radius).length() * (1 + 1e-12)) << p.name;
    EXPECT_GE(shortest.length(), std::hypot(p.to.x - p.from.x, p.to.y - p.from.y) * (1 - 1e-15)) << p.name;
  }
  // The random pairs reach every word of the paper's 48 (each with both gear patterns of its
  // cusps) that the formulas produce.
  EXPECT_GE(words.size(), 48u);
}

TEST(ReedsShepp, IsSymmetric) {
  for (const test::PosePair& p : test::every_test_pair()) {
    const double there = shortest_reeds_shepp_path(p.from, p.to, p.radius).length();
    const double back = shortest_reeds_shepp_path(p.to, p.from, p.radius).length();
    EXPECT_NEAR(there, back, 1e-12 * std::max(1.0, there)) << p.name;
  }
}

TEST(ReedsShepp, KnownAnswers) {
  const SteeringPath reverse = shortest_reeds_shepp_path({0, 0, 0}, {-3, 0, 0}, 1);
  EXPECT_EQ(reverse.word, "S-");
  EXPECT_DOUBLE_EQ(reverse.length(), 3);
  EXPECT_EQ(shortest_reeds_shepp_path({1, 2, 0.3}, {1, 2, 0.3}, 1).length(), 0);
  // A goal 1e-9 behind is a 1e-9 reverse, not a loop.
  EXPECT_NEAR(shortest_reeds_shepp_path({5, 5, 0}, {5 - 1e-9, 5, 0}, 1).length(), 1e-9, 1e-15);
  // A quarter turn backwards onto the left circle.
  const SteeringPath quarter = shortest_reeds_shepp_path({0, 0, 0}, {-1, 1, -M_PI / 2}, 1);
  EXPECT_EQ(quarter.word, "L-");
  EXPECT_NEAR(quarter.length(), M_PI / 2, 1e-12);
}

TEST(ReedsShepp, RefusesWhatIsNotACar) {
  EXPECT_THROW(shortest_reeds_shepp_path({0, 0, 0}, {1, 1, 0}, 0), InputError);
  EXPECT_THROW(shortest_reeds_shepp_path({0, 0, std::nan("")}, {1, 1, 0}, 1), InputError);
}

}  // namespace
}  // namespace polyplan
