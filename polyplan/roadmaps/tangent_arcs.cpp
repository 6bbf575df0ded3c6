// The circles, tangents and arc tests of roadmaps/detail/tangent_arcs.hpp, exact in CORE's numbers.
//
// The distance from an arc to a point or a segment is the least of a few candidates, each exact:
// the arc's ends; the point's radial projection onto the circle when it falls inside the arc; where
// the segment's line meets the circle inside both; and, for a line that misses the circle, the
// circle's point nearest the line when it falls inside both. The extreme of a linear function over
// an arc (a box side, the distance from the bounds' centre) is at an end or at the direction it
// points to, when the arc holds it.
#include <polyplan/roadmaps/detail/tangent_arcs.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace polyplan::tangent {
namespace {

using Core = round_rules::Obstacle<Algebraic>::Core;
using round_rules::cross;
using round_rules::dot;
using round_rules::Seg;
using round_rules::sign_of;
using round_rules::squared;
using round_rules::squared_distance;
using AP = AlgebraicPoint;
using Rules = round_rules::RoundRules<Algebraic>;
using Obstacle = round_rules::Obstacle<Algebraic>;

AP perpendicular(const AP& v) { return {-v.y, v.x}; }
AP times(const AP& v, const Algebraic& t) { return {v.x * t, v.y * t}; }
Algebraic length(const AP& v) { return root(squared(v)); }
Algebraic absolute(const Algebraic& x) { return sign_of(x) < 0 ? -x : x; }

void add_vertices(const std::vector<ExactPoint>& points, const std::string& name, const Rational& r,
                  std::vector<Circle>& out) {
  for (std::size_t k = 0; k < points.size(); ++k)
    out.push_back({algebraic(points[k]), algebraic(r), points[k], r, name + " vertex " + std::to_string(k)});
}

// The half, [0, π) or [π, 2π), that the counter-clockwise angle from a to v falls in.
int half(const AP& a, const AP& v) {
  const int s = sign_of(cross(a, v));
  return s > 0 || (s == 0 && sign_of(dot(a, v)) > 0) ? 0 : 1;
}

// Whether u points to one of the arc's ends.
bool towards_end(const Arc& arc, const AP& u) {
  const auto same = [&](const AP& v) { return sign_of(cross(u, v)) == 0 && sign_of(dot(u, v)) > 0; };
  return same(arc.from - arc.circle->centre) || same(arc.to - arc.circle->centre);
}

// A distance from an arc, kept apart: the least over its ends, and the least over its other points
// where it is not at an end (none when only an end is nearest).
struct ArcDistance {
  Algebraic ends;
  std::optional<Algebraic> inside;
  void add(const Algebraic& d, bool at_end) {
    if (at_end) ends = std::min(ends, d);
    else inside = inside ? std::min(*inside, d) : d;
  }
  Algebraic least() const { return inside ? std::min(ends, *inside) : ends; }
};

ArcDistance distance_to_arc(const Arc& arc, const AP& p) {
  const AP u = p - arc.circle->centre;
  ArcDistance out{std::min(length(p - arc.from), length(p - arc.to)), std::nullopt};
  if (sign_of(squared(u)) == 0) out.add(arc.circle->radius, false);
  else if (spans(arc, u)) out.add(absolute(length(u) - arc.circle->radius), towards_end(arc, u));
  return out;
}

ArcDistance distance_to_segment(const Arc& arc, const Seg<Algebraic>& s) {
  ArcDistance out{std::min(root(squared_distance(s, arc.from)), root(squared_distance(s, arc.to))), std::nullopt};
  for (const AP& end : {s.a, s.b}) {
    const ArcDistance d = distance_to_arc(arc, end);
    out.add(d.ends, true);
    if (d.inside) out.add(*d.inside, false);
  }
  const AP d = s.b - s.a, &c = arc.circle->centre;
  const Algebraic length2 = squared(d), &rho = arc.circle->radius;
  if (sign_of(length2) != 0) {
    const Algebraic t = dot(c - s.a, d) / length2;
    const AP foot = s.a + times(d, t), normal = foot - c;
    const Algebraic h2 = squared(normal);
    const auto inside = [](const Algebraic& u) { return sign_of(u) >= 0 && u <= Algebraic(1); };
    if (h2 <= rho * rho) {  // the line meets the circle: where, if inside the segment and the arc
      const Algebraic w = root((rho * rho - h2) / length2);
      for (const Algebraic& u : {t - w, t + w}) {
        const AP radial = s.a + times(d, u) - c;
        if (inside(u) && spans(arc, radial)) out.add(Algebraic(0), towards_end(arc, radial));
      }
    } else if (inside(t) && spans(arc, normal)) {
      out.add(root(h2) - rho, towards_end(arc, normal));
    }
  }
  return out;
}

// Whether the obstacle's feature is the circle's own: the disc itself, or an edge or a wall piece
// ending at the corner (the corner's arc keeps exactly its radius from them).
bool owns(const Obstacle& o, const Circle& circle) {
  if (!(o.radius == circle.radius)) return false;
  if (o.core == Core::point) return o.centre == circle.centre;
  if (o.core == Core::segment) return o.from == circle.centre || o.to == circle.centre;
  return false;
}

bool edge_owns(const Seg<Algebraic>& e, const Obstacle& o, const Circle& circle) {
  return o.radius == circle.radius && (e.a == circle.centre || e.b == circle.centre);
}

// Whether the arc comes nearer than `radius` (or touches it, unless `own`); an open arc (`open`)
// may touch anything at its ends.
bool too_near(const ArcDistance& distance, const Algebraic& radius, bool own, bool open) {
  const auto near = [&](const Algebraic& d) { return d < radius || (!own && d == radius); };
  if (!open) return near(distance.least());
  return distance.ends < radius || (distance.inside && near(*distance.inside));
}

std::optional<std::string> blocked_by(const Obstacle& o, const Arc& arc, bool open) {
  const Circle& circle = *arc.circle;
  const std::string why = "the arc round " + circle.name + " comes to " + o.name;
  if (o.core == Core::point) {
    if (too_near(distance_to_arc(arc, o.centre), o.radius, owns(o, circle), open)) return why;
  } else if (o.core == Core::segment) {
    if (too_near(distance_to_segment(arc, {o.from, o.to}), o.radius, owns(o, circle), open)) return why;
  } else if (o.core == Core::wall) {
    for (std::size_t k = 0; k + 1 < o.wall.size(); ++k)
      if (too_near(distance_to_segment(arc, {o.wall[k], o.wall[k + 1]}), o.radius, false, open)) return why;
  } else {
    for (const auto& ring : o.rings)
      for (const Seg<Algebraic>& e : round_rules::edges_of(ring))
        if (too_near(distance_to_segment(arc, e), o.radius, edge_owns(e, o, circle), open)) return why;
  }
  return std::nullopt;
}

// The largest value of v·x over the arc's points x: at its ends, and where the arc holds v's
// direction (none when it does not, or only at an end).
struct Largest {
  Algebraic ends;
  std::optional<Algebraic> inside;
  bool reaches(const Algebraic& limit, bool open) const {
    if (inside && *inside >= limit) return true;
    return open ? ends > limit : ends >= limit;
  }
};
Largest largest(const Arc& arc, const AP& v) {
  Largest out{std::max(dot(v, arc.from), dot(v, arc.to)), std::nullopt};
  if (spans(arc, v) && !towards_end(arc, v)) out.inside = dot(v, arc.circle->centre) + arc.circle->radius * length(v);
  return out;
}

// Whether the arc touches or leaves the bounds; an open arc may touch them at its ends, and an arc
// of the bounds' own circle runs along them.
std::optional<std::string> leaves_bounds(const Rules& rules, const Arc& arc, bool open) {
  const std::string why = "the arc round " + arc.circle->name + " comes to the bounds";
  if (const auto& box = rules.box()) {
    const auto& [xmin, ymin, xmax, ymax] = *box;
    const Algebraic one(1), zero(0);
    if (largest(arc, {one, zero}).reaches(xmax, open) || largest(arc, {zero, one}).reaches(ymax, open) ||
        largest(arc, {-one, zero}).reaches(-xmin, open) || largest(arc, {zero, -one}).reaches(-ymin, open))
      return why;
  }
  if (const auto& centre = rules.disc_centre()) {
    const AP w = arc.circle->centre - *centre;
    if (open && sign_of(squared(w)) == 0 && arc.circle->radius == rules.disc_radius()) return std::nullopt;  // along
    Largest farthest{std::max(length(arc.from - *centre), length(arc.to - *centre)), std::nullopt};
    if (sign_of(squared(w)) == 0) farthest.inside = arc.circle->radius;
    else if (spans(arc, w) && !towards_end(arc, w)) farthest.inside = length(w) + arc.circle->radius;
    if (farthest.reaches(rules.disc_radius(), open)) return why;
  }
  return std::nullopt;
}

}  // namespace

