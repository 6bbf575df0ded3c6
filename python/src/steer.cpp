// polyplan.steer: the shortest Dubins or Reeds–Shepp curve between two poses (polyplan steer), as
// the dict `polyplan steer --json -` prints, and its picture.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/draw/steering_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/steering_json.hpp>

#include <nlohmann/json.hpp>

#include <pybind11/pybind11.h>

#include <cmath>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// (x, y, degrees), the heading reduced modulo 360 exactly before it becomes radians, as the
// program reads --from and --to.
CarPose pose_of(py::handle value, const std::string& what) {
  const std::vector<Rational> numbers = exact_numbers(value, what);
  if (numbers.size() != 3)
    throw InputError(what + ": expected a pose (x, y, degrees), got " + std::to_string(numbers.size()) + " numbers");
  return {to_double(numbers[0]), to_double(numbers[1]), to_double(reduce_degrees(numbers[2])) * M_PI / 180};
}

}  // namespace

void bind_steer(py::module_& m) {
  m.def(
      "steer",
      [](const py::object& start, const py::object& goal, const py::object& radius_given, const std::string& model,
         bool all_words) {
        const CarPose from = pose_of(start, "start"), to = pose_of(goal, "goal");
        const double radius = finite_number(radius_given, "radius");
        if (model != "dubins" && model != "reeds-shepp")
          throw InputError("model " + model + ": expected dubins or reeds-shepp");
        const SteeringWords words =
            model == "dubins" ? dubins_words(from, to, radius) : reeds_shepp_words(from, to, radius);
        const SteeringPath& path = words.path;
        nlohmann::json document = steering_json(path);
        if (all_words) document["words"] = steering_words_json(words);
        py::dict result = from_json(document);
        result["svg"] = draw_steering(path, from, to, radius, steering_summary(model, path)).str();
        return result;
      },
      py::arg("start"), py::arg("goal"), py::arg("radius") = 1.0, py::arg("model") = "dubins",
      py::arg("all_words") = false,
      R"(The shortest curve of a car turning with `radius` from pose `start` to pose `goal`, each
(x, y, degrees): model "dubins" drives forward only, "reeds-shepp" may reverse. Returns the dict
`polyplan steer --json -` prints (length, word, segments: [{steer, gear, length}]) and svg, its
picture; with all_words=True also words, every word tried ([{name, length (None: infeasible),
shortest}]: Dubins' six, Reeds-Shepp's 44 formula applications), as `polyplan steer --all-words`.
Radius and coordinates from 1e-100 to 1e100; headings reduced modulo 360 exactly. Raises InputError
for anything else.)");
}

}  // namespace polyplan::python
