#pragma once
// Helpers the test programs share: worlds described inline as JSON text, exact points, rings
// compared as cycles, exact areas, scratch files, and the message of an expected InputError.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/world_reader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace polyplan {
// Lets GoogleTest print points in failure messages, as polyplan's own messages name them.
inline void PrintTo(const ExactPoint& p, std::ostream* os) { *os << to_string(p); }
}  // namespace polyplan

namespace polyplan::test {

inline World world_from(const std::string& json) { return parse_world(json, "test.json"); }

// A world of data/worlds by its name ("u_trap").
inline World shipped(const std::string& name) {
  return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json");
}

inline ExactPoint pt(const std::string& x, const std::string& y) { return {*parse_rational(x), *parse_rational(y)}; }

// A query named "q" from start to goal.
inline Query between(const ExactPoint& start, const ExactPoint& goal) { return Query{start, goal, "q"}; }

// A ring rotated to start at its lexicographically smallest vertex, so that two descriptions of
// the same cycle compare equal.
inline Ring canonical(Ring ring) {
  auto less = [](const ExactPoint& a, const ExactPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), less), ring.end());
  return ring;
}

// The exact shoelace area of a closed ring: positive counter-clockwise, negative clockwise.
inline Rational signed_area(const Ring& ring) {
  Rational twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

// The area of a polygon oriented as validated worlds and C-spaces are (outer counter-clockwise,
// holes clockwise): the holes' negative areas subtract themselves.
inline Rational area(const PolygonWithHoles& polygon) {
  Rational total = signed_area(polygon.outer);
  for (const Ring& hole : polygon.holes) total += signed_area(hole);
  return total;
}

// A shipped data file: data/<relative>.
inline std::string data_file(const std::string& relative) {
  return std::string(POLYPLAN_SOURCE_DIR) + "/data/" + relative;
}

// The path of `name` in this test program's own scratch folder under GoogleTest's temporary
// directory (the process id keeps concurrent runs apart; the folder goes when the program ends).
inline std::string temp_path(const std::string& name) {
  static const struct Folder {
    std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / ("polyplan_tests_" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  } folder;
  std::filesystem::create_directories(folder.path);
  return (folder.path / name).string();
}

// Writes `text` to temp_path(name) and returns that path (readers' messages name it).
inline std::string write_temp_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The message of the InputError that `f()` throws, or "no InputError" when it returns.
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

}  // namespace polyplan::test
