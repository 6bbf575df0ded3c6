#include <polyplan/plan/planner_options.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace polyplan::detail {

std::optional<std::int64_t> parse_whole_number(std::string_view text) {
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::optional<double> parse_real_number(std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<bool> parse_flag(std::string_view text) {
  for (std::string_view yes : {"true", "yes", "on", "1"})
    if (text == yes) return true;
  for (std::string_view no : {"false", "no", "off", "0"})
    if (text == no) return false;
  return std::nullopt;
}

std::string show_number(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

std::string show_exact(const Rational& value) {
  // k digits after the point are exact when the denominator divides 10^k: it is 2^a 5^b, k = max(a, b).
  mpz_class rest = value.get_den();
  std::size_t twos = 0, fives = 0;
  for (; mpz_divisible_ui_p(rest.get_mpz_t(), 2); rest /= 2) ++twos;
  for (; mpz_divisible_ui_p(rest.get_mpz_t(), 5); rest /= 5) ++fives;
  if (rest != 1) return to_string(value);
  const std::size_t digits = std::max(twos, fives);
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, digits);
  const mpz_class scaled = abs(value.get_num()) * (scale / value.get_den());
  std::string text = scaled.get_str();
  if (digits > 0) {
    if (text.size() <= digits) text.insert(0, digits + 1 - text.size(), '0');
    text.insert(text.size() - digits, ".");
  }
  return (sgn(value) < 0 ? "-" : "") + text;
}

}  // namespace polyplan::detail

namespace polyplan {

std::string OptionRange::text() const {
  const auto end = [](double x) {
    return std::isinf(x) ? std::string(x < 0 ? "-inf" : "inf") : detail::show_number(x);
  };
  return (min_open ? "(" : "[") + end(min) + ", " + end(max) + (max_open ? ")" : "]");
}

}  // namespace polyplan
