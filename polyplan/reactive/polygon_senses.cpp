#include <polyplan/reactive/detail/tangent_senses.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan::walk {
namespace {

// The point of a-b at the rational copy of t, moved on towards the parameter `last` in growing
// steps until `holds` (which must hold at `last`): how an irrational event point becomes a
// rational point on the same line, a few ulps past it.
template <class Holds>
Point first_where(const Point& a, const Point& b, double t, const Rational& last, Holds holds) {
  const double end = to_double(last);
  double step = std::numeric_limits<double>::epsilon() * std::max(std::abs(t), std::numeric_limits<double>::min());
  for (t = std::max(t, 0.0); t < end; t += step, step *= 2)
    if (const Point p = along(a, b, Rational(t)); holds(p)) return p;
  return along(a, b, last);
}

}  // namespace

PolygonSenses::PolygonSenses(const Boundary& boundary, double range)
    : RangeSensor(range), boundary_(&boundary), regions_(boundary) {}

std::vector<Sighting<Point>> PolygonSenses::candidates(const Point& x, bool) const {
  std::vector<Sighting<Point>> out;
  for (const auto& [near, far] : windows(*boundary_, x, regions_.visible_from(x))) out.push_back({near});
  return out;
}

bool PolygonSenses::discontinuity(const Point& x, const Point& o) const {
  return senses(x, o) && check_segment(boundary_->cspace(), x, o).valid;
}

std::vector<Point> PolygonSenses::region(const Point& x) const {
  return within_range(regions_.visible_from(x), x, range());
}

Point PolygonSenses::short_of(const Point& x, const Point& hit, const Point&) const {
  const double t = 1 - range() / distance(x, hit);
  return first_where(x, hit, t, Rational(1), [&](const Point& p) { return senses(p, hit); });
}

Point PolygonSenses::ahead(const Point& x, const Point& end, const Point&) const {
  return along(x, end, Rational(range() / distance(x, end)));
}

std::optional<Point> PolygonSenses::nearer_than(Edge, bool, const Point& a, const Point& b, const Point& goal,
                                                const Rational& record) const {
  if (a == b) return std::nullopt;
  const Rational ab = squared(a, b);
  const Rational foot = std::clamp(Rational(dot(a, goal, b) / ab), Rational(0), Rational(1));
  if (!(squared(along(a, b, foot), goal) < record)) return std::nullopt;
  // |a + t(b - a) - goal|² = record: A t² + B t + C = 0 with A = |b - a|², B = 2 (a - goal)·(b - a).
  const double a2 = to_double(ab), b1 = 2 * to_double((a.x - goal.x) * (b.x - a.x) + (a.y - goal.y) * (b.y - a.y));
  const double c0 = to_double(squared(a, goal) - record);
  // The smaller root as c / q (b < 0 here, the distance falling): no cancellation.
  const double q = (-b1 + std::sqrt(std::max(0.0, b1 * b1 - 4 * a2 * c0))) / 2;
  const double root = q > 0 ? c0 / q : 0;
  return first_where(a, b, root, foot, [&](const Point& p) { return squared(p, goal) < record; });
}

Point PolygonSenses::cut(const Point& a, const Point& b, double fraction, const std::optional<Along>&) const {
  return along(a, b, Rational(fraction));
}

}  // namespace polyplan::walk
