#pragma once
// JSON parsing that keeps every floating-point literal as its source text, so that a file's 0.1
// can be read as exactly 1/10 (geometry/rational.hpp's parse_rational). Shared by the world
// reader and the arm reader; not installed (nlohmann is a private dependency).
#include <polyplan/geometry/input_error.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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

// A file's whole text; InputError "<path>: cannot open file".
inline std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// What every reader of polyplan's JSON files shares: the file name, so that every message is
// one line "FILE: OBJECT: problem", and the checks that do not depend on the file's kind.
class JsonFileReader {
 public:
  using json = nlohmann::json;
  explicit JsonFileReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& object, const std::string& problem) const {
    throw InputError(file_ + ": " + object + ": " + problem);
  }

  json parse(const std::string& text) const { return parse_exact_json(text, file_); }

  const json& required(const json& object_value, const char* key, const std::string& object) const {
    if (!object_value.contains(key)) fail(object, std::string("missing field \"") + key + "\"");
    return object_value[key];
  }

  // Unknown fields are warned about (when warnings are collected) and ignored.
  void warn_unknown(const json& v, const std::string& object, const std::set<std::string>& known,
                    std::vector<std::string>* warnings) const {
    if (!warnings) return;
    for (const auto& item : v.items())
      if (!known.count(item.key()))
        warnings->push_back(file_ + ": " + object + ": unknown field \"" + item.key() + "\" ignored");
  }

  static std::string abbreviated(const json& v) {
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace polyplan::detail
