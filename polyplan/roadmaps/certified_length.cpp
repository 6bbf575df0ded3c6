// How roadmaps/detail/certified_length.hpp bounds a length, step by step:
//  - a segment: √|b − a|² is a CORE number; its doubleInterval is the pair of consecutive doubles
//    around it, decided by an exact sign (CORE's Expr::doubleInterval);
//  - an arc: the counter-clockwise angle θ from a = from − c to b = to − c is atan2(a×b, a·b) when
//    a×b > 0, 2π − atan2(−a×b, a·b) when a×b < 0 (0 or π on the line, decided exactly). The cross
//    and dot products are bounded by doubleInterval; atan2 over that box lies between its values at
//    the box's corners (the box lies in the open upper half-plane, where the angle is monotone
//    along each side), each computed by MPFR rounded down for the lower bound and up for the upper;
//    π likewise. The radius is rational: MPFR rounds it each way; the product of the positive bounds
//    is rounded outward.
#include <polyplan/roadmaps/detail/certified_length.hpp>

#include <polyplan/geometry/detail/rounded_angles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan::tangent {
namespace {

using round_rules::cross;
using round_rules::dot;
using round_rules::sign_of;
using round_rules::squared;
using polyplan::detail::pi_rounded;
using Big = polyplan::detail::RoundedNumber;

double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

LengthBounds angle(const AlgebraicPoint& a, const AlgebraicPoint& b) {
  const Algebraic c = cross(a, b), d = dot(a, b);
  const int turn = sign_of(c);
  if (turn == 0)
    return sign_of(d) > 0 ? LengthBounds{0, 0} : LengthBounds{pi_rounded(MPFR_RNDD), pi_rounded(MPFR_RNDU)};
  double clo = 0, chi = 0, dlo = 0, dhi = 0;
  (turn > 0 ? c : -c).doubleInterval(clo, chi);
  d.doubleInterval(dlo, dhi);
  const polyplan::detail::AngleBounds half = polyplan::detail::upper_half_angle(clo, chi, dlo, dhi);
  const LengthBounds theta{half.lower, half.upper};
  if (turn > 0) return theta;
  // 2π − θ: twice π is exact in binary; the difference rounded outward.
  return {down(2 * pi_rounded(MPFR_RNDD) - theta.upper), up(2 * pi_rounded(MPFR_RNDU) - theta.lower)};
}

}  // namespace

LengthBounds segment_length(const AlgebraicPoint& a, const AlgebraicPoint& b) {
  LengthBounds out;
  root(squared(b - a)).doubleInterval(out.lower, out.upper);
  return out;
}

LengthBounds arc_length(const Arc& arc) {
  const LengthBounds theta = angle(arc.from - arc.circle->centre, arc.to - arc.circle->centre);
  Big rlo, rhi, lo, hi, tlo, thi;
  mpfr_set_q(rlo.get(), arc.circle->exact_radius.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(rhi.get(), arc.circle->exact_radius.get_mpq_t(), MPFR_RNDU);
  mpfr_set_d(tlo.get(), theta.lower, MPFR_RNDN);
  mpfr_set_d(thi.get(), theta.upper, MPFR_RNDN);
  mpfr_mul(lo.get(), rlo.get(), tlo.get(), MPFR_RNDD);
  mpfr_mul(hi.get(), rhi.get(), thi.get(), MPFR_RNDU);
  return {std::max(0.0, lo.rounded(MPFR_RNDD)), hi.rounded(MPFR_RNDU)};
}

LengthBounds operator+(const LengthBounds& a, const LengthBounds& b) {
  return {down(a.lower + b.lower), up(a.upper + b.upper)};
}

LengthBounds length_bounds(const CirclePiece& piece, const std::vector<Circle>& circles) {
  return piece.circle ? arc_length(arc_of(piece, circles)) : segment_length(piece.from, piece.to);
}

PathPiece path_piece(const CirclePiece& piece, const std::vector<Circle>& circles, const ExactPoint& from,
                     const ExactPoint& to, const LengthBounds& bounds) {
  const auto doubles = [](const ExactPoint& p) { return FactPoint{to_double(p.x), to_double(p.y)}; };
  PathPiece out;
  out.from = doubles(from);
  out.to = doubles(to);
  out.length = (bounds.lower + bounds.upper) / 2;
  if (piece.circle) {
    out.kind = PathPiece::Kind::arc;
    out.centre = doubles(circles[*piece.circle].exact_centre);
    out.radius = to_double(circles[*piece.circle].exact_radius);
    out.counter_clockwise = piece.counter_clockwise;
  }
  return out;
}

}  // namespace polyplan::tangent
