#pragma once
// Floating-point bounds that hold in real arithmetic, for the arm's certificates (docs/design.md: "a
// bound evaluated in floating point is a proof only with outward rounding"). Two tools:
//  - CGAL's interval numbers, evaluated with the processor rounding upward (RoundingUpward: one
//    guard around a stretch of interval code; CGAL derives every lower bound from upward rounding
//    by negation). Nothing else may run inside such a stretch: CGAL's filtered predicates (Epick)
//    assume rounding to nearest, and so do libm's cos and sin.
//  - above/below for a single result computed in the default rounding (to nearest): the next
//    double up or down bounds the real result, whose rounding to nearest is within half an ulp.
// Private to arm/ (CGAL stays out of installed headers).
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace polyplan::detail {

using Interval = CGAL::Interval_nt<false>;  // its operations assume RoundingUpward is in force
using RoundingUpward = CGAL::Protect_FPU_rounding<true>;

// The next double up: for x rounded from a real y (to nearest, or upward, or downward),
// below(x) <= y <= above(x). Infinities and NaN stay. std::nextafter's work, inline: these sit in
// the innermost loops of the clearances.
inline double above(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);  // a negative x nearer 0 is larger
}
inline double below(double x) { return -above(-x); }

// With RoundingUpward in force: the largest distance from x to a point of [lo, hi], rounded up.
inline double farthest_from(double x, double lo, double hi) {
  return std::max({x - lo, lo - x, x - hi, hi - x});  // each difference rounded up; the largest is the farther end's
}

// How long a clearance c (a lower bound) lasts at speed v (an upper bound), rounded down: c / v;
// forever for a positive c that does not move; not at all for c = 0, which proves nothing.
inline double lasts_below(double c, double v) {
  if (c == 0) return 0.0;
  if (!(v > 0)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, below(c / v));
}

// The distance covered at speed v (an upper bound) in the time t, rounded up (0 when v is 0, also
// for an endless t).
inline double covered_above(double v, double t) { return v > 0 ? above(v * t) : 0.0; }

}  // namespace polyplan::detail
