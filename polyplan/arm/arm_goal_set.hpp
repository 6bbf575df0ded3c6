#pragma once
// The configurations an arm query may end at, for every arm planner: its goal configuration, or for
// a goal in the workspace (ArmQuery::goal_point: the hand at a point, optionally with the last link's
// orientation) the collision-free inverse-kinematics solutions that put the hand there.
//
//   two links without an orientation, three with one: every solution of the closed forms (2, or 1 on
//   the boundary of the reachable annulus); otherwise numeric_ik's distinct solutions from `seeds`
//   seeds (a redundant arm has a continuum of them: the seeds pick a spread of it), refined until the
//   end-effector error is below 1e-12 (1e-14 is aimed at) and never accepted above 1e-9; then the arm's joint limits;
//   then the collision checker: only free configurations are goals. Each is normalised to [0, 2π) as the planners'
//   paths are, and its error measured there, by forward kinematics.
//
// Why there are none is part of the answer: a point outside the annulus the hand reaches,
// max(0, 2·max l − Σ l) ≤ d ≤ Σ l, decided exactly (hand_reach), is status no_path; a point within it
// whose every solution found collides or breaks the limits is not_found (a path may still end at a
// configuration the seeds missed).
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

struct ArmGoal {
  JointAngles angles;  // each in [0, 2π)
  double error = 0;    // |hand − goal point| at these angles; 0 for a goal given as joint angles
};

struct ArmGoalSet {
  std::vector<ArmGoal> goals;  // in a fixed order (the solutions' order); a workspace goal's are all free
  bool workspace = false;      // the query's goal is a point for the hand
  // When `goals` is empty: no_path (out of reach) or not_found, and why, in one sentence.
  PlanStatus status = PlanStatus::solved;
  std::string why_none;
  std::size_t solutions = 0;  // inverse-kinematics solutions found, before the limits and collisions

  std::vector<JointAngles> configurations() const;
  // Which goal `configuration` is (the first equal to it); throws std::logic_error when none is.
  std::size_t index_of(const JointAngles& configuration) const;
};

// The seeds numeric_ik starts from for a workspace goal (docs/workspace_goals.md measures them).
inline constexpr std::size_t goal_set_seeds = 32;

// The goal set of `query` for the checker's arm. A goal given as joint angles is that configuration
// alone, normalised (query_not_free says whether it is free). Call after query_not_free accepted the query.
ArmGoalSet arm_goal_set(const ArmCollisionChecker& checker, const ArmQuery& query, std::size_t seeds = goal_set_seeds);

// The facts of a path that ends at goal `reached` of `set`, the same for every arm planner:
//   goal.candidates  how many goals (the sampling planners' word; set here for a workspace goal even
//                    when it is 1, so that its JSON always says which solution was reached)
//   goal.reached     which one, its 0-based index
//   goal.error       the hand's distance from the goal point there (a workspace goal only)
//   goal.solutions   the inverse-kinematics solutions found before the limits and collisions (workspace)
// Nothing for a goal given as joint angles.
void set_goal_facts(const ArmGoalSet& set, std::size_t reached, Facts& facts);

}  // namespace polyplan
