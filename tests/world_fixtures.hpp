#pragma once
// Small helpers for tests that describe worlds inline as JSON text.
#include <polyplan/io/world_reader.hpp>

#include <algorithm>
#include <ostream>
#include <string>

namespace polyplan {
// Lets GoogleTest print points and rings in failure messages.
inline void PrintTo(const ExactPoint& p, std::ostream* os) { *os << "[" << to_string(p.x) << ", " << to_string(p.y) << "]"; }
}  // namespace polyplan

namespace polyplan::test {

inline World world_from(const std::string& json) { return parse_world(json, "test.json"); }

inline ExactPoint pt(const std::string& x, const std::string& y) {
  return {*parse_rational(x), *parse_rational(y)};
}

// A ring rotated to start at its lexicographically smallest vertex, so that two descriptions of
// the same cycle compare equal.
inline Ring canonical(Ring ring) {
  auto less = [](const ExactPoint& a, const ExactPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), less), ring.end());
  return ring;
}

}  // namespace polyplan::test
