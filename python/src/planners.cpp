// Every planner of the registries in Python through one generic binding: polyplan.planner(name,
// problem, **options) builds any planner of planners<Space>() for the space that plans in the
// problem, and polyplan.planners() lists them. Nothing here names a planner: adding one to the
// registry adds it to Python.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <pybind11/stl.h>

#include <cmath>

namespace polyplan::python {
namespace {

// What differs between the spaces in Python: the handle planners are built from, and queries.
template <class Space>
struct PythonSpace;

// (x, y) or (x, y, theta): the position, and theta (degrees) when given.
std::pair<ExactPoint, std::optional<double>> pose_of(py::handle value, const std::string& what) {
  if (py::isinstance<py::array>(value) || PySequence_Check(value.ptr()))
    if (!py::isinstance<py::str>(value) && py::len(value) == 3) {
      const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
      const double theta = finite_number(s[2], what + "[2] (theta, degrees)");
      if (std::abs(theta) > 1e6) throw InputError(what + "[2]: theta " + std::to_string(theta) + " degrees: expected an angle within ±1e6 degrees");
      return {exact_point(py::make_tuple(s[0], s[1]), what), theta};
    }
  return {exact_point(value, what), std::nullopt};
}

template <>
struct PythonSpace<TranslatingRobot> {
  using Handle = WorldHandle;
  static const CSpace& problem(WorldHandle& world) { return world.cspace(); }
  static const std::vector<Query>& queries(const WorldHandle& world) { return world.world().queries; }
  static Query query(py::handle start, py::handle goal, const WorldHandle&) {
    const auto [from, from_theta] = pose_of(start, "start");
    const auto [to, to_theta] = pose_of(goal, "goal");
    for (const auto& [what, theta] : {std::pair{"start", from_theta}, std::pair{"goal", to_theta}})
      if (turned(theta))
        throw InputError(std::string(what) + ": an orientation other than 0 degrees; a translating planner moves the robot as "
                         "its file draws it: use planner=\"rotation\"");
    return Query{from, to, "start/goal"};
  }
  static void require_plannable(WorldHandle& world, const std::string& planner) {
    require_plannable_queries(world.world(), &world.cspace(), planner);
  }
  static void require_fits(const WorldHandle& world, const std::string& planner) { require_planner_for_robot(world.world(), planner); }
};

template <>
struct PythonSpace<RotatingRobot> {
  using Handle = WorldHandle;
  static const World& problem(WorldHandle& world) { return world.world(); }
  static const std::vector<Query>& queries(const WorldHandle& world) { return world.world().queries; }
  static Query query(py::handle start, py::handle goal, const WorldHandle&) {
    Query q;
    std::tie(q.start, q.start_theta) = pose_of(start, "start");
    std::tie(q.goal, q.goal_theta) = pose_of(goal, "goal");
    q.name = "start/goal";
    return q;
  }
  static void require_plannable(WorldHandle& world, const std::string& planner) {
    require_plannable_queries(world.world(), nullptr, planner);
  }
  static void require_fits(const WorldHandle& world, const std::string& planner) { require_planner_for_robot(world.world(), planner); }
};

template <>
struct PythonSpace<SteeredCar> {
  using Handle = WorldHandle;
  static const World& problem(WorldHandle& world) { return world.world(); }
  static const std::vector<Query>& queries(const WorldHandle& world) { return world.world().queries; }
  static Query query(py::handle start, py::handle goal, const WorldHandle& world) {
    Query q = PythonSpace<RotatingRobot>::query(start, goal, world);
    if (!q.start_theta || !q.goal_theta) throw InputError(std::string(q.start_theta ? "goal" : "start") + ": a car's pose is (x, y, theta), theta in degrees");
    return q;
  }
  static void require_plannable(WorldHandle& world, const std::string& planner) {
    require_plannable_queries(world.world(), nullptr, planner);
  }
  static void require_fits(const WorldHandle& world, const std::string& planner) { require_planner_for_robot(world.world(), planner); }
};

template <>
struct PythonSpace<PlanarArm> {
  using Handle = ArmHandle;
  static const ArmProblem& problem(ArmHandle& arm) { return arm.problem(); }
  static const std::vector<ArmQuery>& queries(const ArmHandle& arm) { return arm.problem().queries; }
  // The goal as joint angles, or as the hand at a point (goal_point, and goal_orientation there,
  // radians), as an arm file gives it.
  static ArmQuery query(py::handle start, const PlannerHandle::Goal& goal, const ArmHandle& arm) {
    const bool point = !goal.point.is_none();
    if (point && !goal.angles.is_none())
      throw InputError("plan: give goal or goal_point, not both: a query's goal is joint angles or the hand at a point");
    if (!goal.orientation.is_none() && !point)
      throw InputError("plan: goal_orientation given without goal_point (it is the hand's orientation at that point)");
    ArmQuery q{"start/goal", angles(start, "start", arm), {}};
    if (!point) {
      q.goal = angles(goal.angles, "goal", arm);
      return q;
    }
    const std::vector<double> at = finite_numbers(goal.point, "goal_point");
    if (at.size() != 2) throw InputError("goal_point: expected (x, y), got " + std::to_string(at.size()) + " number(s)");
    q.goal_point = WorkspaceGoal{{at[0], at[1]}, std::nullopt};
    if (!goal.orientation.is_none()) q.goal_point->orientation = finite_number(goal.orientation, "goal_orientation");
    return q;
  }
  static JointAngles angles(py::handle value, const std::string& what, const ArmHandle& arm) {
    JointAngles q = finite_numbers(value, what);
    const std::size_t joints = arm.problem().arm.joints();
    if (q.size() != joints)
      throw InputError(what + ": expected " + std::to_string(joints) + " joint angles (radians), got " + std::to_string(q.size()));
    return q;
  }
  static void require_fits(const ArmHandle&, const std::string&) {}
  static void require_plannable(ArmHandle& arm, const std::string&) {
    if (arm.problem().queries.empty()) throw InputError(arm.problem().source + ": no start/goal and no queries to plan");
  }
};

// A keyword argument as the option text the registry parses: True/False, an int, a float (its
// shortest round-trip text), a Fraction (as a float) or a string; nothing else.
std::string option_text(const std::string& planner, const std::string& key, py::handle value) {
  if (PyBool_Check(value.ptr())) return value.ptr() == Py_True ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (PyIndex_Check(value.ptr())) return py::str(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())));
  if (PyFloat_Check(value.ptr()) || py::isinstance(value, py::module_::import("numbers").attr("Real")))
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));
  throw InputError("planner " + planner + ": option " + key + "=" + std::string(py::repr(value)) +
                   ": expected a number, text, True or False, got " + type_name(value));
}

