#include <polyplan/arm/arm_goal_set.hpp>

#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/inverse_kinematics.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <algorithm>
#include <stdexcept>

namespace polyplan {
namespace {

// The end-effector errors of a workspace goal's configurations: what the refinement aims at (well
// below 1e-12, so that the normalised angles' rounding keeps them there; damped least squares
// converges quadratically, and gets there in a step or two), and the most it accepts (a solution it
// could not bring nearer, beside a singular configuration).
constexpr double aimed_error = 1e-14, accepted_error = 1e-9;

std::string point_text(const Eigen::Vector2d& p) {
  return "(" + detail::show_number(p.x()) + ", " + detail::show_number(p.y()) + ")";
}

std::string goal_text(const WorkspaceGoal& goal) {
  std::string text = "the point " + point_text(goal.point);
  if (goal.orientation) text += " with the last link at " + detail::show_number(*goal.orientation) + " rad";
  return text;
}

IkOptions ik_options(const Arm& arm, const WorkspaceGoal& goal, std::size_t seeds) {
  IkOptions options;
  options.orientation = goal.orientation;
  options.exact_target = goal.exact_point;
  options.limits = arm.limits;
  options.seeds = seeds;
  options.all = true;
  options.tolerance = accepted_error;
  options.refine_to = aimed_error;
  return options;
}

// Why a reachable point has no goal: what inverse kinematics found, and what became of it.
std::string why_none(const WorkspaceGoal& goal, const IkAnswer& answer, std::size_t colliding, std::size_t inaccurate) {
  const std::string within = goal_text(goal) + " is within the arm's reach, but ";
  if (!answer.found) return within + "inverse kinematics found no configuration there (" + answer.why_not + ")";
  const std::size_t tried = answer.solutions.size() + answer.outside_limits;
  std::string why = within + "none of the " + std::to_string(tried) +
                    " inverse-kinematics solution(s) found is a goal: " + std::to_string(colliding) + " collide";
  if (answer.outside_limits > 0) why += ", " + std::to_string(answer.outside_limits) + " lie outside the joint limits";
  if (inaccurate > 0) why += ", " + std::to_string(inaccurate) + " miss the point by more than 1e-9";
  return why + (answer.every_solution ? " (every solution there is)"
                                      : "; a free configuration the seeds missed may still exist");
}

ArmGoalSet workspace_goal_set(const ArmCollisionChecker& checker, const WorkspaceGoal& goal, std::size_t seeds) {
  const Arm& arm = checker.arm();
  ArmGoalSet set;
  set.workspace = true;
  const HandReach reach = hand_reach(arm, goal.point, goal.exact_point);
  if (!reach.reachable()) {
    set.status = PlanStatus::no_path;
    set.why_none = "the point " + point_text(goal.point) + " is out of reach: the arm reaches distances " +
                   detail::show_number(reach.inner) + " to " + detail::show_number(reach.outer) + " from its base";
    return set;
  }
  const IkAnswer answer = inverse_kinematics(arm, goal.point, ik_options(arm, goal, seeds));
  std::size_t colliding = 0, inaccurate = 0;
  if (answer.found) {
    set.solutions = answer.solutions.size() + answer.outside_limits;
    for (const IkSolution& solution : answer.solutions) {
      // Measured again where the planners' paths end: at the normalised angles.
      ArmGoal candidate{normalize_angles(solution.angles), 0};
      candidate.error = (joint_positions(arm, candidate.angles).back() - goal.point).norm();
      if (candidate.error > accepted_error) ++inaccurate;
      else if (!checker.is_free(candidate.angles)) ++colliding;
      else set.goals.push_back(std::move(candidate));
    }
  }
  if (set.goals.empty()) {
    set.status = PlanStatus::not_found;
    set.why_none = why_none(goal, answer, colliding, inaccurate);
  }
  return set;
}

}  // namespace

std::vector<JointAngles> ArmGoalSet::configurations() const {
  std::vector<JointAngles> out;
  out.reserve(goals.size());
  for (const ArmGoal& g : goals) out.push_back(g.angles);
  return out;
}

std::size_t ArmGoalSet::index_of(const JointAngles& configuration) const {
  const auto found =
      std::find_if(goals.begin(), goals.end(), [&](const ArmGoal& g) { return g.angles == configuration; });
  if (found == goals.end())
    throw std::logic_error("a path ends at a configuration that is not one of its query's goals");
  return static_cast<std::size_t>(found - goals.begin());
}

ArmGoalSet arm_goal_set(const ArmCollisionChecker& checker, const ArmQuery& query, std::size_t seeds) {
  if (query.goal_point) return workspace_goal_set(checker, *query.goal_point, seeds);
  ArmGoalSet set;
  set.goals.push_back({normalize_angles(query.goal), 0});
  return set;
}

void set_goal_facts(const ArmGoalSet& set, std::size_t reached, Facts& facts) {
  if (!set.workspace) return;
  facts.set(GoalFacts::candidates, set.goals.size());
  facts.set(GoalFacts::reached, reached);
  facts.set(GoalFacts::error, set.goals.at(reached).error);
  facts.set(GoalFacts::solutions, set.solutions);
}

}  // namespace polyplan
