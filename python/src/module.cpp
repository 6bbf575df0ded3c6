// polyplan._polyplan, the compiled half of `import polyplan` (python/polyplan/__init__.py is the
// other): the problems, the planners of every registry, plans and pictures. Errors: bad input is
// polyplan.InputError (a ValueError) with the message the program prints; Python's own errors
// pass through; anything else polyplan throws is a bug and a RuntimeError.
#include "plans.hpp"

#include <polyplan/geometry/input_error.hpp>

#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;

PYBIND11_MODULE(_polyplan, m) {
  m.doc() = "polyplan's compiled core; import polyplan, not this module.";
  static py::exception<polyplan::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a file, a value or an option polyplan refuses. The message is the one `polyplan` prints.";
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      std::rethrow_exception(thrown);
    } catch (const polyplan::InputError& e) {
      // A message may quote a file's bytes that are not UTF-8: they are shown as \xNN escapes,
      // never turned into a UnicodeDecodeError or an empty message.
      const std::string text = e.what();
      const py::object message = py::reinterpret_steal<py::object>(
          PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "backslashreplace"));
      PyErr_SetObject(input_error.ptr(), message.ptr());
    }
  });
  polyplan::python::bind_problems(m);
  polyplan::python::bind_plans(m);
  polyplan::python::bind_planners(m);
  polyplan::python::bind_replan(m);
  polyplan::python::bind_potential(m);
  polyplan::python::bind_search(m);
  polyplan::python::bind_steer(m);
  polyplan::python::bind_space(m);
  polyplan::python::bind_ik(m);
  polyplan::python::bind_experiment(m);
  polyplan::python::bind_scen(m);
  polyplan::python::bind_check(m);
}
