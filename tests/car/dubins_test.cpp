// Dubins paths: every word returned reaches the goal, the shortest is the least of them, and
// known answers (straight, U-turn, start = goal) come out exactly. OMPL's distances:
// steering_reference_test.cpp.
#include <polyplan/car/dubins.hpp>
#include <polyplan/geometry/input_error.hpp>
#include "car/steering_test_poses.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>

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

// Dubins-Curves' closed forms (A. Walker's dubins.c, after Shkel and Lumelsky), written out here
// independently of dubins.cpp: each word's length in turning radii from the start's heading
// alpha and the goal's beta, both measured from the start-goal line, and the distance d in radii;
// none where the word is infeasible.
double mod2pi(double a) { return a - 2 * M_PI * std::floor(a / (2 * M_PI)); }

std::map<std::string, std::optional<double>> dubins_curves_lengths(const CarPose& from, const CarPose& to,
                                                                   double radius) {
  const double dx = to.x - from.x, dy = to.y - from.y, d = std::hypot(dx, dy) / radius;
  const double theta = d > 0 ? mod2pi(std::atan2(dy, dx)) : 0;
  const double alpha = mod2pi(from.theta - theta), beta = mod2pi(to.theta - theta);
  const double sa = std::sin(alpha), sb = std::sin(beta), ca = std::cos(alpha), cb = std::cos(beta),
               c_ab = std::cos(alpha - beta);
  std::map<std::string, std::optional<double>> lengths;
  if (const double p2 = 2 + d * d - 2 * c_ab + 2 * d * (sa - sb); p2 >= 0) {
    const double tmp = std::atan2(cb - ca, d + sa - sb);
    lengths["LSL"] = mod2pi(tmp - alpha) + std::sqrt(p2) + mod2pi(beta - tmp);
  }
  if (const double p2 = 2 + d * d - 2 * c_ab + 2 * d * (sb - sa); p2 >= 0) {
    const double tmp = std::atan2(ca - cb, d - sa + sb);
    lengths["RSR"] = mod2pi(alpha - tmp) + std::sqrt(p2) + mod2pi(tmp - beta);
  }
  if (const double p2 = -2 + d * d + 2 * c_ab + 2 * d * (sa + sb); p2 >= 0) {
    const double p = std::sqrt(p2), tmp = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p);
    lengths["LSR"] = mod2pi(tmp - alpha) + p + mod2pi(tmp - beta);
  }
  if (const double p2 = -2 + d * d + 2 * c_ab - 2 * d * (sa + sb); p2 >= 0) {
    const double p = std::sqrt(p2), tmp = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p);
    lengths["RSL"] = mod2pi(alpha - tmp) + p + mod2pi(beta - tmp);
  }
  if (const double c = (6 - d * d + 2 * c_ab + 2 * d * (sa - sb)) / 8; std::abs(c) <= 1) {
    const double p = mod2pi(2 * M_PI - std::acos(c)), t = mod2pi(alpha - std::atan2(ca - cb, d - sa + sb) + p / 2);
    lengths["RLR"] = t + p + mod2pi(alpha - beta - t + p);
  }
  if (const double c = (6 - d * d + 2 * c_ab + 2 * d * (sb - sa)) / 8; std::abs(c) <= 1) {
    const double p = mod2pi(2 * M_PI - std::acos(c)), t = mod2pi(-alpha - std::atan2(ca - cb, d + sa - sb) + p / 2);
    lengths["LRL"] = t + p + mod2pi(beta - alpha - t + p);
  }
  for (const char* word : {"LSL", "RSR", "LSR", "RSL", "RLR", "LRL"})
    if (auto& length = lengths[word]) *length *= radius;
  return lengths;
}

// The least listed length.
double least_listed(const SteeringWords& words) {
  double least = HUGE_VAL;
  for (const SteeringWord& w : words.words)
    if (w.length) least = std::min(least, *w.length);
  return least;
}