std::vector<Circle> circles_of(const RoundCSpace& space) {
  std::vector<Circle> out;
  for (const RoundCore& core : space.obstacles) {
    if (core.kind == RoundCore::Kind::point)
      out.push_back({algebraic(core.points[0]), algebraic(core.radius), core.points[0], core.radius, core.name});
    else add_vertices(core.points, core.name, core.radius, out);
    for (std::size_t h = 0; h < core.rings.size(); ++h)
      add_vertices(core.rings[h], h == 0 ? core.name : core.name + " hole " + std::to_string(h - 1), core.radius, out);
  }
  return out;
}

// With n the tangent line's unit normal, a's touching point is c_a + ρ_a·n and b's c_b + s·ρ_b·n
// (s = 1: an outer tangent, −1: an inner one); both on the line when n·(c_b − c_a) = ρ_a − s·ρ_b =: k,
// so n = (k·d ± √(|d|² − k²)·d⊥) / |d|², d = c_b − c_a.
std::vector<Tangent> common_tangents(const Circle& a, const Circle& b) {
  const AP d = b.centre - a.centre;
  const Algebraic d2 = squared(d);
  if (sign_of(d2) == 0) return {};
  const bool a_point = sign_of(a.radius) == 0, b_point = sign_of(b.radius) == 0;
  std::vector<Tangent> out;
  for (const int s : {1, -1}) {
    if (s < 0 && (a_point || b_point)) continue;  // the outer tangents again
    const Algebraic k = a.radius - Algebraic(s) * b.radius, room = d2 - k * k;
    if (sign_of(room) < 0) continue;
    const Algebraic w = root(room);
    for (const int side : {1, -1}) {
      if (side < 0 && (sign_of(room) == 0 || (a_point && b_point))) continue;  // one line
      const AP n = times(times(d, k) + times(perpendicular(d), Algebraic(side) * w), Algebraic(1) / d2);
      out.push_back({a.centre + times(n, a.radius), b.centre + times(n, Algebraic(s) * b.radius)});
    }
  }
  return out;
}

