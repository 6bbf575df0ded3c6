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

// The nearest doubles, as a message or the JSON prints a point.
inline double approximate(const Algebraic& x) { return x.doubleValue(); }

}  // namespace polyplan

template <>
struct polyplan::round_rules::Field<CORE::Expr> {
  static int sign(const CORE::Expr& x) { return x.sign(); }
  static std::string text(const CORE::Expr& x) { return std::to_string(x.doubleValue()); }
};
