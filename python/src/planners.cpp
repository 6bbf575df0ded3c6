// Every planner of the registry in Python through the front door (registry/any_planner.hpp):
// polyplan.planner(name, problem, **options) builds the planner `name` for a World or an Arm, and
// polyplan.planners() lists them. Nothing here names a planner, a space or a default: adding one
// to the registry adds it to Python.
#include "exact_values.hpp"
#include "keyword_options.hpp"
#include "plans.hpp"

#include <polyplan/geometry/rational.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <pybind11/stl.h>

#include <algorithm>

namespace polyplan::python {
namespace {

// Python's Planner: a planner of the registry built once for one World or Arm.
struct PlannerHandle {
  std::unique_ptr<AnyPlanner> planner;
  std::shared_ptr<ProblemHandle> handle;
  py::object problem;    // the World or Arm
  OptionValues options;  // those given that differ from the defaults

  // The problem's own query number `query` names (its name or index; None: the first).
  std::size_t own_query(py::handle query) const {
    const std::vector<std::string> names = handle->door().query_names();
    const std::string& source = handle->door().source();
    if (names.empty()) throw InputError("plan: " + source + " has no query: give start and goal");
    if (query.is_none()) return 0;
    if (py::isinstance<py::str>(query)) {
      const std::string name = text_of(query, "plan: query");
      const auto at = std::find(names.begin(), names.end(), name);
      if (at == names.end()) throw InputError("plan: " + source + " has no query named " + name);
      return static_cast<std::size_t>(at - names.begin());
    }
    if (!PyIndex_Check(query.ptr()) || PyBool_Check(query.ptr()))
      throw InputError("plan: query: expected a query's name or index, got " + type_name(query));
    const long long i = py::int_(py::reinterpret_borrow<py::object>(query));
    if (i < 0 || static_cast<std::size_t>(i) >= names.size())
      throw InputError("plan: query " + std::to_string(i) + ": " + source + " has " + std::to_string(names.size()) +
                       " query(ies)");
    return static_cast<std::size_t>(i);
  }

  PlanResult answer(Report report) const { return {std::move(report), problem, options, std::nullopt}; }

