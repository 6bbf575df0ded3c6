#pragma once
// Small helpers shared by the arm/ tests (and the arm reader's): arms, obstacles and data files
// described inline.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_goal_set.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::test {

inline constexpr double kPi = two_pi / 2;

// The next double above / below x: "one ulp beside".
inline double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
inline double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

inline Ring ring(const std::vector<std::pair<double, double>>& points) {
  Ring r;
  for (auto [x, y] : points) r.push_back({Rational(x), Rational(y)});
  return r;
}

// The axis-aligned square of half-side `half` centred at (cx, cy).
inline PolygonWithHoles square(double half, double cx = 0, double cy = 0) {
  return {ring({{cx - half, cy - half}, {cx + half, cy - half}, {cx + half, cy + half}, {cx - half, cy + half}}), {}};
}

inline Arm arm_of(std::vector<double> links, double width = 0, bool self_collision = false) {
  Arm arm;
  arm.links = std::move(links);
  arm.link_width = width;
  arm.self_collision = self_collision;
  return arm;
}

// Whether every configuration at samples `resolution` radians apart (arm/arm_motion.hpp's
// motion_samples) is free: the sampled check certification replaced, kept here to show what it
// misses and to check certificates independently with dense samples.
inline bool samples_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to,
                         double resolution) {
  for (const JointAngles& q : motion_samples(from, to, resolution))
    if (!checker.is_free(q)) return false;
  return true;
}

// A shipped arm file: data/arms/<name>.
inline std::string arm_data_file(const std::string& name) {
  return std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/" + name;
}

// Where the hand of an arm with these links is at `angles`: forward kinematics written out here, apart
// from the library's joint_positions, for the tests that check a planner's hand against a point.
inline Eigen::Vector2d hand_at(const std::vector<double>& links, const JointAngles& angles) {
  Eigen::Vector2d hand(0, 0);
  double heading = 0;
  for (std::size_t k = 0; k < links.size(); ++k) {
    heading += angles.at(k);
    hand += links[k] * Eigen::Vector2d(std::cos(heading), std::sin(heading));
  }
  return hand;
}

// Whether a configuration keeps to joint limits [lo, hi] read round the circle (some a + 2πk in
// them), to 1e-12 rad.
inline bool keeps_limits(const JointAngles& angles, const std::vector<std::pair<double, double>>& limits) {
  for (std::size_t i = 0; i < limits.size(); ++i) {
    const auto [lo, hi] = limits[i];
    bool within = hi - lo >= two_pi;
    for (int k = -3; k <= 3 && !within; ++k)
      within = angles[i] + k * two_pi >= lo - 1e-12 && angles[i] + k * two_pi <= hi + 1e-12;
    if (!within) return false;
  }
  return true;
}

// The end of a path to a goal in the workspace: the hand at the point within 1e-9 (and the last
// link at the orientation, when asked, within 1e-9), by hand_at; the configuration normalised and
// within the arm's joint limits.
inline void expect_hand_at_goal(const Arm& arm, const WorkspaceGoal& goal, const JointAngles& end) {
  EXPECT_LE((hand_at(arm.links, end) - goal.point).norm(), 1e-9) << "the hand misses the goal point";
  if (goal.orientation) {
    double heading = 0;
    for (const double a : end) heading += a;
    EXPECT_LE(std::abs(std::remainder(heading - *goal.orientation, two_pi)), 1e-9) << "the last link's orientation";
  }
  for (const double a : end) EXPECT_TRUE(a >= 0 && a < two_pi) << a;
  EXPECT_TRUE(keeps_limits(end, arm.limits));
}

// A returned arm path checked independently of its planner: it begins at the query's start and
// ends at its goal (normalised) — or, for a goal in the workspace, with the hand at the point
// (expect_hand_at_goal) —, and every motion is free at samples 0.01° apart (of the joint that
// turns most) and certified again. Returns the sum of the joints' short-way turns.
inline double expect_arm_path_free(const ArmCollisionChecker& checker, const ArmQuery& q,
                                   const std::vector<JointAngles>& path) {
  if (path.size() < 2) {
    ADD_FAILURE() << "a path of " << path.size() << " configurations";
    return 0;
  }
  for (std::size_t j = 0; j < q.start.size(); ++j) EXPECT_EQ(path.front()[j], normalize_angle(q.start[j]));
  if (q.goal_point) {
    expect_hand_at_goal(checker.arm(), *q.goal_point, path.back());
  } else {
    for (std::size_t j = 0; j < q.goal.size(); ++j) EXPECT_EQ(path.back()[j], normalize_angle(q.goal[j]));
  }
  const double dense = 0.01 * two_pi / 360;
  double length = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    for (const JointAngles& c : motion_samples(path[k], path[k + 1], dense))
      if (!checker.is_free(c)) {
        ADD_FAILURE() << "a configuration between path[" << k << "] and path[" << k + 1 << "] collides";
        break;
      }
    EXPECT_TRUE(certify_motion(checker, path[k], path[k + 1]).free()) << "motion " << k;
    length += total_angular_distance(path[k], path[k + 1]);
  }
  return length;
}

// The goal facts of a found path to a goal in the workspace, against the query's goal set: they name
// a goal of the set (goal.candidates its size) whose angles are the path's end and whose error
// goal.error is. Returns which goal it is.
inline std::size_t expect_goal_facts(const PlanReport<JointAngles>& report, const ArmGoalSet& set) {
  const auto reached = static_cast<std::size_t>(report.facts.at(GoalFacts::reached));
  EXPECT_EQ(report.facts.at(GoalFacts::candidates), static_cast<std::int64_t>(set.goals.size()));
  if (reached >= set.goals.size() || report.path.empty()) {
    ADD_FAILURE() << "goal.reached " << reached << " of " << set.goals.size() << " goals";
    return 0;
  }
  EXPECT_EQ(report.path.back(), set.goals[reached].angles);
  EXPECT_EQ(report.facts.at(GoalFacts::error), set.goals[reached].error);
  return reached;
}

}  // namespace polyplan::test
