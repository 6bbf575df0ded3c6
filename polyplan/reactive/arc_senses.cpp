#include <polyplan/reactive/detail/tangent_senses.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan::walk {
namespace {

using round_rules::dot;
using round_rules::sign_of;
using round_rules::squared;

AP times(const AP& v, const Algebraic& t) { return {v.x * t, v.y * t}; }

// A few units in the last place of t: the first step of a search for a point just within range.
double ulps(double t) {
  return 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), std::numeric_limits<double>::min());
}

}  // namespace

ArcSenses::ArcSenses(const ArcBoundary& boundary, double range) : RangeSensor(range), boundary_(&boundary) {}

std::vector<Sighting<AP>> ArcSenses::candidates(const AP& x, bool from_x) const {
  // Where the visible boundary may jump: at a corner, or where a sight line touches a circle of
  // the boundary (on a part of it that bounds the free space, or the point is not seen).
  std::vector<Sighting<AP>> out;
  std::vector<std::size_t> circles;
  for (std::size_t c = 0; c < boundary_->cycles().size(); ++c)
    for (const ArcPiece& piece : boundary_->cycles()[c]) {
      out.push_back({piece.from});
      if (piece.circle && std::find(circles.begin(), circles.end(), *piece.circle) == circles.end())
        circles.push_back(*piece.circle);
    }
  if (!from_x) return out;
  for (const std::size_t k : circles)
    for (const tangent::Tangent& t : tangent::common_tangents({x, Algebraic(0), {}, {}, ""}, boundary_->circles()[k]))
      out.push_back({t.to, true});
  return out;
}

bool ArcSenses::discontinuity(const AP& x, const AP& o) const {
  // Sensed, seen, and the sight runs on past it: the boundary there is behind, not ahead.
  return !(o == x) && senses(x, o) && boundary_->sees(x, o) && !boundary_->rules().blocked_at(o, std::nullopt, o - x);
}

AP ArcSenses::short_of(const AP& x, const AP& hit, const AP& goal) const {
  const AP way = goal - x;
  const double length = std::sqrt(approximate(squared(way))), to_hit = std::sqrt(approximate(squared(hit - x)));
  const double last = to_hit / length;
  double t = (to_hit - range()) / length, step = ulps(t);
  for (; t < last; t += step, step *= 2) {
    const AP p = x + times(way, algebraic(Rational(t)));
    if (senses(p, hit)) return sign_of(dot(hit - p, way)) >= 0 ? p : hit;  // (never past the obstacle)
  }
  return hit;
}

AP ArcSenses::ahead(const AP& x, const AP& end, const AP& goal) const {
  const AP way = goal - x;
  double t = range() / std::sqrt(approximate(squared(way))), step = ulps(t);
  for (; t > 0; t -= step, step *= 2)
    if (const AP p = x + times(way, algebraic(Rational(t))); senses(x, p)) return p;
  return x;
}

std::optional<AP> ArcSenses::nearer_than(Edge e, bool forward, const AP& a, const AP& b, const AP& goal,
                                         const Algebraic& record) const {
  if (a == b) return std::nullopt;
  if (squared(a - goal) < record) return a;
  const AP& first = forward ? a : b;  // the part in the piece's own order
  const AP& last = forward ? b : a;
  const AP nearest = boundary_->nearest(e, first, last, goal);
  if (!(squared(nearest - goal) < record)) return std::nullopt;
  // The distance falls below d_followed once before the nearest point (it rises, then falls, along
  // a segment or an arc): the last crossing of d_followed's circle before it, in walking order.
  std::optional<AP> crossing;
  for (const AP& p : boundary_->circle_points(e, first, last, goal, root(record)))
    if (before(e, forward, p, nearest) && (!crossing || before(e, forward, *crossing, p))) crossing = p;
  return crossing.value_or(nearest);
}

AP ArcSenses::slide_end(Edge e, bool forward, const AP& x, const AP& nearest, const AP& goal) const {
  std::optional<AP> end;
  const AP& first = forward ? x : nearest;
  const AP& last = forward ? nearest : x;
  for (const AP& p : boundary_->touching_points(e, first, last, goal))
    if (before(e, forward, x, p) && (!end || before(e, forward, p, *end))) end = p;
  return end.value_or(nearest);
}

AP ArcSenses::cut(const AP& a, const AP& b, double fraction, const std::optional<Along>& along) const {
  if (along && boundary_->piece(along->edge).circle) return a;
  return a + times(b - a, algebraic(Rational(fraction)));
}

}  // namespace polyplan::walk
