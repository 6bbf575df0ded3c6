#pragma once
// The area of a round world's free space (geometry/round_cspace.hpp): where the reference point
// keeps to (the box or the disc) outside every C-obstacle. Exact when every core has radius 0 and
// the bounds are a box (polygons only: walls of radius 0 have no area); otherwise certified bounds,
// lower ≤ area ≤ upper, from an exact union of discs and rational polygons that contains the
// C-obstacles and another that they contain (round_cspace_area.cpp says how).
#include <polyplan/geometry/round_cspace.hpp>

#include <optional>
#include <string>

namespace polyplan {

struct FreeArea {
  bool bounded = true;            // false without bounds: the free space is unbounded
  std::optional<Rational> exact;  // the area, when it is rational and computed exactly
  double lower = 0, upper = 0;    // lower ≤ area ≤ upper for sure (the exact area rounded outward
                                  // when there is one; +∞ when unbounded)
};

// `source` names the world's file in messages.
FreeArea round_free_area(const RoundCSpace& space, const std::string& source);

// "391.5 (exact)" (with the fraction when it is not an integer: "391.5 (exact, 783/2)"),
// "319.6 ≤ … ≤ 319.6, certified" (each bound to 12 significant digits, rounded outward), or
// "unbounded".
std::string free_area_text(const FreeArea& area);

}  // namespace polyplan
