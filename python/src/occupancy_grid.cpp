#include "occupancy_grid.hpp"
#include "exact_values.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// A boolean array [row, column], True where blocked (integers 0 and 1 too), as a MovingAI map.
GridMap grid_of(const py::handle& value, const std::string& what) {
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(value);
  } catch (const py::error_already_set& e) {  // ragged lists, objects numpy cannot read
    throw InputError(what + ": expected a .map file's path or a 2-d boolean array, got " + type_name(value) +
                     " that numpy cannot read as an array (" + e.what() + ")");
  }
  std::string shape;
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  const std::string given = "a " + std::string(py::str(a.dtype())) + " array of shape (" + shape + ")";
  if (a.ndim() != 2 || a.shape(0) == 0 || a.shape(1) == 0)
    throw InputError(what +
                     ": expected a .map file's path or a 2-d boolean array [row, column], True where "
                     "blocked, got " +
                     given);
  const char kind = a.dtype().kind();
  if (kind != 'b' && kind != 'i' && kind != 'u')
    throw InputError(what + ": expected booleans (True where blocked) or the integers 0 and 1, got " + given);
  const auto rows = static_cast<std::uint64_t>(a.shape(0)), columns = static_cast<std::uint64_t>(a.shape(1));
  if (rows * columns > limits::map_cells)
    throw InputError(what + ": " + given + " has more than the supported " + std::to_string(limits::map_cells) +
                     " cells");
  const py::array_t<std::int64_t> cells = a.attr("astype")("int64");
  const auto v = cells.unchecked<2>();
  GridMap map{"grid (" + shape + ")", static_cast<int>(columns), static_cast<int>(rows), {}};
  map.blocked.resize(rows * columns);
  for (py::ssize_t y = 0; y < v.shape(0); ++y)
    for (py::ssize_t x = 0; x < v.shape(1); ++x) {
      if (v(y, x) != 0 && v(y, x) != 1)
        throw InputError(what + "[" + std::to_string(y) + ", " + std::to_string(x) + "]: " + std::to_string(v(y, x)) +
                         " is neither 0 (free) nor 1 (blocked)");
      map.blocked[static_cast<std::size_t>(y) * columns + x] = v(y, x) == 1;
    }
  return map;
}

}  // namespace

GridMap grid_map_of(const py::object& map, const std::string& what) {
  if (py::isinstance<py::str>(map) || py::hasattr(map, "__fspath__")) return read_movingai_map(path_of(map, what));
  return grid_of(map, what);
}

}  // namespace polyplan::python
