#pragma once
// Exact check that a polyline is a valid motion under docs/design.md's semantics: it may touch and
// slide along C-obstacle boundaries, it never enters their interior, and it never passes
// through a zero-width passage (a pinch point where C-obstacles touch: the path must leave such
// a point into the free wedge it arrived from). Exact-fit corridors and seams between touching
// obstacles are interior to the joined C-obstacles, so entering them is caught as entering.
#include <polyplan/geometry/cspace.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

struct PathCheck {
  bool valid = true;
  std::string reason;                  // empty when valid
  std::optional<std::size_t> segment;  // the first offending segment (0-based), if any
};

PathCheck check_path(const CSpace& cspace, const std::vector<ExactPoint>& path);

// The straight motion from a to b (both ends included): the exact segment test for planners.
PathCheck check_segment(const CSpace& cspace, const ExactPoint& a, const ExactPoint& b);

}  // namespace polyplan
