#pragma once
// A plan as Python holds it: any planner's report (of any configuration space), the query's and
// the planner's names, and the problem it was planned in (kept alive for pictures).
#include "problems.hpp"

#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <nlohmann/json_fwd.hpp>
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace polyplan::python {

using AnyReport = std::variant<PlanReport<ExactPoint>, PlanReport<Pose>, PlanReport<JointAngles>, PlanReport<CarState>>;
using AnyProblem = std::variant<std::shared_ptr<WorldHandle>, std::shared_ptr<ArmHandle>>;

struct PlanResult {
  AnyReport report;
  std::string query;
  std::string planner;
  AnyProblem problem;
  std::optional<WorkspaceGoal> goal_point = std::nullopt;  // an arm query's goal in the workspace: the picture marks it
};

// What Python's Planner holds: one registry planner built for one problem.
class PlannerHandle {
 public:
  virtual ~PlannerHandle() = default;
  // One query: start and goal given (Python objects, converted for the space) — for an arm the goal
  // may be a point for the hand instead (goal_point, goal_orientation) —, or the problem's query
  // named or numbered by `query` (None: its first).
  struct Goal {
    pybind11::object angles, point, orientation;
  };
  virtual PlanResult plan(const pybind11::object& start, const Goal& goal, const pybind11::object& query, bool record) = 0;
  // Every query of the problem, checked first as `polyplan plan` checks them.
  virtual std::vector<PlanResult> plan_all(bool record) = 0;
  virtual std::string space() const = 0;
  std::string name;
};

// The planner `name` of whichever space plans in `problem` (a World or an Arm), with `options`
// (a dict of Python values, given as keyword arguments). InputError for an unknown planner, one
// of another space, an unknown option or a value it refuses.
std::unique_ptr<PlannerHandle> make_planner(const std::string& name, pybind11::handle problem, const pybind11::dict& options);

void bind_plans(pybind11::module_& m);
void bind_planners(pybind11::module_& m);
void bind_replan(pybind11::module_& m);
void bind_potential(pybind11::module_& m);
void bind_search(pybind11::module_& m);

// A JSON value as Python's json.loads reads it (dicts, lists, numbers, strings).
pybind11::object from_json(const nlohmann::json& value);

}  // namespace polyplan::python
