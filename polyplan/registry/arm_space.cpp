// The front door of a planar n-link arm.
#include <polyplan/registry/detail/space_door.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>

#include <cstdio>

namespace polyplan::detail {
namespace {

JointAngles joint_angles(const std::vector<Rational>& numbers, const std::string& what, const ArmProblem& problem) {
  const std::size_t joints = problem.arm.joints();
  if (numbers.size() != joints)
    throw InputError(what + ": expected " + std::to_string(joints) + " joint angles (radians), got " +
                     std::to_string(numbers.size()));
  JointAngles angles;
  for (const Rational& a : numbers) angles.push_back(to_double(a));
  return angles;
}

// The hand at a point (and at an orientation), kept exactly as given, as the arm reader keeps it.
WorkspaceGoal hand_goal(const QuerySpec& spec) {
  if (spec.goal_point.size() != 2)
    throw InputError("goal_point: expected (x, y), got " + std::to_string(spec.goal_point.size()) + " number(s)");
  const ExactPoint at{spec.goal_point[0], spec.goal_point[1]};
  WorkspaceGoal goal{{to_double(at.x), to_double(at.y)}, std::nullopt, at};
  if (spec.goal_orientation) goal.orientation = to_double(*spec.goal_orientation);
  return goal;
}

class ArmDoor final : public SpaceDoor<PlanarArm> {
 public:
  std::string_view kind() const override { return "Arm"; }
  std::string_view file() const override { return "ARM.json"; }
  bool plans(const Problem& problem) const override { return problem.arm() != nullptr; }
  const ArmProblem& built_from(const Problem& problem) const override { return *problem.arm(); }
  ArmQuery own_query(const Problem& problem, std::size_t index) const override {
    return problem.arm()->queries.at(index);
  }

  // The goal as joint angles, or as the hand at a point, as an arm file gives it.
  ArmQuery query(const Problem& problem, const QuerySpec& spec) const override {
    const bool point = !spec.goal_point.empty();
    if (point && !spec.goal.empty())
      throw InputError("give goal or goal_point, not both: a query's goal is joint angles or the hand at a point");
    if (spec.goal_orientation && !point)
      throw InputError("goal_orientation given without goal_point (it is the hand's orientation at that point)");
    ArmQuery q{spec.name, joint_angles(spec.start, "start", *problem.arm()), {}};
    if (point) q.goal_point = hand_goal(spec);
    else q.goal = joint_angles(spec.goal, "goal", *problem.arm());
    return q;
  }

  void require_plannable(const Problem& problem, std::string_view) const override {
    if (problem.arm()->queries.empty()) throw InputError(problem.source() + ": no start/goal and no queries to plan");
  }
  std::string default_planner(const Problem&) const override { return planners<PlanarArm>().default_planner(); }

  std::size_t columns(const Problem& problem) const override { return problem.arm()->arm.joints(); }
  std::string_view steps() const override { return "motion"; }
  std::string_view unit() const override { return " rad"; }

  // A path to a goal point: which inverse-kinematics solution it reached, and how near the hand is.
  std::string summary(const Facts& facts) const override {
    const auto error = facts.find(GoalFacts::error);
    const auto reached = facts.find(GoalFacts::reached), candidates = facts.find(GoalFacts::candidates);
    if (!error || !reached || !candidates) return "";
    char goal[160];
    std::snprintf(goal, sizeof goal,
                  ", ends at IK solution %lld of %lld (goal.reached %lld), the hand %.2g from the goal point",
                  static_cast<long long>(*reached + 1), static_cast<long long>(*candidates),
                  static_cast<long long>(*reached), *error);
    return goal;
  }
};

}  // namespace

template <>
const SpaceDoor<PlanarArm>& space_door<PlanarArm>() {
  static const ArmDoor door;
  return door;
}

}  // namespace polyplan::detail