OptionValues option_values(const std::string& planner, const py::dict& options) {
  OptionValues values;
  for (const auto& [key, value] : options) {
    const std::string name = py::str(key);
    values.emplace_back(name, option_text(planner, name, value));
  }
  return values;
}

template <class Space>
class PlannerOf final : public PlannerHandle {
 public:
  using Handle = typename PythonSpace<Space>::Handle;

  PlannerOf(const PlannerEntry<Space>& entry, std::shared_ptr<Handle> handle, const OptionValues& options)
      : handle_(std::move(handle)) {
    name = entry.name;
    PythonSpace<Space>::require_fits(*handle_, name);
    planner_ = locked(handle_->lock(), [&] { return entry.make(PythonSpace<Space>::problem(*handle_), options); });
  }

  PlanResult plan(const py::object& start, const Goal& goal, const py::object& query, bool record) override {
    const auto q = chosen_query(start, goal, query);
    return result(locked(handle_->lock(), [&] { return planner_->plan(q, QueryOptions{record}); }), q);
  }

  std::vector<PlanResult> plan_all(bool record) override {
    std::vector<PlanReport<typename Space::Configuration>> reports = locked(handle_->lock(), [&] {
      PythonSpace<Space>::require_plannable(*handle_, name);
      std::vector<PlanReport<typename Space::Configuration>> all;
      for (const auto& q : PythonSpace<Space>::queries(*handle_)) all.push_back(planner_->plan(q, QueryOptions{record}));
      return all;
    });
    std::vector<PlanResult> results;
    for (std::size_t i = 0; i < reports.size(); ++i) results.push_back(result(std::move(reports[i]), PythonSpace<Space>::queries(*handle_)[i]));
    return results;
  }

