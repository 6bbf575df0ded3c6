#pragma once
// JSON parsing that keeps every floating-point literal as its source text, so that a file's 0.1
// can be read as exactly 1/10 (geometry/rational.hpp's parse_rational). Shared by the world
// reader and the arm reader; not installed (nlohmann is a private dependency).
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/io/detail/text_file.hpp>

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace polyplan::detail {

// Builds the usual DOM, except that floating-point literals are kept as their source text
// (a string), so that 0.1 can be read as exactly 1/10. Integers arrive exact already.
// On the way it keeps the path of keys and indices to the current value, so that a problem
// found while parsing names its object; refuses nesting deeper than limits::json_depth and an
// object that repeats a key (which nlohmann would silently resolve to the last value).
class ExactNumberSax {
 public:
  using json = nlohmann::json;
  explicit ExactNumberSax(json& root) : dom_(root, /*allow_exceptions=*/false) {}
  bool null() { return value(dom_.null()); }
  bool boolean(bool v) { return value(dom_.boolean(v)); }
  bool number_integer(json::number_integer_t v) { return value(dom_.number_integer(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return value(dom_.number_unsigned(v)); }
  bool number_float(json::number_float_t, const json::string_t& text) {
    json::string_t copy = text;
    return value(dom_.string(copy));
  }
  bool string(json::string_t& v) { return value(dom_.string(v)); }
  bool binary(json::binary_t& v) { return value(dom_.binary(v)); }
  bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
  bool key(json::string_t& k) {
    Frame& frame = frames_.back();
    if (!frame.keys.insert(k).second) {
      frame.key.clear();  // name the object that repeats the key
      error = where() + ": duplicate key \"" + abbreviated_text(k) + "\"";
      return false;
    }
    frame.key = k;
    return dom_.key(k);
  }
  bool end_object() { return close(dom_.end_object()); }
  bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
  bool end_array() { return close(dom_.end_array()); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    const std::string at = " at byte " + std::to_string(position);
    // nlohmann converts numbers to double while lexing: one beyond double's range fails here,
    // before its text reaches number_float.
    if (ex.id == 406) error = where() + ": number" + at + " overflows " + limits::supported_number_range();
    else
      error = "invalid JSON" + at + (frames_.empty() ? "" : " (in " + where() + ")") + ": " +
              abbreviated_text(ex.what(), 160);
    return false;
  }
  std::string error;

 private:
  struct Frame {
    bool array;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> keys;
  };

  // "obstacles[2].outer[0]": the value being read, as messages name objects.
  std::string where() const {
    std::string path;
    for (const Frame& f : frames_) {
      if (f.array) {  // appended piece by piece: GCC 12 takes "[" + string for an out-of-bounds copy
        path += '[';
        path += std::to_string(f.index);
        path += ']';
      } else if (!f.key.empty()) path += (path.empty() ? "" : ".") + abbreviated_text(f.key);
    }
    return path.empty() ? "top level" : path;
  }
  bool open(bool array) {
    if (static_cast<int>(frames_.size()) >= limits::json_depth) {
      error = where() + ": nested deeper than the supported " + std::to_string(limits::json_depth) + " levels";
      return false;
    }
    frames_.push_back(Frame{array, 0, {}, {}});
    return true;
  }
  bool close(bool ok) {
    frames_.pop_back();
    return value(ok);
  }
  // A value is complete: the enclosing array moves on to its next index.
  bool value(bool ok) {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return ok;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Frame> frames_;
};

// Parses `text` with floating-point literals kept as strings; throws InputError "<file>: <why>".
inline nlohmann::json parse_exact_json(const std::string& text, const std::string& file) {
  nlohmann::json root;
  ExactNumberSax sax(root);
  if (!nlohmann::json::sax_parse(text, &sax))
    throw InputError(file + ": " + (sax.error.empty() ? "invalid JSON" : sax.error));
  return root;
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
        warnings->push_back(file_ + ": " + object + ": unknown field \"" + abbreviated_text(item.key()) + "\" ignored");
  }

  static std::string abbreviated(const json& v) { return abbreviated_text(v.dump()); }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace polyplan::detail
