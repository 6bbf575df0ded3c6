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
  // Checked in the array's own type, before any conversion could wrap a large value round to 0 or 1.
  const py::module_ np = py::module_::import("numpy");
  const py::object bad =
      np.attr("argwhere")(np.attr("logical_and")(np.attr("not_equal")(a, 0), np.attr("not_equal")(a, 1)));
  if (py::len(bad) > 0) {
    const py::object at = bad[py::int_(0)];
    const std::string y = py::str(at[py::int_(0)]), x = py::str(at[py::int_(1)]);
    throw InputError(what + "[" + y + ", " + x +
                     "]: " + std::string(py::str(a[py::make_tuple(at[py::int_(0)], at[py::int_(1)])])) +
                     " is neither 0 (free) nor 1 (blocked)");
  }
  const py::array_t<std::uint8_t> cells = a.attr("astype")("uint8");
  const auto v = cells.unchecked<2>();
  GridMap map{"grid (" + shape + ")", static_cast<int>(columns), static_cast<int>(rows), {}};
  map.blocked.resize(rows * columns);
  for (py::ssize_t y = 0; y < v.shape(0); ++y)
    for (py::ssize_t x = 0; x < v.shape(1); ++x) map.blocked[static_cast<std::size_t>(y) * columns + x] = v(y, x) == 1;
  return map;
}

}  // namespace

GridMap grid_map_of(const py::object& map, const std::string& what) {
  if (py::isinstance<py::str>(map) || py::hasattr(map, "__fspath__")) return read_movingai_map(path_of(map, what));
  return grid_of(map, what);
}

}  // namespace polyplan::python
