#include <polyplan/geometry/rational.hpp>

#include <polyplan/geometry/input_limits.hpp>

#include <mpfr.h>

#include <cctype>
#include <cstdlib>
#include <limits>

namespace polyplan {
namespace {

// Larger decimal exponents would ask GMP for gigabytes (10^999999999) before anyone could
// notice; no world needs them.
constexpr long kMaxExponent = 4000;

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

std::optional<Rational> fail(std::string* why, const std::string& reason) {
  if (why) *why = reason;
  return std::nullopt;
}

// A decimal in JSON's grammar (optional sign, digits, optional fraction, optional exponent),
// read exactly: mantissa digits as an integer, scaled by a power of ten.
std::optional<Rational> parse_decimal(std::string_view s, std::string* why) {
  bool negative = false;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  long exponent = 0;
  if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
    std::string_view exp_text = s.substr(e + 1);
    s = s.substr(0, e);
    bool exp_negative = false;
    if (!exp_text.empty() && (exp_text[0] == '-' || exp_text[0] == '+')) {
      exp_negative = exp_text[0] == '-';
      exp_text.remove_prefix(1);
    }
    if (!all_digits(exp_text)) return fail(why, "not a number");
    if (exp_text.size() > 6) return fail(why, "exponent out of range");
    exponent = std::strtol(std::string(exp_text).c_str(), nullptr, 10);
    if (exp_negative) exponent = -exponent;
  }
  std::string digits;
  if (auto dot = s.find('.'); dot != std::string_view::npos) {
    std::string_view integral = s.substr(0, dot), fraction = s.substr(dot + 1);
    if ((!integral.empty() && !all_digits(integral)) || (!fraction.empty() && !all_digits(fraction)) ||
        (integral.empty() && fraction.empty()))
      return fail(why, "not a number");
    digits = std::string(integral) + std::string(fraction);
    exponent -= static_cast<long>(fraction.size());
  } else {
    if (!all_digits(s)) return fail(why, "not a number");
    digits = std::string(s);
  }
  if (exponent > kMaxExponent || exponent < -kMaxExponent) return fail(why, "exponent out of range");
  mpz_class mantissa(digits, 10);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  Rational value = exponent < 0 ? Rational(mantissa, power) : Rational(mantissa * power);
  value.canonicalize();
  return negative ? Rational(-value) : value;
}

std::optional<Rational> parse_text(std::string_view text, std::string* why) {
  if (auto slash = text.find('/'); slash != std::string_view::npos) {
    std::string_view num = text.substr(0, slash), den = text.substr(slash + 1);
    if (den.find('/') != std::string_view::npos) return fail(why, "not a number");
    std::string_view num_digits = num;
    if (!num_digits.empty() && (num_digits[0] == '-' || num_digits[0] == '+')) num_digits.remove_prefix(1);
    if (!all_digits(num_digits) || !all_digits(den)) return fail(why, "not a number");
    mpz_class d(std::string(den), 10);
    if (d == 0) return fail(why, "zero denominator");
    mpz_class n(std::string(num_digits), 10);
    if (num[0] == '-') n = -n;
    Rational value(n, d);
    value.canonicalize();
    return value;
  }
  return parse_decimal(text, why);
}

// 10^exponent, exactly.
Rational power_of_ten(int exponent) {
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  return exponent < 0 ? Rational(mpz_class(1), power) : Rational(power);
}

}  // namespace

std::optional<Rational> parse_rational(std::string_view text, std::string* why) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (text.empty()) return fail(why, "not a number");
  if (text.size() > limits::number_characters)
    return fail(why, "longer than the supported " + std::to_string(limits::number_characters) + " characters");
  auto value = parse_text(text, why);
  if (value) {
    static const Rational largest = power_of_ten(limits::number_decimal_exponent);
    static const Rational smallest = power_of_ten(-limits::number_decimal_exponent);
    const Rational magnitude = abs(*value);
    const std::string range = limits::supported_number_range();
    if (magnitude > largest) return fail(why, "overflows " + range);
    if (sgn(magnitude) != 0 && magnitude < smallest) return fail(why, "underflows " + range);
  }
  return value;
}

std::string to_string(const Rational& value) { return value.get_str(10); }

// Appended piece by piece: GCC 12 reads "[" + std::string&& as an out-of-bounds memcpy (its bugs
// 105329 and 105651).
std::string to_string(const ExactPoint& point) {
  std::string text = "[";
  text += to_string(point.x);
  text += ", ";
  text += to_string(point.y);
  text += "]";
  return text;
}

Rational reduce_degrees(const Rational& degrees) {
  // The turns to take off: k = ceil((degrees - 180) / 360), so that degrees - 360 k is in (-180, 180].
  const Rational turns = (degrees - 180) / 360;
  mpz_class k;
  mpz_cdiv_q(k.get_mpz_t(), turns.get_num_mpz_t(), turns.get_den_mpz_t());
  return degrees - 360 * Rational(k);
}

double to_double(const Rational& value) {
  mpfr_t rounded;
  mpfr_init2(rounded, 53);
  mpfr_set_q(rounded, value.get_mpq_t(), MPFR_RNDN);
  const double result = mpfr_get_d(rounded, MPFR_RNDN);
  mpfr_clear(rounded);
  return result;
}

}  // namespace polyplan
