#include "cli/command.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>

#include <cmath>
#include <sstream>

namespace polyplan::cli {

std::vector<double> comma_numbers(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(value))
      throw InputError(option + " " + text + ": \"" + part + "\" is not a finite number");
    values.push_back(value);
  }
  return values;
}

double degrees_option(const std::string& text, const std::string& option) {
  std::string why;
  const auto degrees = parse_rational(text, &why);
  if (!degrees) throw InputError(option + " " + text + ": " + why);
  return to_double(reduce_degrees(*degrees));
}

}  // namespace polyplan::cli
