#include <polyplan/reactive/detail/arc_boundary.hpp>

#include <polyplan/geometry/round_query.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace polyplan::walk {
namespace {

using round_rules::cross;
using round_rules::dot;
using round_rules::sign_of;
using round_rules::squared;

AP times(const AP& v, const Algebraic& t) { return {v.x * t, v.y * t}; }
AP left_of(const AP& v) { return {-v.y, v.x}; }
AP right_of(const AP& v) { return {v.y, -v.x}; }
AP middle(const AP& a, const AP& b) { return times(a + b, Algebraic(1) / Algebraic(2)); }

// A piece before cutting: a segment, or a whole circle (from and to unset).
struct Candidate {
  ArcPiece shape;
  bool whole = false;
};

// Box of a candidate in doubles, widened so that boxes apart prove the exact shapes apart — a filter
// that only skips the exact intersection of shapes it proves disjoint, never decides one. The error:
// approximate() is the nearest double (relative error ≤ 2⁻⁵³), and x ± r adds one rounding more,
// so each side is within 4·2⁻⁵³·M ≈ 4.5e-16·M of the exact box's, M the largest magnitude among the
// coordinates and the radius; the widening, 1e-9·(1 + M), is over a million times that.
struct Box {
  double xmin, ymin, xmax, ymax;
};
Box box_of(const Candidate& c, const std::vector<tangent::Circle>& circles) {
  const auto widen = [](Box b) {
    const double m = 1e-9 * (1 + std::max({std::abs(b.xmin), std::abs(b.ymin), std::abs(b.xmax), std::abs(b.ymax)}));
    return Box{b.xmin - m, b.ymin - m, b.xmax + m, b.ymax + m};
  };
  if (c.shape.circle) {
    const tangent::Circle& k = circles[*c.shape.circle];
    const double x = approximate(k.centre.x), y = approximate(k.centre.y), r = approximate(k.radius);
    return widen({x - r, y - r, x + r, y + r});
  }
  const double ax = approximate(c.shape.from.x), ay = approximate(c.shape.from.y);
  const double bx = approximate(c.shape.to.x), by = approximate(c.shape.to.y);
  return widen({std::min(ax, bx), std::min(ay, by), std::max(ax, bx), std::max(ay, by)});
}
bool apart(const Box& a, const Box& b) {
  return a.xmax < b.xmin || b.xmax < a.xmin || a.ymax < b.ymin || b.ymax < a.ymin;
}

// The points where the segment a-b meets the circle (centre c, radius r).
void segment_circle(const AP& a, const AP& b, const AP& c, const Algebraic& r, std::vector<AP>& out) {
  const AP d = b - a, f = a - c;
  const Algebraic dd = squared(d), fd = dot(f, d), room = fd * fd - dd * (squared(f) - r * r);
  if (sign_of(dd) == 0 || sign_of(room) < 0) return;
  const Algebraic w = root(room);
  for (const Algebraic& t : {(-fd - w) / dd, (-fd + w) / dd})
    if (sign_of(t) >= 0 && t <= Algebraic(1)) out.push_back(a + times(d, t));
}

// The points where two circles meet (none for concentric ones).
void circle_circle(const tangent::Circle& p, const tangent::Circle& q, std::vector<AP>& out) {
  const AP d = q.centre - p.centre;
  const Algebraic dd = squared(d);
  if (sign_of(dd) == 0) return;
  const Algebraic along = (dd + p.radius * p.radius - q.radius * q.radius) / (Algebraic(2) * dd);
  const Algebraic h2 = p.radius * p.radius / dd - along * along;
  if (sign_of(h2) < 0) return;
  const AP foot = p.centre + times(d, along);
  const Algebraic h = root(h2);
  out.push_back(foot + times(left_of(d), h));
  if (sign_of(h2) > 0) out.push_back(foot - times(left_of(d), h));
}

// The points where the segments a-b and p-q meet (a collinear overlap: the ends inside the other).
void segment_segment(const AP& a, const AP& b, const AP& p, const AP& q, std::vector<AP>& out) {
  const AP d = b - a, e = q - p;
  const auto on_ab = [&](const AP& x) { return sign_of(dot(x - a, x - b)) <= 0; };
  const Algebraic denominator = cross(d, e);
  if (sign_of(denominator) == 0) {
    if (sign_of(cross(d, p - a)) != 0) return;
    for (const AP& x : {p, q})
      if (on_ab(x)) out.push_back(x);
    return;
  }
  const Algebraic t = cross(p - a, e) / denominator, s = cross(p - a, d) / denominator;
  if (sign_of(t) >= 0 && t <= Algebraic(1) && sign_of(s) >= 0 && s <= Algebraic(1)) out.push_back(a + times(d, t));
}

class Builder {
 public:
  Builder(const RoundCSpace& space, std::vector<tangent::Circle>& circles) : circles_(circles) {
    std::size_t next = 0;  // circles_of's order: a disc, or a core's vertices ring by ring
    for (const RoundCore& core : space.obstacles) {
      const Algebraic r = algebraic(core.radius);
      if (core.kind == RoundCore::Kind::point) {
        whole(next++, false);
        continue;
      }
      for (std::size_t k = 0; k + 1 < core.points.size(); ++k) {  // a wall: both its sides
        side(algebraic(core.points[k]), algebraic(core.points[k + 1]), r);
        side(algebraic(core.points[k + 1]), algebraic(core.points[k]), r);
      }
      for (std::size_t k = 0; k < core.points.size(); ++k) corner(next++, r);
      for (const Ring& ring : core.rings)  // the polygon on each edge's left
        for (std::size_t k = 0; k < ring.size(); ++k) {
          side(algebraic(ring[k]), algebraic(ring[(k + 1) % ring.size()]), r);
          corner(next++, r);
        }
    }
    if (const auto& b = space.box) {  // the free space inside: counter-clockwise
      const AP corners[] = {algebraic(ExactPoint{b->xmin, b->ymin}), algebraic(ExactPoint{b->xmax, b->ymin}),
                            algebraic(ExactPoint{b->xmax, b->ymax}), algebraic(ExactPoint{b->xmin, b->ymax})};
      for (int k = 0; k < 4; ++k) candidates_.push_back({{corners[k], corners[(k + 1) % 4], std::nullopt, true}});
    }
    if (const auto& disc = space.disc; disc && disc->radius > 0) {  // (the robot may not fit: no free space)
      circles_.push_back({algebraic(disc->center), algebraic(disc->radius), disc->center, disc->radius, "the bounds"});
      whole(circles_.size() - 1, true);
    }
  }

