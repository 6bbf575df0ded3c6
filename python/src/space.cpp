// polyplan.space(problem): the sampling planners' space of a World or Arm (registry/
// problem_sampling_space.hpp) — distance, interpolate, steer and the certified motion test the
// planners themselves use — with numpy arrays in and out.
#include "plans.hpp"
#include "problems.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/problem_sampling_space.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace py = pybind11;

namespace polyplan::python {
namespace {

struct SpaceHandle {
  std::unique_ptr<AnySamplingSpace> space;
  std::shared_ptr<ProblemHandle> handle;  // keeps the problem the space is built on alive
};

// `work()` with the problem's lock held and the GIL released; its InputError prefixed by `what`.
template <class Work>
auto asked(const SpaceHandle& s, const std::string& what, Work work) {
  try {
    return locked(s.handle->lock(), work);
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
}

// A configuration as a vector of doubles: a one-dimensional sequence of numbers (InputError naming
// `what` otherwise); its count and values are the space's to check.
std::vector<double> coordinates_of(const py::handle& value, const std::string& what) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 1) throw InputError(what + ": expected a sequence of numbers (a configuration)");
  return {array.data(), array.data() + array.size()};
}

py::array_t<double> array_of(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

double number_of(const py::handle& value, const std::string& what) {
  if (!PyNumber_Check(value.ptr()) || PyBool_Check(value.ptr())) throw InputError(what + ": expected a number");
  return py::float_(py::reinterpret_borrow<py::object>(value));
}

}  // namespace

void bind_space(py::module_& m) {
  py::class_<SpaceHandle>(m, "Space",
                          R"(The configuration space the sampling planners plan in for one World or Arm
(polyplan.space): coordinates are numpy arrays — (x, y) for a translating or round robot,
(x, y, heading in radians) for a car, joint angles (radians, on the torus) for an arm. Each method
is the planners' own: steer is the step their trees take, motion_is_free their certified motion
test. InputError for a configuration of the wrong length, with a NaN or infinity, or outside the
sampling box (arms: any finite angle, taken modulo 2π).)")
      .def_property_readonly(
          "dimension", [](const SpaceHandle& s) { return s.space->dimension(); }, "The number of coordinates.")
      .def(
          "distance",
          [](const SpaceHandle& s, const py::object& a, const py::object& b) {
            const auto x = coordinates_of(a, "distance: a"), y = coordinates_of(b, "distance: b");
            return asked(s, "distance", [&] { return s.space->distance(x, y); });
          },
          py::arg("a"), py::arg("b"),
          "The length of the motion a → b: Euclidean, the sum of the joints' short turns (arm), the car's shortest "
          "curve (not symmetric for a car that cannot reverse).")
      .def(
          "interpolate",
          [](const SpaceHandle& s, const py::object& a, const py::object& b, const py::object& t) {
            const auto x = coordinates_of(a, "interpolate: a"), y = coordinates_of(b, "interpolate: b");
            const double fraction = number_of(t, "interpolate: t");
            return array_of(asked(s, "interpolate", [&] { return s.space->interpolate(x, y, fraction); }));
          },
          py::arg("a"), py::arg("b"), py::arg("t"),
          "The configuration a fraction t in [0, 1] of the way along the motion a → b (arm angles normalised into [0, "
          "2π)).")
      .def(
          "steer",
          [](const SpaceHandle& s, const py::object& a, const py::object& b, const py::object& step) {
            const auto x = coordinates_of(a, "steer: a"), y = coordinates_of(b, "steer: b");
            const double length = number_of(step, "steer: step");
            return array_of(asked(s, "steer", [&] { return s.space->steer(x, y, length); }));
          },
          py::arg("a"), py::arg("b"), py::arg("step"),
          "The configuration `step` (> 0) along the motion a → b, or b itself when it is nearer: the step the "
          "planners' trees take (on the torus each joint turns the short way round).")
      .def(
          "motion_is_free",
          [](const SpaceHandle& s, const py::object& a, const py::object& b) {
            const auto x = coordinates_of(a, "motion_is_free: a"), y = coordinates_of(b, "motion_is_free: b");
            return asked(s, "motion_is_free", [&] { return s.space->motion_is_free(x, y); });
          },
          py::arg("a"), py::arg("b"),
          "Whether the motion a → b is certified free for every configuration on it (the planners' exact or "
          "conservative test, never sampled); False when it collides or cannot be proved free.")
      .def(
          "is_free",
          [](const SpaceHandle& s, const py::object& a) {
            const auto x = coordinates_of(a, "is_free: a");
            return asked(s, "is_free", [&] { return s.space->is_free(x); });
          },
          py::arg("a"), "Whether the configuration is free, decided as the planners decide it.")
      .def("__repr__", [](const SpaceHandle& s) {
        return "<polyplan.Space of " + s.handle->door().source() + ", " + std::to_string(s.space->dimension()) +
               " coordinates>";
      });

  m.def(
      "space",
      [](const py::object& problem) {
        SpaceHandle s{nullptr, problem_of(problem, "space")};
        s.space = asked(s, "space", [&] { return problem_sampling_space(s.handle->door()); });
        return s;
      },
      py::arg("problem"),
      "The sampling planners' configuration space of a World or Arm (a Space): distance, interpolate, steer and "
      "motion_is_free on numpy arrays. InputError for a problem no sampling planner plans.");
}

}  // namespace polyplan::python
