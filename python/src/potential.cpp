// polyplan.potential: the critical points of the potential-field planner's potential for a world's
// goal (polyplan potential), as the dict `polyplan potential --json -` prints, and its picture.
#include "exact_values.hpp"
#include "plans.hpp"
#include "problems.hpp"

#include <polyplan/draw/potential_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/reactive/potential_study.hpp>
#include <polyplan/registry/potential_json.hpp>

#include <nlohmann/json.hpp>

#include <pybind11/pybind11.h>

#include <algorithm>
#include <optional>

namespace py = pybind11;

namespace polyplan::python {
namespace {

std::size_t cells_of(const py::handle& value) {
  const Rational n = exact_number(value, "cells");
  if (n.get_den() != 1 || n < 0 || !n.get_num().fits_ulong_p())
    throw InputError("cells: expected an integer, got " + std::string(py::str(value)));
  return n.get_num().get_ui();
}

// (xmin, ymin, xmax, ymax); None: the program's default, decided on the C-space.
std::optional<BoxGrid> box_of(const py::handle& value, std::size_t cells) {
  if (value.is_none()) return std::nullopt;
  const std::vector<double> v = finite_numbers(value, "box");
  if (v.size() != 4)
    throw InputError("box: expected (xmin, ymin, xmax, ymax), got " + std::to_string(v.size()) + " numbers");
  return BoxGrid{v[0], v[1], v[2], v[3], cells};
}

}  // namespace

void bind_potential(py::module_& m) {
  m.def(
      "potential",
      [](const py::object& given, const py::object& zeta, const py::object& d_star, const py::object& eta,
         const py::object& q_star, const py::object& box_given, const py::object& cells_given,
         const py::object& picture) {
        const std::shared_ptr<WorldHandle> world = world_of(given, "potential");
        const Vec2 goal = potential_goal(world->world());
        const std::size_t cells = cells_of(cells_given);
        // Checked by the study's one table, named as Python spells them (d_star for d-star).
        const OptionValues values{{"zeta", detail::show_number(finite_number(zeta, "zeta"))},
                                  {"d-star", detail::show_number(finite_number(d_star, "d_star"))},
                                  {"eta", detail::show_number(finite_number(eta, "eta"))},
                                  {"q-star", detail::show_number(finite_number(q_star, "q_star"))},
                                  {"cells", std::to_string(cells)}};
        const PotentialStudyOptions options =
            potential_study_options().parse_as(values, [](std::string key, const std::string& value) {
              std::replace(key.begin(), key.end(), '-', '_');
              return key + " " + value + ": ";
            });
        const std::optional<BoxGrid> box = box_of(box_given, options.cells);
        const bool draw = flag_of(picture, "svg");
        nlohmann::json out;
        std::string svg;
        locked(world->lock(), [&] {
          const CSpace& cspace = world->cspace();
          const ObstacleField field(cspace);
          const PotentialStudy study = study_potential(cspace, field, goal, options, box, "box");
          out = potential_json(study);
          if (draw) svg = draw_potential_study(cspace, field, study).str();
        });
        py::dict result = from_json(out);
        if (draw) result["svg"] = svg;
        return result;
      },
      py::arg("world"), py::arg("zeta") = 1.0, py::arg("d_star") = 0.0, py::arg("eta") = 1.0, py::arg("q_star") = 1.0,
      py::arg("box") = py::none(), py::arg("cells") = 256, py::arg("svg") = false,
      R"(The critical points of the potential-field planner's potential for the world's goal (its first
query's): attraction zeta (quadratic within d_star of the goal, conic beyond; d_star 0: conic
everywhere) plus each C-obstacle's repulsion eta within q_star. They are searched in the free space
of box (xmin, ymin, xmax, ymax; None: the world's bounds, or the box around it) cut into
cells x cells cells, and classified by the Hessian.

Returns the dict `polyplan potential --json -` prints: goal, parameters, box, cells_per_axis,
candidates and critical_points, each {"at": [x, y], "kind": "minimum", "maximum", "saddle" or
"degenerate", "eigenvalues": [smaller, larger], "value": U, "gradient": |grad U|}, by x then y.
svg=True adds "svg", the picture (heat map, contours, descent arrows, critical points) as SVG
text. The goal of a conic attraction is not among them (no gradient there). Raises InputError
naming the argument for a negative or non-finite parameter, a bad box or cells, a world without
a query.)");
}

}  // namespace polyplan::python
