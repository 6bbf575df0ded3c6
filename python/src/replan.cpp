// polyplan.replan: the robot that discovers a map as it drives (polyplan replan) — a MovingAI map
// file or a numpy occupancy grid — its drive as a Drive object with the program's JSON, the
// course's g/rhs tables when asked, and its picture.
#include "exact_values.hpp"
#include "keyword_options.hpp"
#include "occupancy_grid.hpp"
#include "plans.hpp"

#include <polyplan/draw/replan_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/incremental/replan_options.hpp>
#include <polyplan/registry/replan_json.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include <limits>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// The g/rhs tables are whole maps, one per replan: kept for maps a course draws, not for a
// benchmark's 512 x 512.
constexpr std::size_t max_table_cells = 65536;

// A drive as Python holds it: the result, the sensor it drove with (for the JSON) and, when asked,
// the --rhs-trace lines and every replan's tables.
struct Drive {
  ReplanResult result;
  double sensor = 0;
  bool tables_asked = false;
  std::vector<nlohmann::json> trace;
  std::vector<ReplanTables> tables;
};

// Collects the trace while the drive runs without the GIL; converted to Python afterwards.
class CollectedTrace : public ReplanTrace {
 public:
  explicit CollectedTrace(Drive& drive) : drive_(&drive) {}
  void replan_begins(std::size_t replan, GridPoint at, std::size_t changed) override {
    drive_->trace.push_back(replan_begins_json(replan, at, changed));
  }
  void pass(const ReplanTracePass& p) override { drive_->trace.push_back(replan_pass_json(p)); }
  bool wants_tables() const override { return true; }
  void tables(const ReplanTables& t) override { drive_->tables.push_back(t); }

 private:
  Drive* drive_;
};

// (x, y), a column and a row: two integers (numpy's too), not bools, text or bytes.
GridPoint cell_of(const py::handle& value, const char* what) {
  const auto refuse = [&] { throw InputError(std::string(what) + ": expected (x, y), a column and a row (integers)"); };
  if (!py::isinstance<py::sequence>(value) && !py::isinstance<py::array>(value)) refuse();
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) || PyByteArray_Check(value.ptr())) refuse();
  std::vector<Rational> xy;
  try {
    xy = exact_numbers(value, what);
  } catch (const InputError&) {
    refuse();
  }
  if (xy.size() != 2) refuse();
  for (const Rational& v : xy)
    if (v.get_den() != 1 || !v.get_num().fits_sint_p()) refuse();
  return {static_cast<int>(xy[0].get_num().get_si()), static_cast<int>(xy[1].get_num().get_si())};
}

py::array_t<double> table_array(const std::vector<OctileLength>& values, int height, int width) {
  py::array_t<double> a({height, width});
  double* out = a.mutable_data();
  for (const OctileLength& c : values)
    *out++ = c == OctileLength::infinity() ? std::numeric_limits<double>::infinity() : c.to_double();
  return a;
}

py::object cost_or_none(const OctileLength& c, const GridConventions& grid = {}) {
  return c == OctileLength::infinity() ? py::object(py::none()) : py::object(py::float_(grid.in_cells(c)));
}

py::list cells(const std::vector<GridPoint>& points) {
  py::list out;
  for (const GridPoint& p : points) out.append(py::make_tuple(p.x, p.y));
  return out;
}

Drive drive(const py::object& map, const py::object& start, const py::object& goal, py::kwargs options) {
  const bool tables = options.contains("tables") && flag_of(options.attr("pop")("tables"), "replan: tables");
  Drive out;
  out.tables_asked = tables;
  ReplanOptions replanning = keyword_command_options(replan_option_table(), "replan", options);
  out.sensor = replanning.sensor_radius;
  const GridPoint from = cell_of(start, "start"), to = cell_of(goal, "goal");
  GridMap grid = grid_map_of(map, "replan: map");
  if (tables && static_cast<std::size_t>(grid.width) * grid.height > max_table_cells)
    throw InputError("replan: tables=True: " + grid.source + " has " +
                     std::to_string(static_cast<std::size_t>(grid.width) * grid.height) +
                     " cells; the g/rhs tables are kept for maps of at most " + std::to_string(max_table_cells));
  CollectedTrace trace(out);
  if (tables) replanning.trace = &trace;
  py::gil_scoped_release released;
  out.result = drive_through_unknown_map(std::move(grid), from, to, replanning);
  return out;
}

}  // namespace

