#include "keyword_options.hpp"
#include "exact_values.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>

#include <pybind11/numpy.h>

#include <algorithm>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// A keyword argument as the option text the registry parses: True/False, an int, a float (its
// shortest round-trip text), a Fraction (as a float; for an exact number option, as it is, as is
// a Decimal), a string, or for a point option a pair of numbers ("x,y"); nothing else.
std::string option_text(const std::string& owner, const OptionInfo& option, const std::string& key, py::handle value) {
  const std::string where = owner + ": option " + key;
  if (is_boolean(value)) return py::bool_(py::reinterpret_borrow<py::object>(value)) ? "true" : "false";
  if (py::isinstance<py::str>(value)) return text_of(value, where);
  // An integer as the exact reader takes it: within its digits (str() itself refuses 4300 digits).
  if (PyIndex_Check(value.ptr()) && !py::isinstance<py::array>(value)) return to_string(exact_number(value, where));
  const bool exact_option = option.kind.find(" (exact)") != std::string::npos;
  if (exact_option && (py::isinstance(value, py::module_::import("numbers").attr("Rational")) ||
                       py::isinstance(value, py::module_::import("decimal").attr("Decimal"))))
    return to_string(exact_number(value, where));
  if (PyFloat_Check(value.ptr()) || py::isinstance(value, py::module_::import("numbers").attr("Real")))
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));
  if (option.kind.rfind("point", 0) == 0 && (PySequence_Check(value.ptr()) || py::isinstance<py::array>(value))) {
    std::string text;
    for (const Rational& x : exact_numbers(value, owner + ": option " + key))
      text += (text.empty() ? "" : ",") + to_string(x);
    return text;
  }
  throw InputError(owner + ": option " + key + "=" + std::string(py::repr(value)) +
                   ": expected a number, text, True or False, got " + type_name(value));
}

}  // namespace

OptionValues keyword_options(const std::string& owner, const std::vector<OptionInfo>& options, const py::dict& given) {
  OptionValues values;
  std::string known;
  for (const OptionInfo& o : options) known += (known.empty() ? "" : ", ") + o.name;
  for (const auto& [key, value] : given) {
    const std::string spelt = text_of(key, owner + ": an option's name");
    std::string name = spelt;
    std::replace(name.begin(), name.end(), '_', '-');
    const auto option =
        std::find_if(options.begin(), options.end(), [&](const OptionInfo& o) { return o.name == name; });
    if (option == options.end())
      throw InputError(owner + ": option " + spelt + ": no such option (" +
                       (known.empty() ? "it takes none" : "its options: " + known) + ")");
    values.emplace_back(name, option_text(owner, *option, spelt, value));
  }
  return values;
}

}  // namespace polyplan::python
