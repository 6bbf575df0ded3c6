#pragma once
// Python values in and out of polyplan's exact numbers. In: an int, a fractions.Fraction, a
// decimal.Decimal or a decimal string ("0.1", "3/7") is its exact value; a float is the exact
// value of that double (as a WKT number is); bool, NaN, infinity and anything else are an
// InputError naming `what`. Out: new float64 numpy arrays the caller owns, and Fractions.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace polyplan::python {

namespace py = pybind11;

Rational exact_number(py::handle value, const std::string& what);
// A finite double from any real number (angles, lengths): an InputError for anything else.
double finite_number(py::handle value, const std::string& what);

// An (x, y) pair: a sequence or a 1-d array of two numbers.
ExactPoint exact_point(py::handle value, const std::string& what);
// An (N, 2) array-like: a numpy array of any dtype of numbers, order and stride, or a sequence
// of pairs (which may mix ints, Fractions, floats and strings).
std::vector<ExactPoint> exact_points(py::handle value, const std::string& what);
// A sequence or 1-d array of finite numbers (joint angles).
std::vector<double> finite_numbers(py::handle value, const std::string& what);
// A sequence or 1-d array of exact numbers (a query's start or goal, whatever the problem).
std::vector<Rational> exact_numbers(py::handle value, const std::string& what);

// A str; a path may also be an os.PathLike (pathlib.Path). InputError for anything else.
std::string text_of(py::handle value, const std::string& what);
std::string path_of(py::handle value, const std::string& what);
// True or False (numpy's bools too); InputError for anything else, 0 and 1 included.
bool flag_of(py::handle value, const std::string& what);

py::object fraction(const Rational& value);
// An (N, columns) float64 array of rows given as doubles.
py::array_t<double> rows_array(const std::vector<std::vector<double>>& rows, std::size_t columns);
py::array_t<double> points_array(const std::vector<ExactPoint>& points);

// "list", "numpy.ndarray": how messages name what a caller passed.
std::string type_name(py::handle value);
// True or False, Python's or numpy's.
bool is_boolean(py::handle value);

}  // namespace polyplan::python