  // Every candidate cut where another meets it.
  std::vector<ArcPiece> cut() const {
    std::vector<Box> boxes;
    for (const Candidate& c : candidates_) boxes.push_back(box_of(c, circles_));
    std::vector<ArcPiece> out;
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
      std::vector<AP> points;
      if (!candidates_[i].whole) points = {candidates_[i].shape.from, candidates_[i].shape.to};
      for (std::size_t j = 0; j < candidates_.size(); ++j)
        if (j != i && !apart(boxes[i], boxes[j])) meet(candidates_[i], candidates_[j], points);
      split(candidates_[i], std::move(points), out);
    }
    return out;
  }

 private:
  // The side a→b of a core with the core on its left, moved out by r and walked the other way.
  void side(const AP& a, const AP& b, const Algebraic& r) {
    AP shift{Algebraic(0), Algebraic(0)};
    if (sign_of(r) > 0) shift = times(right_of(b - a), r / root(squared(b - a)));
    candidates_.push_back({{b + shift, a + shift, std::nullopt, true}});
  }
  void corner(std::size_t circle, const Algebraic& r) {
    if (sign_of(r) > 0) whole(circle, false);
  }
  // An obstacle's circle walked clockwise (the disc on the right), the bounds' counter-clockwise.
  void whole(std::size_t circle, bool counter_clockwise) {
    candidates_.push_back({{{}, {}, circle, counter_clockwise}, true});
    candidates_.back().whole = true;
  }

  void meet(const Candidate& a, const Candidate& b, std::vector<AP>& out) const {
    const auto& [p, q] = std::pair(a.shape, b.shape);
    if (!p.circle && !q.circle) return segment_segment(p.from, p.to, q.from, q.to, out);
    if (p.circle && q.circle) return circle_circle(circles_[*p.circle], circles_[*q.circle], out);
    const ArcPiece& s = p.circle ? q : p;
    const tangent::Circle& c = circles_[*(p.circle ? p.circle : q.circle)];
    segment_circle(s.from, s.to, c.centre, c.radius, out);
  }