  // `ask(planner)` with the problem's lock held and the GIL released; the door's InputError as the
  // message of plan().
  template <class Ask>
  auto asked(Ask ask) const {
    try {
      return locked(handle->lock(), [&] { return ask(*planner); });
    } catch (const InputError& e) {
      throw InputError("plan: " + std::string(e.what()));
    }
  }
};

struct Goal {
  py::object angles, point, orientation;
};

QuerySpec query_spec(const py::object& start, const Goal& goal) {
  QuerySpec spec;
  spec.start = exact_numbers(start, "start");
  if (!goal.angles.is_none()) spec.goal = exact_numbers(goal.angles, "goal");
  if (!goal.point.is_none()) spec.goal_point = exact_numbers(goal.point, "goal_point");
  if (!goal.orientation.is_none()) spec.goal_orientation = exact_number(goal.orientation, "goal_orientation");
  return spec;
}

PlanResult plan(const PlannerHandle& p, const py::object& start, const Goal& goal, const py::object& query,
                bool record) {
  const bool own = start.is_none() && goal.angles.is_none() && goal.point.is_none() && goal.orientation.is_none();
  if (own) {
    const std::size_t index = p.own_query(query);
    return p.answer(p.asked([&](AnyPlanner& planner) { return planner.plan(index, QueryOptions{record}); }));
  }
  if (start.is_none() || (goal.angles.is_none() && goal.point.is_none()))
    throw InputError("plan: give both start and goal (or goal_point), or neither (the problem's own query)");
  if (!query.is_none()) throw InputError("plan: give start and goal, or query, not both");
  const QuerySpec spec = query_spec(start, goal);
  return p.answer(p.asked([&](AnyPlanner& planner) { return planner.plan(spec, QueryOptions{record}); }));
}

std::vector<PlanResult> plan_all(const PlannerHandle& p, bool record) {
  std::vector<Report> reports = locked(p.handle->lock(), [&] {
    p.planner->require_plannable();
    std::vector<Report> all;
    for (std::size_t i = 0; i < p.handle->door().query_names().size(); ++i)
      all.push_back(p.planner->plan(i, QueryOptions{record}));
    return all;
  });
  std::vector<PlanResult> results;
  for (Report& r : reports) results.push_back(p.answer(std::move(r)));
  return results;
}

// "0" and "0.0" are one number; texts that are not numbers compare as text.
bool same_value(const std::string& a, const std::string& b) {
  const auto x = parse_rational(a), y = parse_rational(b);
  return x && y ? *x == *y : a == b;
}

// The options whose value differs from the option's default (seed=1 given for a default seed of 1 is
// not worth a label).
OptionValues not_defaults(const PlannerListing& planner, const OptionValues& values) {
  OptionValues out;
  for (const auto& given : values) {  // not a structured binding: clang 14 cannot capture one
    const auto option = std::find_if(planner.options.begin(), planner.options.end(),
                                     [&](const OptionInfo& o) { return o.name == given.first; });
    if (option == planner.options.end() || !same_value(option->default_value, given.second)) out.push_back(given);
  }
  return out;
}

PlannerHandle make(const std::string& name, const py::object& problem, const py::dict& options) {
  PlannerHandle p{nullptr, problem_of(problem, "planner"), problem, {}};
  const std::string planner = name.empty() ? default_planner(p.handle->door()) : name;
  const PlannerListing& listing = planner_for(planner, p.handle->door());
  const OptionValues values = keyword_options("planner " + listing.name, listing.options, options);
  p.options = not_defaults(listing, values);
  p.planner = locked(p.handle->lock(), [&] { return make_planner(planner, p.handle->door(), values); });
  return p;
}

py::tuple option_tuple(const OptionInfo& o) {
  const py::object range =
      o.range ? py::object(py::make_tuple(o.range->min, o.range->max, o.range->min_open, o.range->max_open))
              : py::none();
  return py::make_tuple(o.name, o.kind, o.default_value, o.description, range, o.choices);
}

}  // namespace

void bind_planners(py::module_& m) {
  py::class_<PlannerHandle>(m, "Planner",
                            R"(A planner of the registry built once for one World or Arm (polyplan.planner).

Its roadmap, diagram or grid is built with it; each plan() answers one query with it. One
planner answers one query at a time; planners of different problems plan in parallel in
different threads (the GIL is released while planning).)")
      .def_property_readonly(
          "name", [](const PlannerHandle& p) { return p.planner->name(); }, "The planner's name in the registry.")
      .def_property_readonly(
          "space", [](const PlannerHandle& p) { return p.planner->listing().space; },
          "The configuration space it plans in.")
      .def(
          "plan",
          [](const PlannerHandle& p, const py::object& start, const py::object& goal, const py::object& query,
             const py::object& record, const py::object& goal_point, const py::object& goal_orientation) {
            return plan(p, start, {goal, goal_point, goal_orientation}, query, flag_of(record, "plan: record"));
          },
          py::arg("start") = py::none(), py::arg("goal") = py::none(), py::arg("query") = py::none(),
          py::arg("record") = true, py::arg("goal_point") = py::none(), py::arg("goal_orientation") = py::none(),
          R"(One query answered: a Plan.

start, goal: (x, y) for a translating robot, (x, y) or (x, y, theta) (degrees) for the rotation
planner and a car, a sequence of joint angles (radians) for an arm; exact numbers as in World.
Omitted: the problem's own query, the first one or the one `query` names (its name or index). A
start or goal that is not free is an answer (status "invalid_query"), not an error. record: keep
the roadmap or tree, the expanded configurations and the cells for polyplan.plot and polyplan.svg.
goal_point=(x, y), goal_orientation=radians (an arm only, instead of goal): the hand at that
point (with the last link at that absolute angle); the planner plans to the collision-free
inverse-kinematics solutions, and the Plan's facts["goal"] says which it reached (an unreachable
point is an answer: status "no_path").)")
      .def(
          "plan_all",
          [](const PlannerHandle& p, const py::object& record) {
            return plan_all(p, flag_of(record, "plan_all: record"));
          },
          py::arg("record") = true,
          "Every query of the problem (checked as `polyplan plan` checks them: InputError for one that is not free): a "
          "list of Plan.")
      .def("__repr__", [](const PlannerHandle& p) {
        return "<polyplan.Planner " + p.planner->name() + " for " + p.planner->listing().space + ">";
      });

  // polyplan.planner and polyplan.plan in __init__.py (which document them) call this with the
  // options as a dict; an empty name is the problem's default planner.
  m.def("_planner", [](const py::object& name, const py::object& problem, const py::dict& options) {
    return make(name.is_none() ? std::string() : text_of(name, "planner: name"), problem, options);
  });
  m.def("_planner_list", [] {
    py::list out;
    for (const PlannerListing& planner : planner_catalog()) {
      py::list options;
      for (const OptionInfo& o : planner.options) options.append(option_tuple(o));
      out.append(py::make_tuple(planner.name, planner.space, planner.description, options));
    }
    return out;
  });
}

}  // namespace polyplan::python
