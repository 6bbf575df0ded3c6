// polyplan.replan: the robot that discovers a MovingAI map as it drives (polyplan replan), its drive
// as a Drive object, and its picture.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/draw/replan_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/io/movingai_map.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace polyplan::python {
namespace {

GridPoint cell_of(const py::handle& value, const char* what) {
  try {
    const auto pair = value.cast<std::pair<int, int>>();
    return {pair.first, pair.second};
  } catch (const py::cast_error&) {
    throw InputError(std::string(what) + ": expected (x, y), a column and a row (integers)");
  }
}

py::object cost_or_none(const OctileLength& c) {
  return c == OctileLength::infinity() ? py::object(py::none()) : py::object(py::float_(c.to_double()));
}

py::list cells(const std::vector<GridPoint>& points) {
  py::list out;
  for (const GridPoint& p : points) out.append(py::make_tuple(p.x, p.y));
  return out;
}

}  // namespace

void bind_replan(py::module_& m) {
  py::class_<ReplanResult>(m, "Drive", "A robot's drive through a map it discovered (polyplan.replan).")
      .def_property_readonly(
          "found", [](const ReplanResult& r) { return r.found; }, "Whether it reached the goal.")
      .def_property_readonly(
          "status", [](const ReplanResult& r) { return std::string(to_string(r.status)); },
          "\"solved\", \"no_path\" (the goal unreachable on what it knew) or \"limit\".")
      .def_property_readonly(
          "algorithm", [](const ReplanResult& r) { return std::string(to_string(r.algorithm)); },
          "\"dstar-lite\", \"lpastar\" or \"astar\".")
      .def_property_readonly(
          "traversed", [](const ReplanResult& r) { return cells(r.traversed); },
          "The cells it stood on, (x, y) tuples, the start first.")
      .def_property_readonly(
          "traversed_cost", [](const ReplanResult& r) { return r.traversed_cost.to_double(); },
          "The cost it drove (moves 1 and √2).")
      .def_property_readonly(
          "traversed_cost_exact", [](const ReplanResult& r) { return r.traversed_cost.to_string(); },
          "The same, exactly: \"a + b√2\".")
      .def_property_readonly(
          "moves", [](const ReplanResult& r) { return r.moves; }, "Moves made.")
      .def_property_readonly(
          "replans", [](const ReplanResult& r) { return r.replans; },
          "Searches run: the first, and one after each sensing that changed what it knew.")
      .def_property_readonly(
          "expanded", [](const ReplanResult& r) { return r.expanded; }, "Vertices expanded, all replans.")
      .def_property_readonly(
          "generated", [](const ReplanResult& r) { return r.generated; }, "Vertices put in an open list.")
      .def_property_readonly(
          "heap_operations", [](const ReplanResult& r) { return r.heap_operations; },
          "Pushes, pops, key updates and removals, all replans.")
      .def_property_readonly(
          "seconds", [](const ReplanResult& r) { return r.seconds; }, "Time spent replanning.")
      .def_property_readonly(
          "last_plan", [](const ReplanResult& r) { return cells(r.last_plan); },
          "The last planned path, from where it was made.")
      .def_property_readonly(
          "steps",
          [](const ReplanResult& r) {
            py::list out;
            for (const ReplanStep& s : r.steps) {
              py::dict d;
              d["at"] = py::make_tuple(s.at.x, s.at.y);
              d["cost_to_goal"] = cost_or_none(s.cost_to_goal);
              d["cost_to_goal_exact"] = s.cost_to_goal.to_string();
              d["expanded"] = s.expanded;
              d["changed_cells"] = s.changed_cells;
              d["replanned"] = s.replanned;
              out.append(d);
            }
            return out;
          },
          "One dict per cell it planned from (at, cost_to_goal, cost_to_goal_exact, expanded, changed_cells, "
          "replanned).")
      .def_property_readonly(
          "knowledge",
          [](const ReplanResult& r) {
            py::array_t<std::uint8_t> a({r.height, r.width});
            auto v = a.mutable_unchecked<2>();
            for (int y = 0; y < r.height; ++y)
              for (int x = 0; x < r.width; ++x)
                v(y, x) = static_cast<std::uint8_t>(r.knowledge[static_cast<std::size_t>(y) * r.width + x]);
            return a;
          },
          "What it knew at the end, knowledge[row, column]: 0 unknown, 1 free, 2 blocked (uint8).")
      .def(
          "svg",
          [](const ReplanResult& r, bool animate) {
            return (animate ? draw_replan_animation(r, replan_title(r)) : draw_replan(r, replan_title(r))).str();
          },
          py::arg("animate") = false, "The picture (or, animate=True, the animation) as SVG text.")
      .def("__repr__", [](const ReplanResult& r) {
        return "<polyplan.Drive " + std::string(to_string(r.algorithm)) + " " + std::string(to_string(r.status)) +
               " after " + std::to_string(r.moves) + " moves, " + std::to_string(r.replans) + " replans>";
      });

  m.def(
      "replan",
      [](const py::object& map, const py::object& start, const py::object& goal, double sensor,
         const std::string& algorithm) {
        ReplanOptions options;
        options.algorithm = parse_replan_algorithm(algorithm, "algorithm");
        options.sensor_radius = sensor;
        const GridPoint from = cell_of(start, "start"), to = cell_of(goal, "goal");
        const std::string path = path_of(map, "replan: map");
        py::gil_scoped_release released;
        return drive_through_unknown_map(read_movingai_map(path), from, to, options);
      },
      py::arg("map"), py::arg("start"), py::arg("goal"), py::arg("sensor") = 1.5, py::arg("algorithm") = "dstar-lite",
      R"(A robot drives from start to goal, (x, y) cells of the MovingAI map file (x the column, y the
row), discovering the map as it goes: it senses the cells within `sensor` (at least √2) of its own
and replans with D* Lite, LPA* or A* from scratch (algorithm "dstar-lite", "lpastar", "astar") on
exact costs. Raises InputError for a bad map, a blocked or outside cell, a sensor below √2.)");
}

}  // namespace polyplan::python