  void split(const Candidate& c, std::vector<AP> points, std::vector<ArcPiece>& out) const {
    const ArcPiece& s = c.shape;
    if (!s.circle) {
      const AP d = s.to - s.from;
      std::sort(points.begin(), points.end(),
                [&](const AP& x, const AP& y) { return dot(x - s.from, d) < dot(y - s.from, d); });
      points.erase(std::unique(points.begin(), points.end()), points.end());
      for (std::size_t k = 0; k + 1 < points.size(); ++k) out.push_back({points[k], points[k + 1], std::nullopt, true});
      return;
    }
    const tangent::Circle& circle = circles_[*s.circle];
    if (points.empty()) points.push_back(circle.centre + AP{circle.radius, Algebraic(0)});
    const AP first = points.front() - circle.centre;
    std::sort(points.begin(), points.end(), [&](const AP& x, const AP& y) {
      return tangent::turns_before(first, x - circle.centre, y - circle.centre);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() == 1) points.push_back(circle.centre - first);  // the antipode: two arcs, not one loop
    if (!s.counter_clockwise) std::reverse(points.begin(), points.end());
    for (std::size_t k = 0; k < points.size(); ++k)
      out.push_back({points[k], points[(k + 1) % points.size()], s.circle, s.counter_clockwise});
  }

  std::vector<tangent::Circle>& circles_;
  std::vector<Candidate> candidates_;
};

// Whether the piece bounds the free space: its midpoint free with the way to its left open.
bool bounds_free_space(const ArcBoundary& boundary, const ArcPiece& p) {
  AP m = middle(p.from, p.to);
  if (p.circle) {
    const tangent::Circle& circle = boundary.circles()[*p.circle];
    const AP u = p.from - circle.centre, v = p.to - circle.centre;
    AP towards = u + v;  // the bisector, on the arc's side when it turns less than half round
    const int turn = sign_of(cross(u, v)) * (p.counter_clockwise ? 1 : -1);
    if (turn < 0) towards = AP{-towards.x, -towards.y};
    if (turn == 0) towards = p.counter_clockwise ? left_of(u) : right_of(u);  // half round: u + v = 0
    m = circle.centre + times(towards, circle.radius / root(squared(towards)));
  }
  return !boundary.rules().blocked_at(m, std::nullopt, left_of(boundary.heading(p, m)));
}

// Which of u, v comes first turning counter-clockwise from r (r itself first of all); of two
// pieces leaving along one direction, the one curving further left comes later.
struct Leaving {
  AP direction;
  int curving;       // 1 left (an arc turning counter-clockwise), 0 straight, −1 right
  Algebraic radius;  // an arc's
};
bool leaves_before(const AP& r, const Leaving& u, const Leaving& v) {
  if (sign_of(cross(u.direction, v.direction)) != 0 || sign_of(dot(u.direction, v.direction)) < 0)
    return tangent::turns_before(r, u.direction, v.direction);
  if (u.curving != v.curving) return u.curving < v.curving;
  if (u.curving == 0) return false;
  return u.curving > 0 ? u.radius > v.radius : u.radius < v.radius;
}

std::vector<std::vector<ArcPiece>> link(const ArcBoundary& boundary, const std::vector<ArcPiece>& pieces) {
  const auto leaving = [&](const ArcPiece& p) {
    if (!p.circle) return Leaving{p.to - p.from, 0, Algebraic(0)};
    return Leaving{boundary.heading(p, p.from), p.counter_clockwise ? 1 : -1, boundary.circles()[*p.circle].radius};
  };
  // The piece after j: of those leaving its end, the last counter-clockwise from the way back (the
  // first clockwise).
  const auto next = [&](std::size_t j) {
    const AP way = boundary.heading(pieces[j], pieces[j].to), back{-way.x, -way.y};
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (pieces[k].from == pieces[j].to && (!best || leaves_before(back, leaving(pieces[*best]), leaving(pieces[k]))))
        best = k;
    if (!best) throw std::logic_error("walk::ArcBoundary: the boundary stops at a point");
    return *best;
  };
  std::vector<std::vector<ArcPiece>> cycles;
  std::vector<bool> used(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (used[i]) continue;
    std::vector<ArcPiece>& cycle = cycles.emplace_back();
    for (std::size_t j = i; !used[j]; j = next(j)) {
      used[j] = true;
      cycle.push_back(pieces[j]);
    }
  }
  return cycles;
}

bool same_piece(const ArcBoundary& boundary, const ArcPiece& a, const ArcPiece& b) {
  if (!(a.from == b.from && a.to == b.to) || a.circle.has_value() != b.circle.has_value()) return false;
  if (!a.circle) return true;
  const tangent::Circle &p = boundary.circles()[*a.circle], &q = boundary.circles()[*b.circle];
  return a.counter_clockwise == b.counter_clockwise && p.centre == q.centre && p.radius == q.radius;
}

}  // namespace

