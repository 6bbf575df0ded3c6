#pragma once
// A point with 64-bit integer coordinates: a MovingAI map's grid corner, a query of `polyplan
// scen`, a vertex of the integer triangulation (free_space/detail/integer_triangulation.hpp).
#include <cstdint>

namespace polyplan {

struct IntegerPoint {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const IntegerPoint&, const IntegerPoint&) = default;
};

}  // namespace polyplan
