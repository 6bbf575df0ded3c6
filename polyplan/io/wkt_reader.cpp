#include <polyplan/io/wkt_reader.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/detail/text_file.hpp>

#include <cctype>
#include <string_view>

namespace polyplan {
namespace {

// A recursive-descent reader of the two WKT types a world uses, written here rather than taken
// from CGAL/Boost.Geometry: those crashed on empty rings (POLYGON(()), POLYGON EMPTY), accepted
// NaN and Inf, compared keywords case-sensitively and looped for ever on unknown types.
//
//   file     := { geometry }
//   geometry := "POLYGON" polygon | "MULTIPOLYGON" "(" polygon { "," polygon } ")"
//   polygon  := "(" ring { "," ring } ")"
//   ring     := "(" x y { "," x y } ")"
//
// Keywords in any case; no EMPTY, no Z or M coordinates. Numbers are read exactly, refused
// outside the supported range, and then, as docs/design.md says, rounded to the nearest double.
class WktParser {
 public:
  WktParser(std::string_view text, std::string prefix) : text_(text), prefix_(std::move(prefix)) {}

  std::vector<PolygonWithHoles> file() {
    std::vector<PolygonWithHoles> obstacles;
    while (skip_space(), pos_ < text_.size()) {
      geometry_line_ = line_;
      type_ = word();
      if (type_ == "POLYGON") {
        obstacles.push_back(polygon());
      } else if (type_ == "MULTIPOLYGON") {
        if (peek_word() == "EMPTY") malformed("EMPTY holds no polygon");
        expect('(');
        do obstacles.push_back(polygon());
        while (comma_or(')'));
      } else {
        throw InputError(prefix_ + "line " + std::to_string(geometry_line_) +
                         ": cannot read WKT: expected POLYGON or MULTIPOLYGON, got \"" +
                         detail::abbreviated_text(type_) + "\"");
      }
    }
    if (obstacles.empty()) throw InputError(prefix_ + "cannot read WKT: the file holds no POLYGON or MULTIPOLYGON");
    return obstacles;
  }

 private:
  PolygonWithHoles polygon() {
    if (peek_word() == "EMPTY") malformed("EMPTY holds no polygon");
    PolygonWithHoles polygon;
    expect('(');
    polygon.outer = ring();
    while (comma_or(')')) polygon.holes.push_back(ring());
    return polygon;
  }

  Ring ring() {
    expect('(');
    if (skip_space(), pos_ < text_.size() && text_[pos_] == ')') malformed("empty ring");
    Ring r;
    do {
      const Rational x = number(), y = number();
      if (skip_space(), pos_ < text_.size() && number_char(text_[pos_]))
        malformed("a point has more than two coordinates");
      r.push_back({x, y});
    } while (comma_or(')'));
    // WKT closes a ring by repeating its first point; polyplan's rings are implicitly closed.
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    return r;
  }

  Rational number() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && number_char(text_[pos_])) ++pos_;
    if (pos_ == start) malformed("expected a number, got " + describe_next(start));
    const std::string_view token = text_.substr(start, pos_ - start);
    std::string why;
    const auto exact = parse_rational(token, &why);
    if (!exact) malformed("number \"" + detail::abbreviated_text(std::string(token)) + "\": " + why);
    return Rational(to_double(*exact));
  }

  // Reads ',' (true) or the closing `close` (false).
  bool comma_or(char close) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == ',') return ++pos_, true;
    expect(close);
    return false;
  }

  void expect(char c) {
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != c)
      malformed(std::string("expected '") + c + "', got " + describe_next(pos_));
    ++pos_;
  }

  std::string word() {
    skip_space();
    std::string w;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])))
      w.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++]))));
    if (w.empty()) {  // not a keyword at all: name what is there, up to the next separator
      while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) && text_[pos_] != '(')
        w.push_back(text_[pos_++]);
    }
    return w;
  }

  std::string peek_word() {
    const std::size_t pos = pos_, line = line_;
    std::string w = word();
    pos_ = pos, line_ = line;
    return w;
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  static bool number_char(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E' ||
           c == '/';
  }

  std::string describe_next(std::size_t at) const {
    if (at >= text_.size()) return "the end of the file";
    std::size_t end = at;
    auto separator = [](char c) {
      return std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == '(' || c == ')';
    };
    while (end < text_.size() && end - at < 20 && !separator(text_[end])) ++end;
    std::string quoted = "\"";  // appended: GCC 12 takes "\"" + string for an out-of-bounds copy
    quoted += text_.substr(at, std::max<std::size_t>(end - at, 1));
    quoted += '"';
    return quoted;
  }

  [[noreturn]] void malformed(const std::string& why) const {
    throw InputError(prefix_ + "line " + std::to_string(geometry_line_) + ": cannot read WKT: malformed " + type_ +
                     ": " + why);
  }

  std::string_view text_;
  std::string prefix_;
  std::size_t pos_ = 0, line_ = 1, geometry_line_ = 1;
  std::string type_;
};

}  // namespace

std::vector<PolygonWithHoles> parse_wkt_obstacles(const std::string& text, const std::string& prefix) {
  return WktParser(text, prefix).file();
}

std::vector<PolygonWithHoles> read_wkt_obstacles(const std::string& wkt_path, const std::string& from_file) {
  const std::string prefix = from_file + ": obstacles_wkt \"" + wkt_path + "\": ";
  return parse_wkt_obstacles(detail::read_text_file(wkt_path, prefix.substr(0, prefix.size() - 2)), prefix);
}

}  // namespace polyplan