ArcBoundary::ArcBoundary(const RoundWorld& world)
    : world_(&world), rules_(world.cspace(), [](const Rational& q) { return algebraic(q); }),
      circles_(tangent::circles_of(world.cspace())) {
  std::vector<ArcPiece> kept;
  for (const ArcPiece& p : Builder(world.cspace(), circles_).cut())
    if (bounds_free_space(*this, p) &&
        std::none_of(kept.begin(), kept.end(), [&](const ArcPiece& k) { return same_piece(*this, k, p); }))
      kept.push_back(p);
  cycles_ = link(*this, kept);
}

std::string text(const AP& p) { return text(ExactPoint{Rational(approximate(p.x)), Rational(approximate(p.y))}); }

bool ArcBoundary::before(const ArcPiece& piece, const AP& x, const AP& y) const {
  if (!piece.circle) return dot(x - piece.from, piece.to - piece.from) < dot(y - piece.from, piece.to - piece.from);
  const AP c = circles_[*piece.circle].centre, start = piece.from - c;
  if (piece.counter_clockwise) return tangent::turns_before(start, x - c, y - c);
  // Clockwise: the reverse order, the start itself still first.
  if (y == piece.from) return false;
  return x == piece.from || tangent::turns_before(start, y - c, x - c);
}

bool ArcBoundary::within(const ArcPiece& piece, const AP& a, const AP& b, const AP& x) const {
  if (!piece.circle) return sign_of(dot(x - a, x - b)) <= 0;
  if (x == a || x == b) return true;
  return before(piece, a, x) && before(piece, x, b);
}

std::optional<std::string> ArcBoundary::query_not_free(const Query& query) const {
  return polyplan::query_not_free(*world_, query);
}

bool ArcBoundary::sees(const AP& from, const AP& to) const {
  const AP d = to - from;
  return !rules_.blocked_at(from, std::nullopt, d) && !rules_.segment_blocked(from, to) &&
         !rules_.blocked_at(to, AP{-d.x, -d.y}, std::nullopt);
}

std::optional<AP> ArcBoundary::first_hit(const AP& from, const AP& to) const {
  const AP d = to - from;
  const auto free = [&](const AP& end) { return sees(from, end); };
  if (free(to)) return std::nullopt;
  std::vector<Algebraic> ts{Algebraic(0), Algebraic(1)};
  for (const auto& cycle : cycles_)
    for (const ArcPiece& p : cycle) {
      std::vector<AP> met;
      if (p.circle) segment_circle(from, to, circles_[*p.circle].centre, circles_[*p.circle].radius, met);
      else segment_segment(from, to, p.from, p.to, met);
      for (const AP& x : met)
        if (within(p, p.from, p.to, x)) ts.push_back(dot(x - from, d) / squared(d));
    }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  for (std::size_t k = 0; k + 1 < ts.size(); ++k)
    if (!free(from + times(d, ts[k + 1]))) return from + times(d, ts[k]);
  return from;  // not reached: the whole way would be free
}

std::optional<Edge> ArcBoundary::edge_at(const AP& p, const AP& heading) const {
  const auto on_curve = [&](const ArcPiece& piece) {
    if (!piece.circle) return sign_of(cross(piece.to - piece.from, p - piece.from)) == 0;
    const tangent::Circle& circle = circles_[*piece.circle];
    return squared(p - circle.centre) == circle.radius * circle.radius;
  };
  std::optional<Edge> first;
  for (std::size_t c = 0; c < cycles_.size(); ++c)
    for (std::size_t i = 0; i < cycles_[c].size(); ++i) {
      const ArcPiece& piece = cycles_[c][i];
      if (p == piece.to || !on_curve(piece) || !within(piece, piece.from, piece.to, p)) continue;
      if (sign_of(cross(this->heading(piece, p), heading)) < 0) return Edge{c, i};  // into the obstacle on its right
      if (!first) first = Edge{c, i};
    }
  return first;
}

double ArcBoundary::perimeter(std::size_t cycle) const {
  double sum = 0;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i) {
    const Edge e{cycle, i};
    sum += length(e, start(e), end(e));
  }
  return sum;
}