  std::string space() const override { return std::string(Space::description); }

 private:
  typename Space::Query chosen_query(py::handle start, const Goal& goal, py::handle query) const {
    constexpr bool arm = std::is_same_v<Handle, ArmHandle>;
    const bool point = !goal.point.is_none() || !goal.orientation.is_none();
    if (point && !arm) throw InputError("plan: goal_point and goal_orientation are an arm's (its hand at a point), not a World's");
    if (!start.is_none() || !goal.angles.is_none() || point) {
      if (start.is_none() || (goal.angles.is_none() && goal.point.is_none()))
        throw InputError(arm ? "plan: give both start and goal (or goal_point), or neither (the problem's own query)"
                             : "plan: give both start and goal, or neither (the problem's own query)");
      if (!query.is_none()) throw InputError("plan: give start and goal, or query, not both");
      if constexpr (arm) return PythonSpace<Space>::query(start, goal, *handle_);
      else return PythonSpace<Space>::query(start, goal.angles, *handle_);
    }
    const auto& queries = PythonSpace<Space>::queries(*handle_);
    if (queries.empty()) throw InputError("plan: " + source() + " has no query: give start and goal");
    if (query.is_none()) return queries.front();
    if (py::isinstance<py::str>(query)) {
      for (const auto& q : queries)
        if (q.name == query.cast<std::string>()) return q;
      throw InputError("plan: " + source() + " has no query named " + query.cast<std::string>());
    }
    if (!PyIndex_Check(query.ptr()) || PyBool_Check(query.ptr()))
      throw InputError("plan: query: expected a query's name or index, got " + type_name(query));
    const long long i = py::int_(py::reinterpret_borrow<py::object>(query));
    if (i < 0 || static_cast<std::size_t>(i) >= queries.size())
      throw InputError("plan: query " + std::to_string(i) + ": " + source() + " has " + std::to_string(queries.size()) + " query(ies)");
    return queries[static_cast<std::size_t>(i)];
  }

  std::string source() const {
    if constexpr (std::is_same_v<Handle, WorldHandle>) return handle_->world().source;
    else return handle_->problem().source;
  }

  PlanResult result(PlanReport<typename Space::Configuration> report, const typename Space::Query& query) const {
    PlanResult r{std::move(report), query.name, name, handle_};
    if constexpr (std::is_same_v<Handle, ArmHandle>) r.goal_point = query.goal_point;
    return r;
  }

  std::shared_ptr<Handle> handle_;
  std::unique_ptr<Planner<Space>> planner_;
};

template <class Space>
std::unique_ptr<PlannerHandle> make_if_named(const std::string& name, const std::shared_ptr<typename PythonSpace<Space>::Handle>& handle,
                                             const py::dict& options) {
  const PlannerEntry<Space>* entry = planners<Space>().find(name);
  if (!entry) return nullptr;
  const OptionValues values = option_values(name, options);
  return std::make_unique<PlannerOf<Space>>(*entry, handle, values);
}

// An unknown name: one of the other kind of problem's planners, or none at all.
std::unique_ptr<PlannerHandle> unknown(const std::string& name, bool arm) {
  const bool world_planner =
      planners<TranslatingRobot>().find(name) || planners<RotatingRobot>().find(name) || planners<SteeredCar>().find(name);
  const bool arm_planner = planners<PlanarArm>().find(name) != nullptr;
  if (arm && world_planner) throw InputError("planner " + name + " plans in a World (polyplan.read_world), not in an Arm");
  if (!arm && arm_planner) throw InputError("planner " + name + " plans for an Arm (polyplan.read_arm), not in a World");
  std::string names = arm ? planners<PlanarArm>().names() : planners<TranslatingRobot>().names() + ", " + planners<RotatingRobot>().names();
  if (!arm)  // the car's own (its sampling planners are named already)
    for (const auto& entry : planners<SteeredCar>().entries())
      if (!planners<TranslatingRobot>().find(entry.name)) names += ", " + entry.name;
  throw InputError("unknown planner \"" + name + "\" for a" + (arm ? "n Arm" : " World") + " (" + names + ")");
}

}  // namespace

