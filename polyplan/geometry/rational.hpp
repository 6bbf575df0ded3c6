#pragma once
// Exact rational numbers as they appear in files and in public interfaces.
// GMP's C++ class is used here (not CGAL's number types) so that every includer
// of a public header compiles in milliseconds; geometry/detail converts to CGAL.
#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>

namespace polyplan {

using Rational = mpq_class;

struct ExactPoint {
  Rational x, y;
  friend bool operator==(const ExactPoint& a, const ExactPoint& b) { return a.x == b.x && a.y == b.y; }
};

// Parses a number written as text exactly: integers ("-12"), decimals ("0.1" is 1/10),
// exponents ("1e-3", "2.5E+2"), and rationals ("3/4", "-1/3"). On failure returns nullopt
// and, if `why` is given, stores a short reason ("zero denominator", "not a number"). Numbers
// longer than limits::number_characters, or outside [1e-100, 1e100] in magnitude (other than 0)
// are refused: see geometry/input_limits.hpp.
std::optional<Rational> parse_rational(std::string_view text, std::string* why = nullptr);

// "p/q" in lowest terms, or "n" for an integer: the inverse of parse_rational.
std::string to_string(const Rational& value);

// "[p/q, r/s]": a point as messages name it.
std::string to_string(const ExactPoint& point);

// An angle in degrees reduced exactly into (-180, 180]: 1e9 is -80, 540 is 180 (a heading's
// double is then taken from the reduced value, so no rounding of a huge angle turns the car).
Rational reduce_degrees(const Rational& degrees);

// The double nearest to the value (GMP's own get_d truncates: 21/5 would print 4.199999999999999).
double to_double(const Rational& value);

}  // namespace polyplan