std::size_t ArcBoundary::crossings(std::size_t cycle, const AP& s, const AP& g) const {
  // Distinct (where, which way) pairs: 1 left to right, 2 right to left, 0 touching.
  std::vector<std::pair<AP, int>> met;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i) {
    const Edge e{cycle, i};
    for (const AP& x : line_points(e, start(e), end(e), s, g)) {
      const int turn = sign_of(cross(g - s, heading(piece(e), x)));
      const std::pair<AP, int> crossing{x, turn < 0 ? 1 : turn > 0 ? 2 : 0};
      if (std::find(met.begin(), met.end(), crossing) == met.end()) met.push_back(crossing);
    }
  }
  return met.size();
}

std::vector<AP> ArcBoundary::line_points(Edge e, const AP& a, const AP& b, const AP& s, const AP& g) const {
  const ArcPiece& p = piece(e);
  std::vector<AP> met;
  if (a == b) return met;
  if (p.circle) segment_circle(s, g, circles_[*p.circle].centre, circles_[*p.circle].radius, met);
  else segment_segment(p.from, p.to, s, g, met);
  return in_walking_order(p, a, b, met);
}

std::vector<AP> ArcBoundary::circle_points(Edge e, const AP& a, const AP& b, const AP& centre,
                                           const Algebraic& radius) const {
  const ArcPiece& p = piece(e);
  std::vector<AP> met;
  if (p.circle) circle_circle(circles_[*p.circle], tangent::Circle{centre, radius, {}, {}, ""}, met);
  else segment_circle(p.from, p.to, centre, radius, met);
  return in_walking_order(p, a, b, met);
}

std::vector<AP> ArcBoundary::touching_points(Edge e, const AP& a, const AP& b, const AP& p) const {
  const ArcPiece& arc = piece(e);
  std::vector<AP> touching;
  if (arc.circle)
    for (const tangent::Tangent& t : tangent::common_tangents({p, Algebraic(0), {}, {}, ""}, circles_[*arc.circle]))
      touching.push_back(t.to);
  return in_walking_order(arc, a, b, touching);
}

std::vector<AP> ArcBoundary::in_walking_order(const ArcPiece& p, const AP& a, const AP& b,
                                              const std::vector<AP>& points) const {
  std::vector<AP> out;
  for (const AP& x : points)
    if (within(p, a, b, x) && std::none_of(out.begin(), out.end(), [&](const AP& y) { return y == x; }))
      out.push_back(x);
  std::sort(out.begin(), out.end(), [&](const AP& x, const AP& y) { return before(p, x, y); });
  return out;
}

int ArcBoundary::side(Edge e, const AP& x, const AP& p) const { return sign_of(cross(heading(piece(e), x), p - x)); }

AP ArcBoundary::nearest(Edge e, const AP& a, const AP& b, const AP& p) const {
  const ArcPiece& piece = this->piece(e);
  const auto nearer = [&](const AP& x, const AP& y) { return squared(x - p) <= squared(y - p) ? x : y; };
  AP best = nearer(a, b);
  if (!piece.circle) {  // the foot on the piece's own line, from its own ends: numbers of lower degree than a's
    const AP d = piece.to - piece.from;
    const AP foot = piece.from + times(d, dot(p - piece.from, d) / squared(d));
    return within(piece, a, b, foot) ? nearer(best, foot) : best;
  }
  const tangent::Circle& circle = circles_[*piece.circle];
  const AP w = p - circle.centre;
  if (sign_of(squared(w)) == 0) return best;
  const AP foot = circle.centre + times(w, circle.radius / root(squared(w)));
  return within(piece, a, b, foot) ? nearer(best, foot) : best;
}

double ArcBoundary::length(Edge e, const AP& a, const AP& b) const {
  const ArcPiece& piece = this->piece(e);
  const double ax = approximate(a.x), ay = approximate(a.y), bx = approximate(b.x), by = approximate(b.y);
  if (!piece.circle || a == b) return std::hypot(bx - ax, by - ay);
  const tangent::Circle& circle = circles_[*piece.circle];
  const double cx = approximate(circle.centre.x), cy = approximate(circle.centre.y);
  const double ux = ax - cx, uy = ay - cy, vx = bx - cx, vy = by - cy;
  double theta = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);  // counter-clockwise from a to b
  if (!piece.counter_clockwise) theta = -theta;
  if (theta <= 0) theta += 2 * M_PI;
  return approximate(circle.radius) * theta;
}

}  // namespace polyplan::walk
