// Reeds–Shepp paths: every word returned reaches the goal, the shortest is the least of them,
// the distance is symmetric, never longer than Dubins', and known answers come out exactly.
// OMPL's distances: steering_reference_test.cpp.
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/input_error.hpp>
#include "car/steering_test_poses.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <string>

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

// Whether a path's word ("R+L-S-L-") is a slot's name ("R+L-S-L", a gear left out where the
// formula lets it be either) with some of its segments left out (those of no length).
bool fits(const std::string& word, const std::string& name) {
  std::size_t at = 0;
  for (std::size_t i = 0; i + 1 < word.size(); i += 2) {
    bool matched = false;
    while (!matched && at < name.size()) {
      const bool has_gear = at + 1 < name.size() && (name[at + 1] == '+' || name[at + 1] == '-');
      matched = name[at] == word[i] && (!has_gear || name[at + 1] == word[i + 1]);
      at += has_gear ? 2 : 1;
    }
    if (!matched) return false;
  }
  return true;
}

TEST(ReedsSheppWords, ListsEveryFormulaTriedAndTheShortestIsTheAnswer) {
  std::set<std::string> feasible_somewhere;
  for (const test::PosePair& p : test::random_pose_pairs(300, 48)) {
    const SteeringWords words = reeds_shepp_words(p.from, p.to, p.radius);
    ASSERT_EQ(words.words.size(), 44u);
    std::set<std::string> names;
    for (const SteeringWord& w : words.words) {
      names.insert(w.name);
      if (w.length) feasible_somewhere.insert(w.name);
    }
    EXPECT_EQ(names.size(), 44u) << "each slot named apart";
    const SteeringPath answer = shortest_reeds_shepp_path(p.from, p.to, p.radius);
    EXPECT_EQ(words.path.word, answer.word) << p.name;
    const SteeringWord& marked = words.words[words.shortest];
    ASSERT_TRUE(marked.length) << p.name;
    EXPECT_NEAR(*marked.length, answer.length(), 1e-12 * answer.length()) << p.name;
    double least = HUGE_VAL;
    for (const SteeringWord& w : words.words)
      if (w.length) least = std::min(least, *w.length);
    EXPECT_NEAR(least, answer.length(), 1e-12 * answer.length()) << p.name;
    EXPECT_TRUE(fits(answer.word, marked.name)) << p.name << ": " << answer.word << " under " << marked.name;
    EXPECT_EQ(std::count_if(words.words.begin(), words.words.end(), [](const SteeringWord& w) { return w.length; }),
              static_cast<std::ptrdiff_t>(reeds_shepp_paths(p.from, p.to, p.radius).size()));
  }
  EXPECT_EQ(feasible_somewhere.size(), 44u) << "every formula joins some pair";
}

TEST(ReedsSheppWords, NamesFollowTheFormulasAndTheirSymmetries) {
  const SteeringWords words = reeds_shepp_words({0, 0, 0}, {-3, 0, 0}, 1);
  const char* first[] = {"L+S+L+", "L-S-L-", "R+S+R+", "R-S-R-", "L+S+R+", "L-S-R-", "R+S+L+", "R-S-L-",
                         "L+R-L",  "L-R+L",  "R+L-R",  "R-L+R",  "LR-L+",  "LR+L-",  "RL-R+",  "RL+R-"};
  for (std::size_t i = 0; i < std::size(first); ++i) EXPECT_EQ(words.words[i].name, first[i]) << i;
  EXPECT_EQ(words.words.back().name, "R-L+S+R+L-");
  // Straight back: L-S-L- (and R-S-R-) with no arcs.
  EXPECT_EQ(words.path.word, "S-");
  EXPECT_TRUE(words.words[words.shortest].name == "L-S-L-" || words.words[words.shortest].name == "R-S-R-");
  // Its forward words cannot reach a goal behind the start on the line: L+S+L+ would need arcs.
  ASSERT_TRUE(words.words[0].length);
  EXPECT_GT(*words.words[0].length, 3 + M_PI);
}

TEST(ReedsShepp, RefusesWhatIsNotACar) {
  EXPECT_THROW(shortest_reeds_shepp_path({0, 0, 0}, {1, 1, 0}, 0), InputError);
  EXPECT_THROW(shortest_reeds_shepp_path({0, 0, std::nan("")}, {1, 1, 0}, 1), InputError);
}

}  // namespace
}  // namespace polyplan
