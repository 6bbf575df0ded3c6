#pragma once
// JSON parsing that keeps every floating-point literal as its source text, so that a file's 0.1
// can be read as exactly 1/10 (geometry/rational.hpp's parse_rational). Shared by the world
// reader and the arm reader; not installed (nlohmann is a private dependency).
#include "geometry/input_error.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace polyplan::detail {

// Builds the usual DOM, except that floating-point literals are kept as their source text
// (a string), so that 0.1 can be read as exactly 1/10. Integers arrive exact already.
class ExactNumberSax {
 public:
  using json = nlohmann::json;
  explicit ExactNumberSax(json& root) : dom_(root, /*allow_exceptions=*/false) {}
  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(json::number_float_t, const json::string_t& text) {
    json::string_t copy = text;
    return dom_.string(copy);
  }
  bool string(json::string_t& v) { return dom_.string(v); }
  bool binary(json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) { return dom_.start_object(n); }
  bool key(json::string_t& k) { return dom_.key(k); }
  bool end_object() { return dom_.end_object(); }
  bool start_array(std::size_t n) { return dom_.start_array(n); }
  bool end_array() { return dom_.end_array(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    // nlohmann converts numbers to double while lexing: one beyond double's range fails here,
    // before its text reaches number_float.
    if (ex.id == 406)
      error = "number out of range at byte " + std::to_string(position) + " (exponent too large): " + ex.what();
    else
      error = "invalid JSON at byte " + std::to_string(position) + ": " + ex.what();
    return false;
  }
  std::string error;

 private:
  nlohmann::detail::json_sax_dom_parser<json> dom_;
};

// Parses `text` with floating-point literals kept as strings; throws InputError "<file>: <why>".
inline nlohmann::json parse_exact_json(const std::string& text, const std::string& file) {
  nlohmann::json root;
  ExactNumberSax sax(root);
  if (!nlohmann::json::sax_parse(text, &sax))
    throw InputError(file + ": " + (sax.error.empty() ? "invalid JSON" : sax.error));
  return root;
}

}  // namespace polyplan::detail