std::unique_ptr<PlannerHandle> make_planner(const std::string& name, py::handle problem, const py::dict& options) {
  if (py::isinstance<WorldHandle>(problem)) {
    const auto world = problem.cast<std::shared_ptr<WorldHandle>>();
    // A car's world plans in the car's space first: rrt and its kin are registered for both.
    if (world->world().robot.car)
      if (auto p = make_if_named<SteeredCar>(name, world, options)) return p;
    if (auto p = make_if_named<TranslatingRobot>(name, world, options)) return p;
    if (auto p = make_if_named<RotatingRobot>(name, world, options)) return p;
    if (auto p = make_if_named<SteeredCar>(name, world, options)) return p;
    return unknown(name, false);
  }
  if (py::isinstance<ArmHandle>(problem)) {
    if (auto p = make_if_named<PlanarArm>(name, problem.cast<std::shared_ptr<ArmHandle>>(), options)) return p;
    return unknown(name, true);
  }
  throw InputError("expected a polyplan.World or a polyplan.Arm to plan in, got " + type_name(problem));
}

namespace {

template <class Space>
void list_space(py::list& out) {
  for (const auto& entry : planners<Space>().entries()) {
    py::list options;
    for (const OptionInfo& o : entry.options) options.append(py::make_tuple(o.name, o.kind, o.default_value, o.description));
    out.append(py::make_tuple(entry.name, std::string(Space::description), entry.description, options));
  }
}

}  // namespace

void bind_planners(py::module_& m) {
  py::class_<PlannerHandle>(m, "Planner", R"(A planner of the registry built once for one World or Arm (polyplan.planner).

Its roadmap, diagram or grid is built with it; each plan() answers one query with it. One
planner answers one query at a time; planners of different problems plan in parallel in
different threads (the GIL is released while planning).)")
      .def_readonly("name", &PlannerHandle::name, "The planner's name in the registry.")
      .def_property_readonly("space", &PlannerHandle::space, "The configuration space it plans in.")
      .def("plan",
           [](PlannerHandle& p, const py::object& start, const py::object& goal, const py::object& query, const py::object& record,
              const py::object& goal_point, const py::object& goal_orientation) {
             return p.plan(start, {goal, goal_point, goal_orientation}, query, flag_of(record, "plan: record"));
           },
           py::arg("start") = py::none(), py::arg("goal") = py::none(), py::arg("query") = py::none(),
           py::arg("record") = true, py::arg("goal_point") = py::none(), py::arg("goal_orientation") = py::none(),
           R"(One query answered: a Plan.

start, goal: (x, y) for a translating robot, (x, y) or (x, y, theta) (degrees) for the rotation
planner, a sequence of joint angles (radians) for an arm; exact numbers as in World. Omitted: the
problem's own query, the first one or the one `query` names (its name or index). A start or goal
that is not free is an answer (status "invalid_query"), not an error. record: keep the roadmap
or tree, the expanded configurations and the cells for polyplan.plot and polyplan.svg.
goal_point=(x, y), goal_orientation=radians (an arm only, instead of goal): the hand at that
point (with the last link at that absolute angle); the planner plans to the collision-free
inverse-kinematics solutions, and the Plan's facts["goal"] says which it reached (an unreachable
point is an answer: status "no_path").)")
      .def("plan_all", [](PlannerHandle& p, const py::object& record) { return p.plan_all(flag_of(record, "plan_all: record")); },
           py::arg("record") = true,
           "Every query of the problem (checked as `polyplan plan` checks them: InputError for one that is not free): a list of Plan.")
      .def("__repr__", [](const PlannerHandle& p) { return "<polyplan.Planner " + p.name + " for " + p.space() + ">"; });

  // polyplan.planner in __init__.py (which documents it) calls this with the options as a dict.
  m.def("_planner", [](const py::object& name, const py::object& problem, const py::dict& options) {
    return make_planner(text_of(name, "planner: name"), problem, options);
  });
  m.def("_planner_list", [] {
    py::list out;
    list_space<TranslatingRobot>(out);
    list_space<RotatingRobot>(out);
    list_space<SteeredCar>(out);
    list_space<PlanarArm>(out);
    return out;
  });
}

}  // namespace polyplan::python
