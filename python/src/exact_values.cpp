#include "exact_values.hpp"

#include <polyplan/geometry/input_limits.hpp>

#include <cmath>

namespace polyplan::python {
namespace {

Rational parsed(const std::string& text, const std::string& what) {
  std::string why;
  auto value = parse_rational(text, &why);
  if (!value) throw InputError(what + ": " + why + ": " + text);
  return *value;
}

// An integer's decimal text. One of more than 100 digits is refused as the reader refuses its text
// (geometry/input_limits.hpp), and before str() is asked for it: Python refuses to write an int of
// more than 4300 digits with a ValueError of its own.
std::string decimal_text(py::handle integer, const std::string& what) {
  if (py::int_(integer.attr("bit_length")()).cast<long long>() > 400)
    throw InputError(what + ": an integer of more than 100 digits: longer than the supported " +
                     std::to_string(limits::number_characters) + " characters");
  return py::str(integer);
}

bool is_instance_of(py::handle value, const char* module, const char* name) {
  return py::isinstance(value, py::module_::import(module).attr(name));
}

// A sequence that is not text or bytes (a str is a sequence of characters, never of numbers).
bool is_sequence(py::handle value) {
  return PySequence_Check(value.ptr()) && !py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) &&
         !PyByteArray_Check(value.ptr());
}

py::sequence sequence_of(py::handle value, const std::string& what, const std::string& expected) {
  if (!is_sequence(value)) throw InputError(what + ": expected " + expected + ", got " + type_name(value));
  return py::reinterpret_borrow<py::sequence>(value);
}

// A numpy row or column vector ((1, n) or (n, 1): the course writes points as np.array([[x], [y]]))
// as the 1-d array it stands for; anything else as it is.
py::object as_vector(py::handle value) {
  if (py::isinstance<py::array>(value)) {
    const auto array = py::reinterpret_borrow<py::array>(value);
    if (array.ndim() == 2 && (array.shape(0) == 1 || array.shape(1) == 1)) return value.attr("ravel")();
  }
  return py::reinterpret_borrow<py::object>(value);
}

}  // namespace

bool is_boolean(py::handle value) { return PyBool_Check(value.ptr()) || is_instance_of(value, "numpy", "bool_"); }

std::string type_name(py::handle value) {
  const py::handle type = py::type::handle_of(value);
  const std::string module = py::str(type.attr("__module__"));
  const std::string name = py::str(type.attr("__qualname__"));
  return module == "builtins" ? name : module + "." + name;
}

Rational exact_number(py::handle value, const std::string& what) {
  if (py::isinstance<py::array>(value)) {  // numpy's 0-d arrays are numbers; others are not
    const auto array = py::reinterpret_borrow<py::array>(value);
    if (array.ndim() != 0 || array.dtype().kind() == 'O')
      throw InputError(what + ": expected a number, got an array of shape " +
                       std::string(py::str(value.attr("shape"))));
    return exact_number(value.attr("item")(), what);
  }
  if (is_boolean(value))
    throw InputError(what + ": expected a number, got a bool (" + std::string(py::str(value)) + ")");
  if (py::isinstance<py::str>(value)) return parsed(text_of(value, what), what);
  if (is_instance_of(value, "fractions", "Fraction"))
    return parsed(decimal_text(value.attr("numerator"), what) + "/" + decimal_text(value.attr("denominator"), what),
                  what);
  if (is_instance_of(value, "decimal", "Decimal")) return parsed(py::str(value), what);
  if (PyIndex_Check(value.ptr())) {
    const auto index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!index) {
      PyErr_Clear();
      throw InputError(what + ": expected a number, got " + type_name(value));
    }
    return parsed(decimal_text(index, what), what);
  }
  if (PyFloat_Check(value.ptr()) || is_instance_of(value, "numpy", "floating")) {
    const double d = py::float_(py::reinterpret_borrow<py::object>(value));
    if (!std::isfinite(d)) throw InputError(what + ": not a finite number (" + std::string(py::str(value)) + ")");
    // The double's exact value, within the range of every number read (its exact decimal text can
    // be far longer than a number's 100 characters: the range is what is checked).
    const double magnitude = std::abs(d);
    if (magnitude > 1e100 || (magnitude != 0 && magnitude < 1e-100))
      throw InputError(what + ": " + std::string(py::repr(value)) + ": " +
                       (magnitude > 1 ? "overflows " : "underflows ") + limits::supported_number_range());
    return Rational(d);
  }
  throw InputError(what + ": expected a number (int, Fraction, float or a decimal string), got " + type_name(value));
}

double finite_number(py::handle value, const std::string& what) {
  if (PyFloat_Check(value.ptr()) || is_instance_of(value, "numpy", "floating")) {
    if (is_boolean(value)) throw InputError(what + ": expected a number, got a bool");
    const double d = py::float_(py::reinterpret_borrow<py::object>(value));
    if (!std::isfinite(d)) throw InputError(what + ": not a finite number (" + std::string(py::str(value)) + ")");
    return d;
  }
  return to_double(exact_number(value, what));
}

