// Python's Plan: any planner's report read the way the JSON writer prints it (the same keys and
// values as `polyplan plan --json -`), with numpy arrays for the path, and polyplan.svg, the
// picture the program draws.
#include "plans.hpp"
#include "exact_values.hpp"

#include <polyplan/draw/report_pictures.hpp>
#include <polyplan/plan/plan_json.hpp>

#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

namespace polyplan::python {
namespace {

py::array_t<double> rows_of(const Rows& rows, std::size_t columns) { return rows_array(rows, columns); }

py::object graph(const PlanResult& r) {
  const Recording& recorded = r.recorded();
  if (recorded.graph_kind.empty()) return py::none();
  std::vector<std::vector<double>> edges;
  for (const auto& [a, b] : recorded.graph_edges) edges.push_back({double(a), double(b)});
  py::array_t<double> pairs = rows_array(edges, 2);
  const py::object kinds =
      recorded.graph_edge_kinds.empty() ? py::object(py::none()) : py::object(py::cast(recorded.graph_edge_kinds));
  return py::module_::import("polyplan")
      .attr("Graph")(recorded.graph_kind, rows_of(recorded.graph_vertices, r.report.path_columns()),
                     pairs.attr("astype")("int64"), kinds);
}

py::object cells(const PlanResult& r) {
  const std::shared_ptr<const CellGrid> grid = r.recorded().cells;
  if (!grid) return py::none();
  const CellGrid& c = *grid;
  py::array_t<std::uint8_t> states({c.rows, c.columns});
  std::copy(c.states.begin(), c.states.end(), states.mutable_data());
  py::object values = py::none();
  if (!c.values.empty()) {
    py::array_t<float> v({c.rows, c.columns});
    std::copy(c.values.begin(), c.values.end(), v.mutable_data());
    values = v;
  }
  return py::module_::import("polyplan")
      .attr("Cells")(states, c.x0, c.y0, c.cell_width, c.cell_height, values, c.value_name, c.wraps);
}

py::object decomposition(const PlanResult& r) {
  const Recording& recorded = r.recorded();
  if (recorded.decomposition.empty()) return py::none();
  py::list out;
  for (const Rows& cell : recorded.decomposition) out.append(rows_of(cell, r.report.path_columns()));
  return out;
}

py::object exact_path(const PlanResult& r) {
  const auto rows = r.report.exact_path();
  if (!rows) return py::none();
  py::list out;
  for (const auto& row : *rows) {
    py::list numbers;
    for (const Rational& x : row) numbers.append(fraction(x));
    out.append(py::tuple(numbers));
  }
  return out;
}

// A point, points or a cell as numbers: (2,) and (N, 2) float64 arrays, a tuple of two ints; none
// for the facts the JSON already gives as Python values.
py::object numbers_of(const FactValue& value) {
  if (const auto* p = std::get_if<FactPoint>(&value)) return rows_array({{(*p)[0], (*p)[1]}}, 2).attr("reshape")(2);
  if (const auto* points = std::get_if<FactPoints>(&value)) {
    Rows rows;
    for (const FactPoint& q : *points) rows.push_back({q[0], q[1]});
    return rows_array(rows, 2);
  }
  if (const auto* cell = std::get_if<FactCell>(&value)) return py::make_tuple((*cell)[0], (*cell)[1]);
  return py::none();
}

// The report's facts nested as the JSON nests them ("bug.hits" is facts["bug"]["hits"]), with numbers_of's
// arrays where the JSON has lists.
py::object facts_of(const Report& report) {
  py::object out = from_json(report.facts_json());
  for (const auto& [name, value] : report.facts().entries()) {
    py::object numbers = numbers_of(value);
    if (numbers.is_none()) continue;
    const std::vector<std::string> keys = fact_json_keys(name);
    py::object at = out;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) at = at[py::str(keys[k])];
    at[py::str(keys.back())] = numbers;
  }
  return out;
}

py::dict options_of(const PlanResult& r) {
  py::dict out;
  for (auto [name, value] : r.options) {
    std::replace(name.begin(), name.end(), '-', '_');
    out[py::str(name)] = value;
  }
  return out;
}

// The program's picture of `plans` (all of one problem and space) in `problem`.
std::string svg_of(py::handle problem, const std::vector<const PlanResult*>& plans, bool strobe) {
  const std::shared_ptr<ProblemHandle> handle = problem_of(problem, "svg");
  std::vector<const Report*> reports;
  for (const PlanResult* p : plans) {
    if (!p->problem.is(problem))
      throw InputError("svg: the plan " + p->report.planner() + " " + p->report.query() +
                       " was planned in another problem, not in " + handle->door().source());
    reports.push_back(&p->report);
  }
  const std::vector<Picture> pictures = locked(handle->lock(), [&] {
    return draw_reports(handle->door(), reports, {strobe, 0, ""});
  });
  if (pictures.size() != 1)
    throw InputError("svg: this problem's picture shows one plan, got " + std::to_string(plans.size()));
  return pictures.front().drawing.str();
}

}  // namespace

