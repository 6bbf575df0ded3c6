#pragma once
// Lengths of a tangent path's pieces as intervals of doubles that hold the exact length for sure
// (outward rounding): a segment's length from CORE's exact interval of its square root, an arc's as
// radius × angle with MPFR's directed rounding of atan2 and of the products and sums.
#include <polyplan/plan/fact_key.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/roadmaps/detail/tangent_arcs.hpp>

namespace polyplan::tangent {

// The facts of a path's certified length: the exact length lies between them.
inline constexpr FactKey<double> length_lower{"length_lower"};
inline constexpr FactKey<double> length_upper{"length_upper"};

struct LengthBounds {
  double lower = 0, upper = 0;
};

LengthBounds segment_length(const AlgebraicPoint& a, const AlgebraicPoint& b);
// The counter-clockwise arc's length.
LengthBounds arc_length(const Arc& arc);
// The sum, rounded outward (one step of a double each way covers round-to-nearest's half step).
LengthBounds operator+(const LengthBounds& a, const LengthBounds& b);
// The piece's length: its segment's or its arc's.
LengthBounds length_bounds(const CirclePiece& piece, const std::vector<Circle>& circles);

// The piece as a report gives it (PlanReport::pieces): its ends as printed, its length the middle
// of its bounds, an arc's centre, radius and turn.
PathPiece path_piece(const CirclePiece& piece, const std::vector<Circle>& circles, const ExactPoint& from,
                     const ExactPoint& to, const LengthBounds& bounds);

}  // namespace polyplan::tangent