ExactPoint exact_point(py::handle given, const std::string& what) {
  const py::object value = as_vector(given);
  if (py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() != 1)
    throw InputError(what + ": expected a point (x, y): an array of shape (2,), (1, 2) or (2, 1), got shape " +
                     std::string(py::str(value.attr("shape"))));
  const py::sequence pair = sequence_of(value, what, "a point (x, y)");
  if (py::len(pair) != 2)
    throw InputError(what + ": expected a point (x, y), got " + std::to_string(py::len(pair)) + " numbers");
  return {exact_number(pair[0], what + "[0]"), exact_number(pair[1], what + "[1]")};
}

std::vector<ExactPoint> exact_points(py::handle value, const std::string& what) {
  std::vector<ExactPoint> points;
  if (const py::ssize_t n = PyObject_Length(value.ptr()); n > static_cast<py::ssize_t>(limits::points))
    throw InputError(what + ": " + std::to_string(n) + " points, more than the supported " +
                     std::to_string(limits::points));
  PyErr_Clear();  // PyObject_Length of something without a length
  if (py::isinstance<py::array>(value)) {
    const auto array = py::reinterpret_borrow<py::array>(value);
    if (array.ndim() != 2 || array.shape(1) != 2)
      throw InputError(what + ": expected an (N, 2) array of points, got shape " +
                       std::string(py::str(value.attr("shape"))));
    const char kind = array.dtype().kind();
    if (kind == 'f') {
      // Any order and stride: a C-ordered float64 copy (forcecast) is read, never the caller's memory.
      const auto doubles = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
      const auto view = doubles.unchecked<2>();
      for (py::ssize_t i = 0; i < view.shape(0); ++i) {
        const std::string row = what + "[" + std::to_string(i) + "]";
        points.push_back(
            {exact_number(py::float_(view(i, 0)), row + "[0]"), exact_number(py::float_(view(i, 1)), row + "[1]")});
      }
      return points;
    }
    if (kind == 'b') throw InputError(what + ": expected numbers, got an array of bools");
    if (kind != 'i' && kind != 'u' && kind != 'O')
      throw InputError(what + ": expected an array of numbers, got dtype " + std::string(py::str(array.dtype())));
    // Integers (exact, whatever their size) and objects (Fractions, strings) element by element.
  }
  const py::sequence rows = sequence_of(value, what, "a sequence of points (x, y)");
  for (std::size_t i = 0; i < py::len(rows); ++i)
    points.push_back(exact_point(rows[i], what + "[" + std::to_string(i) + "]"));
  return points;
}

namespace {

// Each element of a sequence or 1-d array of numbers read by `read`.
template <class Read>
auto numbers_of(py::handle given, const std::string& what, Read read) {
  const py::object value = as_vector(given);
  if (py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() != 1)
    throw InputError(what + ": expected a 1-d array of numbers, got shape " +
                     std::string(py::str(value.attr("shape"))));
  const py::sequence numbers = sequence_of(value, what, "a sequence of numbers");
  std::vector<decltype(read(numbers[0], what))> out;
  for (std::size_t i = 0; i < py::len(numbers); ++i)
    out.push_back(read(numbers[i], what + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace

std::vector<double> finite_numbers(py::handle value, const std::string& what) {
  return numbers_of(value, what, finite_number);
}
std::vector<Rational> exact_numbers(py::handle value, const std::string& what) {
  return numbers_of(value, what, exact_number);
}

std::string text_of(py::handle value, const std::string& what) {
  if (!py::isinstance<py::str>(value)) throw InputError(what + ": expected a str, got " + type_name(value));
  Py_ssize_t size = 0;
  const char* utf8 = PyUnicode_AsUTF8AndSize(value.ptr(), &size);
  if (!utf8) {  // a lone surrogate: not text UTF-8 can hold
    PyErr_Clear();
    throw InputError(what + ": " + std::string(py::str(py::repr(value))) +
                     ": not valid Unicode (a lone surrogate: a file name that is not UTF-8?)");
  }
  return {utf8, static_cast<std::size_t>(size)};
}

std::string path_of(py::handle value, const std::string& what) {
  const bool path_like = py::isinstance(value, py::module_::import("os").attr("PathLike"));
  if (!path_like && !py::isinstance<py::str>(value))
    throw InputError(what + ": expected a file's path (a str or a pathlib.Path), got " + type_name(value));
  const std::string path = text_of(path_like ? py::module_::import("os").attr("fspath")(value) : value, what);
  // The file system would stop at a NUL and open another file than the one named.
  if (path.find('\0') != std::string::npos) throw InputError(what + ": a path with a NUL character");
  return path;
}

bool flag_of(py::handle value, const std::string& what) {
  if (!is_boolean(value)) throw InputError(what + ": expected True or False, got " + type_name(value));
  return py::bool_(py::reinterpret_borrow<py::object>(value));
}

py::object fraction(const Rational& value) {
  return py::module_::import("fractions")
      .attr("Fraction")(py::int_(py::str(value.get_num().get_str())), py::int_(py::str(value.get_den().get_str())));
}

py::array_t<double> rows_array(const std::vector<std::vector<double>>& rows, std::size_t columns) {
  py::array_t<double> out({rows.size(), columns});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < columns; ++j) view(i, j) = rows[i].at(j);
  return out;
}

py::array_t<double> points_array(const std::vector<ExactPoint>& points) {
  std::vector<std::vector<double>> rows;
  for (const ExactPoint& p : points) rows.push_back({to_double(p.x), to_double(p.y)});
  return rows_array(rows, 2);
}

}  // namespace polyplan::python