py::object from_json(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, item] : value.items()) out[py::str(key)] = from_json(item);
      return out;
    }
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const auto& item : value) out.append(from_json(item));
      return out;
    }
    case nlohmann::json::value_t::string: return py::str(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    default: return py::none();
  }
}

void bind_plans(py::module_& m) {
  py::class_<PlanResult>(m, "Plan",
                         R"(One query's answer from a Planner: what `polyplan plan --json -` prints, as Python values.

found, status ("solved", "no_path", "not_found", "limit", "invalid_query", "local_minimum") and
why_not say what became of the query; path is the certified path (a new float64 array); facts
the planner's counts and measures, nested as in the JSON.)")
      .def_property_readonly(
          "found", [](const PlanResult& r) { return r.report.found(); },
          "True when a certified path was found (status \"solved\").")
      .def_property_readonly(
          "status", [](const PlanResult& r) { return std::string(to_string(r.report.status())); },
          "What became of the query, the JSON's word: solved, no_path, not_found, limit, invalid_query, local_minimum.")
      .def_property_readonly(
          "why_not",
          [](const PlanResult& r) -> py::object {
            return r.report.found() ? py::object(py::none()) : py::str(r.report.why_not());
          },
          "When not found, one sentence saying why; None when found.")
      .def_property_readonly(
          "length",
          [](const PlanResult& r) -> py::object {
            return r.report.found() ? py::object(py::float_(r.report.length())) : py::object(py::none());
          },
          "The path's length in the planner's metric (Euclidean; an arm's: the sum of the joints' turns); None when "
          "not found.")
      .def_property_readonly(
          "path", [](const PlanResult& r) { return rows_of(r.report.path(), r.report.path_columns()); },
          "The path: a new float64 array of shape (N, 2) for points, (N, 3) [x, y, theta degrees] for poses, "
          "(N, joints) for an arm; (0, k) when not found.")
      .def_property_readonly("path_exact", &exact_path,
                             "The path exactly: a list of tuples of fractions.Fraction, (x, y) for points, (x, y, sin, "
                             "cos) for poses (the exact "
                             "rotation); None for an arm or a car (joint angles and a car's poses are doubles) and "
                             "for a path of pieces (its tangent points are irrational).")
      .def_property_readonly(
          "segments",
          [](const PlanResult& r) -> py::object {
            const nlohmann::json j = r.report.to_json();
            return j.contains("segments") ? from_json(j["segments"]) : py::object(py::none());
          },
          "A car's path as it drives: a list of dicts {steer: \"L\"|\"S\"|\"R\", gear: 1|-1, length, start: [x, y, "
          "theta]}, one per "
          "segment; None for other robots.")
      .def_property_readonly(
          "pieces",
          [](const PlanResult& r) -> py::object {
            const nlohmann::json j = r.report.to_json();
            return j.contains("pieces") ? from_json(j["pieces"]) : py::object(py::none());
          },
          "A path of segments and arcs (a disc robot's shortest path, planner visibility among discs and walls): a "
          "list of dicts {kind: \"segment\"|\"arc\", from: [x, y], to: [x, y], length, and for an arc centre: [x, "
          "y], radius, turn: \"ccw\"|\"cw\"}, piece k joining path[k] to path[k + 1]; None for a polyline.")
      .def_property_readonly(
          "certified", [](const PlanResult& r) { return r.report.certificate().certified; },
          "Whether every configuration along the path was proved free (every found path is).")
      .def_property_readonly(
          "certified_by",
          [](const PlanResult& r) -> py::object {
            const Certificate& c = r.report.certificate();
            return c.certified ? py::object(py::str(c.method)) : py::object(py::none());
          },
          "How the path was proved free, e.g. \"exact path check (triangulation walk)\"; None when not certified.")
      .def_property_readonly(
          "facts", [](const PlanResult& r) { return facts_of(r.report); },
          "Everything the JSON holds beside the answer, as a dict nested as there: the planner's facts "
          "(facts[\"search\"][\"expanded\"], facts[\"roadmap\"][\"vertices\"], ...), clearance and bottleneck, "
          "a planner's further paths")
      .def_property_readonly("options", &options_of,
                             "The planner's options it was planned with that differ from their defaults, "
                             "{\"goal_bias\": \"0.2\"} (values as the program prints them): for labels.")
      .def_property_readonly(
          "query", [](const PlanResult& r) { return r.report.query(); },
          "The query's name (\"start/goal\", \"queries[2]\", ...).")
      .def_property_readonly(
          "planner", [](const PlanResult& r) { return r.report.planner(); }, "The planner's name.")
      .def_property_readonly(
          "problem", [](const PlanResult& r) { return r.problem; }, "The World or Arm it was planned in.")
      .def_property_readonly("graph", &graph,
                             "The roadmap or tree when the query recorded one: Graph(kind, vertices (V, k) float64, "
                             "edges (E, 2) int64); else None.")
      .def_property_readonly(
          "expanded", [](const PlanResult& r) { return rows_of(r.recorded().expanded, r.report.path_columns()); },
          "Where the search expanded, in order (recorded queries), an (M, k) float64 array.")
      .def_property_readonly(
          "cells", &cells,
          "The planner's cells when it has some: Cells(states (rows, columns) uint8 [0 not evaluated, 1 free, "
          "2 blocked, 3 ridge], x0, y0, cell_width, cell_height, values, value_name, wraps); else None.")
      .def_property_readonly("decomposition", &decomposition,
                             "The convex cells of a decomposition (trapezoids), (n, k) arrays; else None.")
      .def(
          "to_json", [](const PlanResult& r) { return r.report.to_json().dump(2); },
          "The JSON text `polyplan plan --json -` (or `polyplan arm`) prints for this query.")
      .def("__repr__", [](const PlanResult& r) {
        const nlohmann::json j = r.report.to_json();
        return "<polyplan.Plan " + r.report.planner() + " " + r.report.query() + ": " + j["status"].get<std::string>() +
               (j["found"].get<bool>() ? ", length " + j["length"].dump() : "") + ">";
      });

  m.def(
      "svg",
      [](const py::object& problem, const py::object& plans, const py::object& strobe) {
        std::vector<const PlanResult*> list;
        if (py::isinstance<PlanResult>(plans)) list.push_back(&plans.cast<const PlanResult&>());
        else if (!plans.is_none()) {
          if (!py::isinstance<py::iterable>(plans))
            throw InputError("svg: expected a Plan or a list of Plan, got " + type_name(plans));
          for (py::handle p : plans) {
            if (!py::isinstance<PlanResult>(p))
              throw InputError("svg: expected a Plan or a list of Plan, got " + type_name(p));
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