TEST(DubinsWords, ListsTheSixAndTheShortestIsTheAnswer) {
  for (const test::PosePair& p : test::random_pose_pairs(300, 48)) {
    const SteeringWords words = dubins_words(p.from, p.to, p.radius);
    ASSERT_EQ(words.words.size(), 6u);
    const char* names[] = {"LSL", "RSR", "LSR", "RSL", "RLR", "LRL"};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(words.words[i].name, names[i]);
    const SteeringPath answer = shortest_dubins_path(p.from, p.to, p.radius);
    EXPECT_EQ(words.path.word, answer.word) << p.name;
    EXPECT_EQ(words.path.length(), answer.length()) << p.name;
    ASSERT_TRUE(words.words[words.shortest].length) << p.name;
    EXPECT_NEAR(*words.words[words.shortest].length, answer.length(), 1e-12 * answer.length()) << p.name;
    EXPECT_NEAR(least_listed(words), answer.length(), 1e-12 * answer.length()) << p.name;
    EXPECT_EQ(std::count_if(words.words.begin(), words.words.end(), [](const SteeringWord& w) { return w.length; }),
              static_cast<std::ptrdiff_t>(dubins_paths(p.from, p.to, p.radius).size()));
  }
}

TEST(DubinsWords, AgreeWithDubinsCurvesClosedForms) {
  for (const test::PosePair& p : test::random_pose_pairs(300, 49)) {
    const auto expected = dubins_curves_lengths(p.from, p.to, p.radius);
    for (const SteeringWord& w : dubins_words(p.from, p.to, p.radius).words) {
      const std::optional<double>& want = expected.at(w.name);
      ASSERT_EQ(w.length.has_value(), want.has_value()) << p.name << " " << w.name;
      // Arcs of a full turn (2 pi) in one and none in the other come from headings equal within
      // rounding: the lengths then differ by 2 pi R.
      if (want) EXPECT_NEAR(*w.length, *want, 1e-9 * (1 + *want)) << p.name << " " << w.name;
    }
  }
}

TEST(DubinsWords, AgreeWithDubinsCurvesTable) {
  std::ifstream table(std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/car/dubins_curves_words.txt");
  ASSERT_TRUE(table) << "tests/data/car/dubins_curves_words.txt";
  std::string line;
  std::optional<SteeringWords> words;
  int blocks = 0, checked = 0;
  while (std::getline(table, line)) {
    double alpha, beta, d;
    if (std::sscanf(line.c_str(), "# %lf %lf %lf", &alpha, &beta, &d) == 3) {
      words = dubins_words({0, 0, alpha}, {d, 0, beta}, 1);
      ++blocks;
      continue;
    }
    char name[4];
    double sum;
    int infeasible;
    if (!words || std::sscanf(line.c_str(), "%3s %lf %d", name, &sum, &infeasible) != 3) continue;
    const auto w = std::find_if(words->words.begin(), words->words.end(),
                                [&](const SteeringWord& listed) { return listed.name == name; });
    ASSERT_NE(w, words->words.end()) << line;
    ++checked;
    EXPECT_EQ(!w->length, infeasible == 1) << line;
    double t, p, q;
    if (w->length && std::sscanf(line.c_str(), "%*s %*f %*d (%lf %lf %lf)", &t, &p, &q) == 3)
      EXPECT_NEAR(*w->length, t + p + q, 3e-6) << line;  // three lengths printed to 1e-6
  }
  EXPECT_EQ(blocks, 12);
  EXPECT_EQ(checked, 72);
}

TEST(DubinsWords, InfeasibleWordsAreMarked) {
  // Headings along the line 10 radii apart: the RLR and LRL circles lie more than 4 radii apart.
  const SteeringWords far = dubins_words({0, 0, 0}, {10, 0, 0}, 1);
  EXPECT_FALSE(far.words[4].length);
  EXPECT_FALSE(far.words[5].length);
  // The four CSC words are all the straight line, their arcs of no length: a tie, driven as "S".
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(*far.words[i].length, 10, 1e-12) << far.words[i].name;
  EXPECT_EQ(far.path.word, "S");
  // A U-turn onto the lane R to the left: the start's right circle and the goal's left one, and
  // the start's left and the goal's right, have centres R apart (under 2R): no inner tangent.
  const SteeringWords u_turn = dubins_words({0, 0, 0}, {0, 1, M_PI}, 1);
  EXPECT_FALSE(u_turn.words[2].length);
  EXPECT_FALSE(u_turn.words[3].length);
  EXPECT_TRUE(u_turn.words[4].length && u_turn.words[5].length);
}

TEST(Dubins, RefusesWhatIsNotACar) {
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, 0), InputError);
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, -1), InputError);
  EXPECT_THROW(shortest_dubins_path({0, 0, 0}, {1, 1, 0}, std::nan("")), InputError);
  EXPECT_THROW(shortest_dubins_path({0, std::numeric_limits<double>::infinity(), 0}, {1, 1, 0}, 1), InputError);
}

}  // namespace
}  // namespace polyplan
