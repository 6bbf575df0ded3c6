// polyplan.check: whether a path is a free motion of the problem's robot, each robot by its own
// motion model and certified as its planners certify: a translating robot's polyline (exact), a
// rotating robot's poses (translations and turns on the spot), a car's segments or poses (arcs and
// straights), an arm's configurations (motions in joint space). A Plan is checked as it was
// planned (its exact path).
#include "exact_values.hpp"
#include "plans.hpp"
#include "problems.hpp"

#include <polyplan/arm/arm_path_check.hpp>
#include <polyplan/car/car_path_check.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/io/car_path_reader.hpp>
#include <polyplan/registry/robot_path_check.hpp>
#include <polyplan/rotation/pose_path_check.hpp>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>

namespace py = pybind11;

namespace polyplan::python {
namespace {

using Rows = std::vector<std::vector<Rational>>;

// How many numbers each configuration of `path` has (a numpy array's columns, a list's first row's
// length), one of `allowed`; InputError naming what was expected and what came.
std::size_t columns_of(const py::handle& path, std::initializer_list<std::size_t> allowed,
                       const std::string& expected) {
  if (py::isinstance<py::str>(path) || (!py::isinstance<py::sequence>(path) && !py::isinstance<py::array>(path)))
    throw InputError("path: expected " + expected + ", got " + type_name(path));
  if (const std::size_t n = py::len(path); n > limits::points)
    throw InputError("path: " + std::to_string(n) + " points, more than the supported " +
                     std::to_string(limits::points));
  std::size_t columns = 0;
  if (py::isinstance<py::array>(path)) {
    const auto array = py::reinterpret_borrow<py::array>(path);
    if (array.ndim() != 2)
      throw InputError("path: expected " + expected + ", got an array of shape " +
                       std::string(py::str(path.attr("shape"))));
    columns = static_cast<std::size_t>(array.shape(1));
  } else {
    if (py::len(path) == 0) throw InputError("path: expected at least one point");
    const py::object first = path[py::int_(0)];
    if (py::isinstance<py::str>(first) || (!py::isinstance<py::sequence>(first) && !py::isinstance<py::array>(first)))
      throw InputError("path[0]: expected " + expected + ", got " + type_name(first));
    columns = py::len(first);
  }
  if (std::find(allowed.begin(), allowed.end(), columns) == allowed.end())
    throw InputError("path: " + std::to_string(columns) + " numbers a configuration: expected " + expected);
  return columns;
}

// The path's rows, exactly; InputError naming a row whose length differs.
Rows exact_rows(const py::handle& path) {
  Rows rows;
  for (const py::handle row : py::iter(path)) {
    rows.push_back(exact_numbers(row, "path[" + std::to_string(rows.size()) + "]"));
    if (rows.back().size() != rows.front().size())
      throw InputError("path[" + std::to_string(rows.size() - 1) + "]: " + std::to_string(rows.back().size()) +
                       " numbers, path[0] " + std::to_string(rows.front().size()));
  }
  if (rows.empty()) throw InputError("path: expected at least one point");
  return rows;
}

PathCheck check_world_rows(WorldHandle& world, const py::handle& path) {
  const World& w = world.world();
  if (w.robot.car) {
    if (py::isinstance<py::list>(path) && py::len(path) > 0 && py::isinstance<py::dict>(path[py::int_(0)])) {
      const std::string text = py::str(py::module_::import("json").attr("dumps")(
          py::dict(py::arg("segments") = py::module_::import("polyplan").attr("_json_value")(path, "path", false))));
      const std::vector<CarPathSegment> segments = parse_car_path(text, "path");
      return locked(world.lock(), [&] { return check_car_path(w, segments); });
    }
    columns_of(path, {3}, "(N, 3) poses (x, y, theta degrees) or a car's segments (Plan.segments)");
    std::vector<CarPose> poses;
    for (const auto& row : exact_rows(path))
      poses.push_back({to_double(row[0]), to_double(row[1]), to_double(row[2]) * pi / 180});
    const auto segments = car_segments_through(poses, w.robot.car->turning_radius);
    return locked(world.lock(), [&] { return check_car_path(w, segments); });
  }
  const std::size_t columns =
      columns_of(path, {2, 3, 4}, "(N, 2) points, (N, 3) poses (x, y, degrees) or (N, 4) (x, y, sin, cos)");
  if (columns == 2) {
    const std::vector<ExactPoint> points = exact_points(path, "path");
    if (points.empty()) throw InputError("path: expected at least one point");
    return locked(world.lock(), [&] { return check_translating_path(world.door(), points); });
  }
  const Rows rows = exact_rows(path);
  std::vector<Pose> poses;
  for (std::size_t i = 0; i < rows.size(); ++i)
    poses.push_back(pose_from_row(rows[i], "path[" + std::to_string(i) + "]"));
  return locked(world.lock(), [&] { return check_pose_path(w, poses); });
}

PathCheck check_arm_rows(ArmHandle& arm, const py::handle& path) {
  if (py::isinstance<py::str>(path) || !py::isinstance<py::iterable>(path))
    throw InputError("path: expected (N, joints) angles, got " + type_name(path));
  std::vector<JointAngles> configurations;
  for (const py::handle row : py::iter(path))
    configurations.push_back(finite_numbers(row, "path[" + std::to_string(configurations.size()) + "]"));
  if (configurations.empty()) throw InputError("path: expected at least one configuration");
  return locked(arm.lock(), [&] { return check_arm_path(arm.problem(), configurations); });
}

// A plan's own path, exactly as its planner made it.
PathCheck check_plan(ProblemHandle& handle, const PlanResult& plan) {
  return locked(handle.lock(), [&]() -> PathCheck {
    return std::visit(
        [&](const auto& report) -> PathCheck {
          using Configuration = typename std::decay_t<decltype(report.path)>::value_type;
          if (report.path.empty()) throw InputError("check: the plan has no path (" + report.why_not + ")");
          if constexpr (std::is_same_v<Configuration, ExactPoint>)
            return check_translating_path(handle.door(), report.path);
          else if constexpr (std::is_same_v<Configuration, Pose>)
            return check_pose_path(*handle.door().world(), report.path);
          else if constexpr (std::is_same_v<Configuration, JointAngles>)
            return check_arm_path(*handle.door().arm(), report.path);
          else {
            std::vector<CarPathSegment> segments;
            for (std::size_t i = 1; i < report.path.size(); ++i)
              segments.push_back({report.path[i - 1].pose, report.path[i].arrival});
            if (segments.empty()) segments.push_back({report.path.front().pose, {Steer::straight, 1, 0}});
            return check_car_path(*handle.door().world(), segments);
          }
        },
        plan.report.typed());
  });
}

py::tuple check(const py::object& problem, const py::object& path) {
  const std::shared_ptr<ProblemHandle> handle = problem_of(problem, "check");
  PathCheck result;
  if (py::isinstance<PlanResult>(path)) {
    const PlanResult& plan = path.cast<const PlanResult&>();
    if (!plan.problem.is(problem)) throw InputError("check: the plan was planned in another problem");
    result = check_plan(*handle, plan);
  } else if (auto arm = std::dynamic_pointer_cast<ArmHandle>(handle)) {
    result = check_arm_rows(*arm, path);
  } else {
    result = check_world_rows(static_cast<WorldHandle&>(*handle), path);
  }
  return py::make_tuple(result.valid, result.reason);
}

}  // namespace

void bind_check(py::module_& m) {
  m.def("check", &check, py::arg("problem"), py::arg("path"),
        R"(Whether `path` is a free motion of the problem's robot, decided as its planners decide it:
(valid, reason), reason "" when valid. path: a Plan (checked as planned); for a World, an (N, 2)
polyline of a translating robot (exact); a rotating robot's (N, 3) poses (x, y, degrees; the exact
rotation the planner uses for that angle) or (N, 4) (x, y, sin, cos) exactly, each step a
translation or a turn on the spot; a car's (N, 3) poses (the straight or arc of its radius between
each two) or its segments (Plan.segments); for an Arm, (N, joints) angles in radians, each motion
certified. Exact numbers as in World.)");
}

}  // namespace polyplan::python