bool turns_before(const AP& a, const AP& u, const AP& v) {
  const int hu = half(a, u), hv = half(a, v);
  if (hu != hv) return hu < hv;
  return sign_of(cross(u, v)) > 0;
}

bool spans(const Arc& arc, const AP& u) {
  const AP a = arc.from - arc.circle->centre, b = arc.to - arc.circle->centre;
  return !turns_before(a, b, u);
}

std::optional<std::string> arc_blocked(const Rules& rules, const Arc& arc, bool open) {
  for (const Obstacle& o : rules.obstacles())
    if (auto why = blocked_by(o, arc, open)) return why;
  return leaves_bounds(rules, arc, open);
}

AP heading(const CirclePiece& piece, const AP& x, const std::vector<Circle>& circles) {
  if (!piece.circle) return piece.to - piece.from;
  const AP radial = x - circles[*piece.circle].centre;
  return piece.counter_clockwise ? perpendicular(radial) : AP{radial.y, -radial.x};
}

Arc arc_of(const CirclePiece& piece, const std::vector<Circle>& circles) {
  const Circle* circle = &circles[*piece.circle];
  return piece.counter_clockwise ? Arc{circle, piece.from, piece.to} : Arc{circle, piece.to, piece.from};
}

std::optional<std::string> path_blocked(const Rules& rules, const std::vector<CirclePiece>& pieces,
                                        const std::vector<Circle>& circles, bool open,
                                        const std::vector<CirclePiece>* covers) {
  int face = 0;  // the side of a wall the path slides along (round_rules' blocked_at)
  for (std::size_t k = 0; k <= pieces.size(); ++k) {
    const AP& at = k < pieces.size() ? pieces[k].from : pieces.back().to;
    std::optional<AP> in, out;
    if (k > 0) {
      const AP arriving = heading(pieces[k - 1], at, circles);
      in = AP{-arriving.x, -arriving.y};  // the direction it arrives from
    }
    if (k < pieces.size()) out = heading(pieces[k], at, circles);
    face = -face;
    if (auto why = rules.blocked_at(at, in, out, face)) return why;
    if (k == pieces.size()) break;
    const CirclePiece& piece = covers ? (*covers)[k] : pieces[k];
    if (auto why = piece.circle ? arc_blocked(rules, arc_of(piece, circles), open)
                                : rules.segment_blocked(piece.from, piece.to))
      return why;
  }
  return std::nullopt;
}

ExactPoint printed_point(const AP& p, const Circle& circle) {
  if (sign_of(circle.radius) == 0) return circle.exact_centre;
  double d[2] = {p.x.doubleValue(), p.y.doubleValue()};
  const Rational least = circle.exact_radius * circle.exact_radius * Rational(1000000000000001, 1000000000000000);
  for (int step = 0; step < 64; ++step) {
    const Rational dx = Rational(d[0]) - circle.exact_centre.x, dy = Rational(d[1]) - circle.exact_centre.y;
    if (dx * dx + dy * dy >= least) break;
    const double inf = std::numeric_limits<double>::infinity();
    if (sgn(dx) != 0) d[0] = std::nextafter(d[0], sgn(dx) > 0 ? inf : -inf);
    if (sgn(dy) != 0) d[1] = std::nextafter(d[1], sgn(dy) > 0 ? inf : -inf);
  }
  return {Rational(d[0]), Rational(d[1])};
}

}  // namespace polyplan::tangent