void bind_replan(py::module_& m) {
  py::class_<Drive>(m, "Drive", "A robot's drive through a map it discovered (polyplan.replan).")
      .def_property_readonly(
          "found", [](const Drive& d) { return d.result.found; }, "Whether it reached the goal.")
      .def_property_readonly(
          "status", [](const Drive& d) { return std::string(to_string(d.result.status)); },
          "\"solved\", \"no_path\" (the goal unreachable on what it knew) or \"limit\".")
      .def_property_readonly(
          "algorithm", [](const Drive& d) { return std::string(to_string(d.result.algorithm)); },
          "\"dstar-lite\", \"lpastar\" or \"astar\".")
      .def_property_readonly(
          "traversed", [](const Drive& d) { return cells(d.result.traversed); },
          "The cells it stood on, (x, y) tuples, the start first.")
      .def_property_readonly(
          "traversed_cost", [](const Drive& d) { return d.result.grid.in_cells(d.result.traversed_cost); },
          "The cost it drove (moves 1 and the diagonal cost, √2 by default).")
      .def_property_readonly(
          "traversed_cost_exact", [](const Drive& d) { return d.result.grid.text(d.result.traversed_cost); },
          "The same, exactly: \"a + b√2\" (a fraction \"p/q\" for a fractional diagonal cost).")
      .def_property_readonly(
          "moves", [](const Drive& d) { return d.result.moves; }, "Moves made.")
      .def_property_readonly(
          "replans", [](const Drive& d) { return d.result.replans; },
          "Searches run: the first, and one after each sensing that changed what it knew.")
      .def_property_readonly(
          "expanded", [](const Drive& d) { return d.result.expanded; }, "Vertices expanded, all replans.")
      .def_property_readonly(
          "generated", [](const Drive& d) { return d.result.generated; }, "Vertices put in an open list.")
      .def_property_readonly(
          "heap_operations", [](const Drive& d) { return d.result.heap_operations; },
          "Pushes, pops, key updates and removals, all replans.")
      .def_property_readonly(
          "seconds", [](const Drive& d) { return d.result.seconds; }, "Time spent replanning.")
      .def_property_readonly(
          "last_plan", [](const Drive& d) { return cells(d.result.last_plan); },
          "The last planned path, from where it was made.")
      .def_property_readonly(
          "steps",
          [](const Drive& d) {
            py::list out;
            for (const ReplanStep& s : d.result.steps) {
              py::dict step;
              step["at"] = py::make_tuple(s.at.x, s.at.y);
              step["cost_to_goal"] = cost_or_none(s.cost_to_goal, d.result.grid);
              step["cost_to_goal_exact"] = d.result.grid.text(s.cost_to_goal);
              step["expanded"] = s.expanded;
              step["changed_cells"] = s.changed_cells;
              step["replanned"] = s.replanned;
              out.append(step);
            }
            return out;
          },
          "One dict per cell it planned from (at, cost_to_goal, cost_to_goal_exact, expanded, changed_cells, "
          "replanned).")
      .def_property_readonly(
          "knowledge",
          [](const Drive& d) {
            const ReplanResult& r = d.result;
            py::array_t<std::uint8_t> a({r.height, r.width});
            auto v = a.mutable_unchecked<2>();
            for (int y = 0; y < r.height; ++y)
              for (int x = 0; x < r.width; ++x)
                v(y, x) = static_cast<std::uint8_t>(r.knowledge[static_cast<std::size_t>(y) * r.width + x]);
            return a;
          },
          "What it knew at the end, knowledge[row, column]: 0 unknown, 1 free, 2 blocked (uint8).")
      .def_property_readonly(
          "trace",
          [](const Drive& d) -> py::object {
            if (!d.tables_asked) return py::none();
            py::list out;
            for (const nlohmann::json& line : d.trace) out.append(from_json(line));
            return out;
          },
          "With tables=True: the course's g/rhs trace, a dict per replan's start {replan, at, changed_cells} and per "
          "pass {replan, pass, popped, key, kind, g_before, g_after, rhs, updated, open} (None for infinity), as "
          "`polyplan replan --rhs-trace FILE` writes its lines; else None.")
      .def_property_readonly(
          "tables",
          [](const Drive& d) -> py::object {
            if (!d.tables_asked) return py::none();
            py::list out;
            for (const ReplanTables& t : d.tables) {
              py::dict one;
              one["replan"] = t.replan;
              one["g"] = table_array(t.g, d.result.height, d.result.width);
              one["rhs"] = table_array(t.rhs, d.result.height, d.result.width);
              out.append(one);
            }
            return out;
          },
          "With tables=True: after each replan, {replan, g, rhs}: every cell's g and rhs as (rows, columns) float64 "
          "arrays indexed [row, column] (inf for infinity); else None.")
      .def(
          "to_json", [](const Drive& d) { return replan_json(d.result, d.sensor).dump(2); },
          "The JSON text `polyplan replan --json -` prints for this drive.")
      .def(
          "svg",
          [](const Drive& d, const py::object& animated) {
            const ReplanResult& r = d.result;
            const bool animate = flag_of(animated, "svg: animate");
            return (animate ? draw_replan_animation(r, replan_title(r)) : draw_replan(r, replan_title(r))).str();
          },
          py::arg("animate") = false, "The picture (or, animate=True, the animation) as SVG text.")
      .def("__repr__", [](const Drive& d) {
        const ReplanResult& r = d.result;
        return "<polyplan.Drive " + std::string(to_string(r.algorithm)) + " " + std::string(to_string(r.status)) +
               " after " + std::to_string(r.moves) + " moves, " + std::to_string(r.replans) + " replans>";
      });

  m.def("replan", &drive, py::arg("map"), py::arg("start"), py::arg("goal"),
        R"(A robot drives from start to goal, (x, y) cells (x the column, y the row), through `map` — a
MovingAI .map file's path, or a numpy array indexed [row, column], True (or 1) where blocked —
discovering the map as it goes: it senses the cells within `sensor` of its own and replans on exact
costs. Options, as `polyplan replan` takes them: algorithm ("dstar-lite", "lpastar", "astar"),
sensor (cells, at least √2; 1.5), memory_mb (4096), time_limit (seconds, 0 none; 300); tables=True
keeps the course's g/rhs trace and every replan's g and rhs arrays (Drive.trace, Drive.tables; maps
of at most 65,536 cells). Raises InputError for a bad map, a blocked or outside cell, an option the
program refuses.)");
}

}  // namespace polyplan::python
