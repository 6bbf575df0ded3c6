// Python's Plan: any planner's report read the way the JSON writer prints it (the same keys and
// values as `polyplan plan --json -`), with numpy arrays for the path, and polyplan.svg, the
// picture the program draws.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/draw/car_svg.hpp>
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/plan/plan_json.hpp>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

namespace polyplan::python {
namespace {

// A configuration's coordinates as the JSON's "path" prints them.
std::vector<double> coordinates(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }
std::vector<double> coordinates(const Pose& p) { return {to_double(p.position.x), to_double(p.position.y), p.degrees}; }
std::vector<double> coordinates(const JointAngles& q) { return q; }
std::vector<double> coordinates(const CarState& s) { return {s.pose.x, s.pose.y, heading_degrees(s.pose)}; }

// Exact coordinates as the JSON's "path_exact" gives them; joint angles are doubles by nature.
py::object exact(const ExactPoint& p) { return py::make_tuple(fraction(p.x), fraction(p.y)); }
py::object exact(const Pose& p) {
  return py::make_tuple(fraction(p.position.x), fraction(p.position.y), fraction(p.rotation.sin), fraction(p.rotation.cos));
}

template <class Configuration>
py::array_t<double> configurations_array(const std::vector<Configuration>& configurations, std::size_t columns) {
  std::vector<std::vector<double>> rows;
  for (const Configuration& c : configurations) rows.push_back(coordinates(c));
  return rows_array(rows, columns);
}

// Columns of a path array: 2 for points, 3 for poses, the joints for an arm.
std::size_t columns(const PlanResult& r) {
  if (std::holds_alternative<PlanReport<ExactPoint>>(r.report)) return 2;
  if (std::holds_alternative<PlanReport<Pose>>(r.report) || std::holds_alternative<PlanReport<CarState>>(r.report)) return 3;
  return std::get<std::shared_ptr<ArmHandle>>(r.problem)->problem().arm.joints();
}

nlohmann::json json_of(const PlanResult& r) {
  return std::visit([&](const auto& report) { return plan_json(report, r.query); }, r.report);
}

template <class F>
decltype(auto) visit(const PlanResult& r, F&& f) {
  return std::visit([&](const auto& report) -> decltype(auto) { return f(report); }, r.report);
}

py::object graph(const PlanResult& r) {
  return visit(r, [&](const auto& report) -> py::object {
    if (!report.graph) return py::none();
    std::vector<std::vector<double>> edges;
    for (const auto& [a, b] : report.graph->edges) edges.push_back({double(a), double(b)});
    py::array_t<double> pairs = rows_array(edges, 2);
    return py::module_::import("polyplan").attr("Graph")(report.graph->kind, configurations_array(report.graph->vertices, columns(r)),
                                                         pairs.attr("astype")("int64"));
  });
}

py::object cells(const PlanResult& r) {
  return visit(r, [&](const auto& report) -> py::object {
    if (!report.cells) return py::none();
    const CellGrid& c = *report.cells;
    py::array_t<std::uint8_t> states({c.rows, c.columns});
    std::copy(c.states.begin(), c.states.end(), states.mutable_data());
    py::object values = py::none();
    if (!c.values.empty()) {
      py::array_t<float> v({c.rows, c.columns});
      std::copy(c.values.begin(), c.values.end(), v.mutable_data());
      values = v;
    }
    return py::module_::import("polyplan").attr("Cells")(states, c.x0, c.y0, c.cell_width, c.cell_height, values, c.value_name, c.wraps);
  });
}

py::object decomposition(const PlanResult& r) {
  return visit(r, [&](const auto& report) -> py::object {
    if (!report.decomposition) return py::none();
    py::list out;
    for (const auto& cell : report.decomposition->cells) out.append(configurations_array(cell, columns(r)));
    return out;
  });
}

std::string arm_title(const ArmProblem& problem, const PlanResult& r) {
  const std::string file = problem.source.substr(problem.source.find_last_of('/') + 1);
  return file + " · " + r.query + " · " + r.planner;
}

// The program's picture of `plans` (all of one problem and space) in `problem`.
std::string svg_of(py::handle problem, const std::vector<const PlanResult*>& plans, bool strobe) {
  if (py::isinstance<ArmHandle>(problem)) {
    const auto arm = problem.cast<std::shared_ptr<ArmHandle>>();
    if (plans.size() != 1) throw InputError("svg: an arm's picture shows one plan, got " + std::to_string(plans.size()));
    const auto* report = std::get_if<PlanReport<JointAngles>>(&plans[0]->report);
    if (!report) throw InputError("svg: the plan is not an arm's (it was planned in a World)");
    const ArmPictureOptions options{strobe ? ArmPictureOptions::Kind::strobe : ArmPictureOptions::Kind::animation,
                                    arm_title(arm->problem(), *plans[0]), 0, 1, plans[0]->goal_point};
    return locked(arm->lock(), [&] { return draw_plan(arm->problem(), *report, options).str(); });
  }
  if (!py::isinstance<WorldHandle>(problem)) throw InputError("svg: expected a polyplan.World or a polyplan.Arm, got " + type_name(problem));
  const auto world = problem.cast<std::shared_ptr<WorldHandle>>();
  std::vector<PlanReport<ExactPoint>> points;
  std::vector<PlanReport<Pose>> poses;
  std::vector<PlanReport<CarState>> cars;
  for (const PlanResult* p : plans) {
    if (const auto* r = std::get_if<PlanReport<ExactPoint>>(&p->report)) points.push_back(*r);
    else if (const auto* r = std::get_if<PlanReport<Pose>>(&p->report)) poses.push_back(*r);
    else if (const auto* r = std::get_if<PlanReport<CarState>>(&p->report)) cars.push_back(*r);
    else throw InputError("svg: a plan is an arm's (it was planned in an Arm), not a World's");
  }
  if (!points.empty() + !poses.empty() + !cars.empty() > 1)
    throw InputError("svg: the plans mix planners of different spaces (translating, rotation, car)");
  return locked(world->lock(), [&] {
    if (!cars.empty() || world->world().robot.car) return draw_plan(world->world(), cars).str();
    return poses.empty() ? draw_plan(world->cspace(), points).str() : draw_plan(world->world(), poses).str();
  });
}

}  // namespace

py::object from_json(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

void bind_plans(py::module_& m) {
  py::class_<PlanResult>(m, "Plan", R"(One query's answer from a Planner: what `polyplan plan --json -` prints, as Python values.

found, status ("solved", "no_path", "not_found", "limit", "invalid_query", "local_minimum") and
why_not say what became of the query; path is the certified path (a new float64 array); facts
the planner's counts and measures, nested as in the JSON.)")
      .def_property_readonly("found", [](const PlanResult& r) { return visit(r, [](const auto& p) { return p.found; }); },
                             "True when a certified path was found (status \"solved\").")
      .def_property_readonly("status", [](const PlanResult& r) { return visit(r, [](const auto& p) { return std::string(to_string(p.status)); }); },
                             "What became of the query, the JSON's word: solved, no_path, not_found, limit, invalid_query, local_minimum.")
      .def_property_readonly(
          "why_not", [](const PlanResult& r) { return visit(r, [](const auto& p) -> py::object { return p.found ? py::object(py::none()) : py::str(p.why_not); }); },
          "When not found, one sentence saying why; None when found.")
      .def_property_readonly(
          "length", [](const PlanResult& r) { return visit(r, [](const auto& p) -> py::object { return p.found ? py::object(py::float_(p.length)) : py::object(py::none()); }); },
          "The path's length in the planner's metric (Euclidean; an arm's: the sum of the joints' turns); None when not found.")
      .def_property_readonly("path", [](const PlanResult& r) { return visit(r, [&](const auto& p) { return configurations_array(p.path, columns(r)); }); },
                             "The path: a new float64 array of shape (N, 2) for points, (N, 3) [x, y, theta degrees] for poses, "
                             "(N, joints) for an arm; (0, k) when not found.")
      .def_property_readonly(
          "path_exact",
          [](const PlanResult& r) {
            return visit(r, [](const auto& p) -> py::object {
              using Report = std::decay_t<decltype(p)>;
              if constexpr (std::is_same_v<Report, PlanReport<JointAngles>> || std::is_same_v<Report, PlanReport<CarState>>)
                return py::none();
              else {
                py::list out;
                for (const auto& c : p.path) out.append(exact(c));
                return out;
              }
            });
          },
          "The path exactly: a list of tuples of fractions.Fraction, (x, y) for points, (x, y, sin, cos) for poses (the exact "
          "rotation); None for an arm or a car (joint angles and a car's poses are doubles).")
      .def_property_readonly(
          "segments",
          [](const PlanResult& r) -> py::object {
            const nlohmann::json j = json_of(r);
            return j.contains("segments") ? from_json(j["segments"]) : py::object(py::none());
          },
          "A car's path as it drives: a list of dicts {steer: \"L\"|\"S\"|\"R\", gear: 1|-1, length, start: [x, y, theta]}, one per "
          "segment; None for other robots.")
      .def_property_readonly("certified", [](const PlanResult& r) { return visit(r, [](const auto& p) { return p.certificate.certified; }); },
                             "Whether every configuration along the path was proved free (every found path is).")
      .def_property_readonly(
          "certified_by", [](const PlanResult& r) { return visit(r, [](const auto& p) -> py::object { return p.certificate.certified ? py::object(py::str(p.certificate.method)) : py::object(py::none()); }); },
          "How the path was proved free, e.g. \"exact path check (triangulation walk)\"; None when not certified.")
      .def_property_readonly("facts", [](const PlanResult& r) { return from_json(visit(r, [](const auto& p) { return facts_json(p.facts); })); },
                             "The planner's facts as a dict nested as in the JSON: facts[\"search\"][\"expanded\"], facts[\"roadmap\"][\"vertices\"], ...")
      .def_readonly("query", &PlanResult::query, "The query's name (\"start/goal\", \"queries[2]\", ...).")
      .def_readonly("planner", &PlanResult::planner, "The planner's name.")
      .def_property_readonly(
          "problem", [](const PlanResult& r) { return std::visit([](const auto& problem) { return py::cast(problem); }, r.problem); },
          "The World or Arm it was planned in.")
      .def_property_readonly("graph", &graph,
                             "The roadmap or tree when the query recorded one: Graph(kind, vertices (V, k) float64, edges (E, 2) int64); else None.")
      .def_property_readonly(
          "expanded", [](const PlanResult& r) { return visit(r, [&](const auto& p) { return configurations_array(p.expanded, columns(r)); }); },
          "Where the search expanded, in order (recorded queries), an (M, k) float64 array.")
      .def_property_readonly("cells", &cells,
                             "The planner's cells when it has some: Cells(states (rows, columns) uint8 [0 not evaluated, 1 free, "
                             "2 blocked, 3 ridge], x0, y0, cell_width, cell_height, values, value_name, wraps); else None.")
      .def_property_readonly("decomposition", &decomposition, "The convex cells of a decomposition (trapezoids), (n, k) arrays; else None.")
      .def("to_json", [](const PlanResult& r) { return json_of(r).dump(2); },
           "The JSON text `polyplan plan --json -` (or `polyplan arm`) prints for this query.")
      .def("__repr__", [](const PlanResult& r) {
        const nlohmann::json j = json_of(r);
        return "<polyplan.Plan " + r.planner + " " + r.query + ": " + j["status"].get<std::string>() +
               (j["found"].get<bool>() ? ", length " + j["length"].dump() : "") + ">";
      });

  m.def(
      "svg",
      [](const py::object& problem, const py::object& plans, const py::object& strobe) {
        std::vector<const PlanResult*> list;
        if (py::isinstance<PlanResult>(plans)) list.push_back(&plans.cast<const PlanResult&>());
        else if (!plans.is_none()) {
          if (!py::isinstance<py::iterable>(plans)) throw InputError("svg: expected a Plan or a list of Plan, got " + type_name(plans));
          for (py::handle p : plans) {
            if (!py::isinstance<PlanResult>(p)) throw InputError("svg: expected a Plan or a list of Plan, got " + type_name(p));
            list.push_back(&p.cast<const PlanResult&>());
          }
        }
        return svg_of(problem, list, flag_of(strobe, "svg: strobe"));
      },
      py::arg("problem"), py::arg("plans") = py::none(), py::arg("strobe") = false,
      R"(The picture the program draws, as SVG text: a World with its C-space and the plans (one Plan
or a list; the roadmap, cells and searches they recorded), or an Arm's plan as an animation
(strobe=True: every k-th configuration at once; two joints: the torus C-space beside it).)");
}

}  // namespace polyplan::python
