#pragma once
// Real algebraic numbers (CORE's Expr: exact +, −, ×, ÷ and √, signs decided exactly) for the
// tangent paths of a disc robot, whose points are irrational: a tangent point from a rational point
// to a rational circle is a + b√c. Only roadmaps/'s tangent visibility units include this header
// (CORE is heavy to compile).
#include <polyplan/geometry/detail/round_rules.hpp>

#include <CGAL/CORE_Expr.h>

#include <string>

namespace polyplan {

using Algebraic = CORE::Expr;
using AlgebraicPoint = round_rules::P<Algebraic>;

inline Algebraic algebraic(const Rational& q) { return Algebraic(CORE::BigRat(q.get_mpq_t())); }
inline AlgebraicPoint algebraic(const ExactPoint& p) { return {algebraic(p.x), algebraic(p.y)}; }

// The square root of x, which is ≥ 0 exactly. CORE's floating-point filter complains when the
// double it carries for x is below 0 though x is not (x = 0 or nearly so, rounded the wrong way):
// it appends a line to a file "Core_Diagnostics" in the working directory, and exits the program
// where it cannot write one. There the root is taken as √|x·x|^(1/2), whose filter doubles are
// squares: the same number, a node of higher degree (so slower to sign), and no complaint.
inline Algebraic root(const Algebraic& x) {
  if (x.sign() == 0) return Algebraic(0);
  if (x.Rep()->ffVal.getValue() > 0) return CORE::sqrt(x);
  return CORE::sqrt(CORE::sqrt(x * x));
}

// The double nearest x, as a message or the JSON prints a point: x to 80 bits, then rounded to
// nearest (CORE's own doubleValue() may be a unit in the last place off: 1/5 is not 0.2).
inline double approximate(const Algebraic& x) {
  const CORE::BigRat q = x.approx(CORE::extLong(80), CORE::extLong(1100)).BigRatValue();
  return to_double(Rational(q.get_mp()));
}

}  // namespace polyplan

template <>
struct polyplan::round_rules::Field<CORE::Expr> {
  static int sign(const CORE::Expr& x) { return x.sign(); }
  static std::string text(const CORE::Expr& x) { return std::to_string(x.doubleValue()); }
};
