#include <polyplan/geometry/root_sum.hpp>

#include <CGAL/CORE_Expr.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace polyplan {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// √square rounded `way`: MPFR rounds the conversion and the root the same way, so the result is
// on that side of the exact root.
double root_rounded(const Rational& square, mpfr_rnd_t way) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, square.get_mpq_t(), way);
  mpfr_sqrt(x, x, way);
  const double result = mpfr_get_d(x, way);
  mpfr_clear(x);
  return result;
}

// √q when it is rational (numerator and denominator perfect squares), which CORE then need not
// treat as a root.
std::optional<Rational> rational_root(const Rational& q) {
  if (!mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t())) return std::nullopt;
  mpz_class num, den;
  mpz_sqrt(num.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(den.get_mpz_t(), q.get_den_mpz_t());
  return Rational(num, den);
}

// The terms of a − b that do not cancel: a term in both sums adds nothing to the difference.
// Cancelling them first keeps CORE's work to the terms that differ: two paths through the same
// corners, or a path and its mirror image, leave nothing to decide.
void cancel_common(std::vector<Rational>& a, std::vector<Rational>& b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::vector<Rational> only_a, only_b;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
  a = std::move(only_a), b = std::move(only_b);
}

// Adds ±√q for each q to `roots`, or ±√q to `rational` where the root is rational.
void collect(const std::vector<Rational>& squares, int sign, CORE::Expr& roots, Rational& rational) {
  for (const Rational& q : squares) {
    if (auto r = rational_root(q)) {
      rational += sign * *r;
    } else {
      const CORE::Expr root = CORE::sqrt(CORE::Expr(CORE::BigRat(q.get_mpq_t())));
      roots = sign > 0 ? roots + root : roots - root;
    }
  }
}

// The sign of Σ√a − Σ√b − c, exactly.
int exact_sign(std::vector<Rational> a, std::vector<Rational> b, const Rational& c) {
  cancel_common(a, b);
  CORE::Expr roots(0);
  Rational rational = -c;
  collect(a, 1, roots, rational);
  collect(b, -1, roots, rational);
  return (roots + CORE::Expr(CORE::BigRat(rational.get_mpq_t()))).sign();
}

}  // namespace

LengthBounds operator+(const LengthBounds& a, const LengthBounds& b) {
  return {std::nextafter(a.lower + b.lower, -infinity), std::nextafter(a.upper + b.upper, infinity)};
}

LengthBounds root_bounds(const Rational& square) {
  return {root_rounded(square, MPFR_RNDD), root_rounded(square, MPFR_RNDU)};
}

LengthBounds rational_bounds(const Rational& c) {
  const double nearest = to_double(c);  // within half a unit in the last place of c
  return {std::nextafter(nearest, -infinity), std::nextafter(nearest, infinity)};
}

int compare_bounds(const LengthBounds& a, const LengthBounds& b) {
  if (a.upper < b.lower) return -1;
  if (a.lower > b.upper) return 1;
  return 0;
}

Rational squared_distance(const ExactPoint& a, const ExactPoint& b) {
  const Rational dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

LengthBounds distance_bounds(const ExactPoint& a, const ExactPoint& b) { return root_bounds(squared_distance(a, b)); }

LengthBounds distance_bounds(double ax, double ay, double bx, double by) {
  const double length = std::hypot(ax - bx, ay - by);
  const double largest = std::max({std::abs(ax), std::abs(ay), std::abs(bx), std::abs(by)});
  const double slack = std::ldexp(length + largest, -49);
  return {std::max(0.0, std::nextafter(length - slack, -infinity)), std::nextafter(length + slack, infinity)};
}

RootSum RootSum::polyline(const std::vector<ExactPoint>& points) {
  RootSum sum;
  for (std::size_t i = 1; i < points.size(); ++i) sum.add(squared_distance(points[i - 1], points[i]));
  return sum;
}

void RootSum::add(const Rational& square) { add(square, root_bounds(square)); }

void RootSum::add(const Rational& square, const LengthBounds& bounds) {
  if (sgn(square) == 0) return;
  squares_.push_back(square);
  bounds_ = squares_.size() == 1 ? bounds : bounds_ + bounds;
}

void RootSum::add(const RootSum& other) {
  if (other.squares_.empty()) return;
  squares_.insert(squares_.end(), other.squares_.begin(), other.squares_.end());
  bounds_ = squares_.size() == other.squares_.size() ? other.bounds_ : bounds_ + other.bounds_;
}

int compare(const RootSum& a, const RootSum& b) {
  if (const int sign = compare_bounds(a.bounds(), b.bounds())) return sign;
  return exact_sign(a.squares(), b.squares(), 0);
}

int compare(const RootSum& a, const Rational& c) {
  if (sgn(c) < 0) return 1;  // a length is never below 0
  if (const int sign = compare_bounds(a.bounds(), rational_bounds(c))) return sign;
  return exact_sign(a.squares(), {}, c);
}

}  // namespace polyplan
