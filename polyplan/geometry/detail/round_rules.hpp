#pragma once
// The rules of geometry/round_world_check.hpp over any exact ordered field N: GMP's rationals for
// the paths the planners and users give (round_world_check.cpp), CORE's real algebraic numbers for
// the tangent paths of a disc robot, whose points are irrational (roadmaps/tangent_visibility.cpp).
// One set of rules, so that both are checked by the same semantics.
//
// A segment a→b is checked in three steps. (1) Its distance to every obstacle's core is at least
// the obstacle's radius (squared distances of points, segments and polygons lie in the field). (2)
// The points where it may touch an obstacle are listed: where it meets a polygon's edge or a
// wall, the projections of the features' ends and of the discs' centres onto it — a superset of
// the contacts, all in the field. (3) At each of those points and at the midpoint between
// consecutive ones (where the contacts stay as they are along a piece), the local test below runs
// with the motion's directions −d and d.
//
// The local test at a point q: each obstacle q touches blocks an open set of directions — an open
// half-plane {d : d·u > 0}, u pointing from q to the obstacle's nearest point, for a disc, a
// rounded core or an edge; an open wedge, the polygon's inner angle, at a polygon's vertex — and
// each wall through q is a separator: rays a motion may move along but not cross. The motion is
// valid at q when the direction it arrives from and the direction it leaves along are both free
// and one turns into the other through free directions without crossing a separator. Free
// directions are tested at the sets' boundary directions and between them (consecutive boundary
// directions, with the four axes among them, are less than π apart, so their sum lies strictly
// between them: a direction of the field).
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/round_cspace.hpp>
#include <polyplan/geometry/world.hpp>

#include <algorithm>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::round_rules {

// A field's sign of a number and how a message prints one: GMP's rationals here, CORE's numbers in
// roadmaps/detail/algebraic.hpp.
template <class N>
struct Field;

template <>
struct Field<Rational> {
  static int sign(const Rational& x) { return sgn(x); }
  static std::string text(const Rational& x) { return to_string(x); }
};

template <class N>
int sign_of(const N& x) {
  return Field<N>::sign(x);
}
template <class N>
std::string number_text(const N& x) {
  return Field<N>::text(x);
}

template <class N>
struct P {
  N x, y;
  friend bool operator==(const P& a, const P& b) { return a.x == b.x && a.y == b.y; }
  friend P operator-(const P& a, const P& b) { return {a.x - b.x, a.y - b.y}; }
  friend P operator+(const P& a, const P& b) { return {a.x + b.x, a.y + b.y}; }
};

template <class N>
P<N> scaled(const P<N>& v, const N& t) {
  return {v.x * t, v.y * t};
}
template <class N>
N dot(const P<N>& a, const P<N>& b) {
  return a.x * b.x + a.y * b.y;
}
template <class N>
N cross(const P<N>& a, const P<N>& b) {
  return a.x * b.y - a.y * b.x;
}
template <class N>
N squared(const P<N>& v) {
  return dot(v, v);
}

template <class N>
struct Seg {
  P<N> a, b;
};

// The parameter in [0, 1] of the point of segment s nearest q.
template <class N>
N nearest_parameter(const Seg<N>& s, const P<N>& q) {
  const P<N> d = s.b - s.a;
  const N length = squared(d);
  if (sign_of(length) == 0) return N(0);
  const N t = dot(q - s.a, d) / length;
  return sign_of(t) < 0 ? N(0) : t > N(1) ? N(1) : t;
}

template <class N>
P<N> at(const Seg<N>& s, const N& t) {
  return s.a + scaled(s.b - s.a, t);
}
template <class N>
P<N> nearest_point(const Seg<N>& s, const P<N>& q) {
  return at(s, nearest_parameter(s, q));
}
template <class N>
N squared_distance(const Seg<N>& s, const P<N>& q) {
  return squared(nearest_point(s, q) - q);
}

template <class N>
bool on_segment(const Seg<N>& s, const P<N>& q) {
  return sign_of(cross(s.b - s.a, q - s.a)) == 0 && sign_of(dot(q - s.a, q - s.b)) <= 0;
}

// Whether s and t cross at a point inside both, each one's ends strictly on either side of the
// other's line.
template <class N>
bool cross_properly(const Seg<N>& s, const Seg<N>& t) {
  const int o1 = sign_of(cross(s.b - s.a, t.a - s.a)), o2 = sign_of(cross(s.b - s.a, t.b - s.a));
  const int o3 = sign_of(cross(t.b - t.a, s.a - t.a)), o4 = sign_of(cross(t.b - t.a, s.b - t.a));
  return o1 * o2 < 0 && o3 * o4 < 0;
}

template <class N>
bool segments_meet(const Seg<N>& s, const Seg<N>& t) {
  if (cross_properly(s, t)) return true;
  return on_segment(s, t.a) || on_segment(s, t.b) || on_segment(t, s.a) || on_segment(t, s.b);
}

template <class N>
N squared_distance(const Seg<N>& s, const Seg<N>& t) {
  if (segments_meet(s, t)) return N(0);
  return std::min(
      {squared_distance(s, t.a), squared_distance(s, t.b), squared_distance(t, s.a), squared_distance(t, s.b)});
}

// A polygon's rings, the first the outer one, each with the region's interior to the left of its
// edges (validated: outer counter-clockwise, holes clockwise).
template <class N>
using Rings = std::vector<std::vector<P<N>>>;

template <class N>
std::vector<Seg<N>> edges_of(const std::vector<P<N>>& ring) {
  std::vector<Seg<N>> edges;
  for (std::size_t i = 0; i < ring.size(); ++i) edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return edges;
}

// Where q lies with respect to a ring's closed region (the side its edges' left is): -1 outside,
// 0 on its boundary, 1 inside; by the crossing number, exact.
template <class N>
int side_of_ring(const std::vector<P<N>>& ring, const P<N>& q) {
  bool inside = false;
  for (const Seg<N>& e : edges_of(ring)) {
    if (on_segment(e, q)) return 0;
    if ((e.a.y > q.y) != (e.b.y > q.y)) {
      const N x = e.a.x + (q.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
      if (x > q.x) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// -1 outside the polygon with holes, 0 on its boundary, 1 in its interior.
template <class N>
int side_of_polygon(const Rings<N>& rings, const P<N>& q) {
  const int outer = side_of_ring(rings.front(), q);
  if (outer <= 0) return outer;
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const int in_hole = side_of_ring(rings[h], q);
    if (in_hole >= 0) return in_hole == 0 ? 0 : -1;
  }
  return 1;
}

// An open set of directions one obstacle blocks at a point, with the directions bounding it.
template <class N>
struct Blocked {
  std::function<bool(const P<N>&)> contains;
  std::vector<P<N>> boundary;
};

template <class N>
Blocked<N> half_plane(const P<N>& towards) {
  return {[towards](const P<N>& d) { return sign_of(dot(d, towards)) > 0; },
          {P<N>{-towards.y, towards.x}, P<N>{towards.y, -towards.x}}};
}

// The open wedge turning counter-clockwise from direction `from` to direction `to`.
template <class N>
Blocked<N> wedge(const P<N>& from, const P<N>& to) {
  const int turn = sign_of(cross(from, to));
  return {[from, to, turn](const P<N>& d) {
            if (turn > 0) return sign_of(cross(from, d)) > 0 && sign_of(cross(d, to)) > 0;
            if (turn < 0) return !(sign_of(cross(to, d)) >= 0 && sign_of(cross(d, from)) >= 0);
            return sign_of(cross(from, d)) > 0;  // a straight angle: the half-plane left of `from`
          },
          {from, to}};
}

// What a point meets: nothing, the inside of an obstacle, or its boundary (the directions it blocks
// there, the walls' rays).
template <class N>
struct Contact {
  bool inside = false;
  std::string inside_of;  // the first obstacle it is inside ("discs[2]"), or "the bounds"
  std::vector<Blocked<N>> blocked;
  std::vector<P<N>> separators;
};

// Counter-clockwise order of directions, exactly: by half-plane, then by turn.
template <class N>
bool before(const P<N>& a, const P<N>& b) {
  const auto upper = [](const P<N>& v) { return sign_of(v.y) > 0 || (sign_of(v.y) == 0 && sign_of(v.x) > 0); };
  if (upper(a) != upper(b)) return upper(a);
  return sign_of(cross(a, b)) > 0;
}

template <class N>
bool same_direction(const P<N>& a, const P<N>& b) {
  return sign_of(cross(a, b)) == 0 && sign_of(dot(a, b)) > 0;
}

// Directions of the polygon's interior at q on its boundary: a half-plane on an edge, the inner
// angle at a vertex.
template <class N>
void touch_polygon(const Rings<N>& rings, const P<N>& q, Contact<N>& c) {
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const P<N>& v = ring[i];
      const P<N>& next = ring[(i + 1) % ring.size()];
      const P<N>& previous = ring[(i + ring.size() - 1) % ring.size()];
      if (v == q) c.blocked.push_back(wedge(next - v, previous - v));
      else if (on_segment(Seg<N>{v, next}, q) && !(next == q))
        c.blocked.push_back(half_plane(P<N>{-(next.y - v.y), next.x - v.x}));
    }
}

// A wall's rays from q: along the piece q is on, or to both neighbours at a vertex.
template <class N>
void touch_wall(const std::vector<P<N>>& wall, const P<N>& q, Contact<N>& c) {
  for (std::size_t i = 0; i < wall.size(); ++i) {
    if (wall[i] == q) {
      if (i > 0) c.separators.push_back(wall[i - 1] - q);
      if (i + 1 < wall.size()) c.separators.push_back(wall[i + 1] - q);
    } else if (i + 1 < wall.size() && on_segment(Seg<N>{wall[i], wall[i + 1]}, q) && !(wall[i + 1] == q)) {
      c.separators.push_back(wall[i] - q);
      c.separators.push_back(wall[i + 1] - q);
    }
  }
}

template <class N>
bool free_direction(const Contact<N>& c, const P<N>& d) {
  return std::none_of(c.blocked.begin(), c.blocked.end(), [&](const Blocked<N>& b) { return b.contains(d); });
}

template <class N>
bool is_separator(const Contact<N>& c, const P<N>& d) {
  return std::any_of(c.separators.begin(), c.separators.end(), [&](const P<N>& s) { return same_direction(s, d); });
}

// Every direction the contact's sets and separators turn at, the axes, and `in` and `out`, sorted
// counter-clockwise without repeats.
template <class N>
std::vector<P<N>> turning_directions(const Contact<N>& c, const P<N>& in, const P<N>& out) {
  std::vector<P<N>> all{{N(1), N(0)}, {N(0), N(1)}, {N(-1), N(0)}, {N(0), N(-1)}, in, out};
  for (const Blocked<N>& b : c.blocked) all.insert(all.end(), b.boundary.begin(), b.boundary.end());
  all.insert(all.end(), c.separators.begin(), c.separators.end());
  std::sort(all.begin(), all.end(), before<N>);
  all.erase(std::unique(all.begin(), all.end(), same_direction<N>), all.end());
  return all;
}

// Whether turning counter-clockwise from `in` to `out` keeps to free directions and crosses no
// separator (touching one at either end is sliding along its wall).
template <class N>
bool turns_freely(const Contact<N>& c, const std::vector<P<N>>& around, const P<N>& in, const P<N>& out) {
  const auto index = [&](const P<N>& v) {
    return static_cast<std::size_t>(
        std::find_if(around.begin(), around.end(), [&](const P<N>& w) { return same_direction(v, w); }) -
        around.begin());
  };
  const std::size_t n = around.size(), to = index(out);
  for (std::size_t i = index(in);; i = (i + 1) % n) {
    const P<N>& here = around[i];
    const P<N>& next = around[(i + 1) % n];
    if (!free_direction(c, here + next)) return false;  // between two turning directions
    if ((i + 1) % n == to) return true;
    if (!free_direction(c, next) || is_separator(c, next)) return false;
  }
}

template <class N>
std::string at_text(const P<N>& q) {
  return "(" + number_text(q.x) + ", " + number_text(q.y) + ")";
}

// The parameters in (0, 1) along s of q's projection, and of where s crosses segment e.
template <class N>
void add_projection(const Seg<N>& s, const P<N>& q, std::vector<N>& out) {
  const N t = nearest_parameter(s, q);
  if (sign_of(t) > 0 && t < N(1)) out.push_back(t);
}

template <class N>
void add_crossing(const Seg<N>& s, const Seg<N>& e, std::vector<N>& out) {
  const P<N> d = s.b - s.a, f = e.b - e.a;
  const N denominator = cross(d, f);
  if (sign_of(denominator) == 0) return;  // parallel: the projections of e's ends bound any overlap
  const N t = cross(e.a - s.a, f) / denominator, u = cross(e.a - s.a, d) / denominator;
  if (sign_of(t) > 0 && t < N(1) && sign_of(u) >= 0 && u <= N(1)) out.push_back(t);
}

template <class N>
void add_segment_events(const Seg<N>& s, const Seg<N>& e, std::vector<N>& out) {
  add_projection(s, e.a, out);
  add_projection(s, e.b, out);
  add_crossing(s, e, out);
}

// An obstacle: its core, its radius (the robot's added), and its name for messages.
template <class N>
struct Obstacle {
  enum class Core { point, segment, polygon, wall } core = Core::point;
  P<N> centre;             // point
  P<N> from, to;           // segment: a wall's piece met by a disc robot
  Rings<N> rings;          // polygon
  std::vector<P<N>> wall;  // wall (radius 0): the whole polyline, its rays
  N radius;                // 0 only for a polygon or a wall met by a point robot
  std::string name;
  // The core's bounding box grown by the radius (xmin, ymin, xmax, ymax): nothing beyond it meets
  // the obstacle, so the checks pass it by with four comparisons (RoundRules sets it).
  std::array<N, 4> reach{};
};

// Whether the box (xmin, ymin, xmax, ymax) lies apart from the obstacle's reach.
template <class N>
bool apart(const Obstacle<N>& o, const std::array<N, 4>& box) {
  return box[2] < o.reach[0] || box[3] < o.reach[1] || box[0] > o.reach[2] || box[1] > o.reach[3];
}

template <class N>
std::array<N, 4> box_of(const P<N>& a, const P<N>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

// The reach of an obstacle whose core and radius are set.
template <class N>
void set_reach(Obstacle<N>& o) {
  using Core = typename Obstacle<N>::Core;
  std::vector<P<N>> points;
  if (o.core == Core::point) points = {o.centre};
  if (o.core == Core::segment) points = {o.from, o.to};
  if (o.core == Core::wall) points = o.wall;
  for (const auto& ring : o.rings) points.insert(points.end(), ring.begin(), ring.end());
  std::array<N, 4> box = box_of(points[0], points[0]);
  for (const P<N>& p : points)
    box = {std::min(box[0], p.x), std::min(box[1], p.y), std::max(box[2], p.x), std::max(box[3], p.y)};
  o.reach = {box[0] - o.radius, box[1] - o.radius, box[2] + o.radius, box[3] + o.radius};
}

// Every obstacle of a world as cores and radii in the field N, the bounds shrunk by the robot's
// radius, and the checks of a configuration and of a polyline motion.
template <class N>
class RoundRules {
 public:
  using Point = P<N>;
  using Vector = P<N>;
  using Core = typename Obstacle<N>::Core;

  // `field` takes a rational of the C-space into N.
  template <class Field>
  RoundRules(const RoundCSpace& space, Field field) : robot_(space.robot) {
    const auto point = [&](const ExactPoint& p) { return Point{field(p.x), field(p.y)}; };
    const auto points = [&](const std::vector<ExactPoint>& ps) {
      std::vector<Point> out;
      for (const ExactPoint& p : ps) out.push_back(point(p));
      return out;
    };
    for (const RoundCore& core : space.obstacles) {
      const N radius = field(core.radius);
      if (core.kind == RoundCore::Kind::point)
        obstacles_.push_back({Core::point, point(core.points[0]), {}, {}, {}, {}, radius, core.name});
      if (core.kind == RoundCore::Kind::wall && sign_of(radius) == 0)
        obstacles_.push_back({Core::wall, {}, {}, {}, {}, points(core.points), radius, core.name});
      if (core.kind == RoundCore::Kind::wall && sign_of(radius) > 0)  // a grown wall: its pieces
        for (std::size_t k = 0; k + 1 < core.points.size(); ++k)
          obstacles_.push_back(
              {Core::segment, {}, point(core.points[k]), point(core.points[k + 1]), {}, {}, radius, core.name});
      if (core.kind == RoundCore::Kind::polygon) {
        Obstacle<N> o{Core::polygon, {}, {}, {}, {}, {}, radius, core.name};
        for (const Ring& ring : core.rings) o.rings.push_back(points(ring));
        obstacles_.push_back(std::move(o));
      }
    }
    for (Obstacle<N>& o : obstacles_) set_reach(o);
    if (const auto& b = space.box) box_ = {field(b->xmin), field(b->ymin), field(b->xmax), field(b->ymax)};
    if (space.disc) {
      disc_centre_ = point(space.disc->center);
      disc_radius_ = field(space.disc->radius);
    }
  }

  const std::vector<Obstacle<N>>& obstacles() const { return obstacles_; }
  // The box the robot's centre keeps to (xmin, ymin, xmax, ymax), and the disc (centre, radius).
  const std::optional<std::array<N, 4>>& box() const { return box_; }
  const std::optional<Point>& disc_centre() const { return disc_centre_; }
  const N& disc_radius() const { return disc_radius_; }

  Contact<N> contact(const Point& q) const {
    Contact<N> c;
    for (const Obstacle<N>& o : obstacles_) touch(o, q, c);
    touch_bounds(q, c);
    return c;
  }

  // Why the motion arriving at q from direction `in` and leaving along `out` (either may be none)
  // is blocked there, or none.
  std::optional<std::string> blocked_at(const Point& q, const std::optional<Vector>& in,
                                        const std::optional<Vector>& out) const {
    int face = 0;
    return blocked_at(q, in, out, face);
  }

  // The same at a joint of a path that may slide along walls, where the face of a wall the robot
  // is on decides: `face` is the side of the ray `in` it is on where it arrives along a wall (1 the
  // left, -1 the right, 0 either), and becomes the side of `out` it leaves on where it leaves
  // along one (0 where it may take either side, as round a wall's end). A path carries it from
  // joint to joint, turned round (-face: the left of `out` is the right of the next joint's `in`),
  // so that sliding along a wall onto a corner it cannot turn in through is a crossing.
  std::optional<std::string> blocked_at(const Point& q, const std::optional<Vector>& in,
                                        const std::optional<Vector>& out, int& face) const {
    const Contact<N> c = contact(q);
    const int arriving = in && is_separator(c, *in) ? face : 0;
    face = 0;
    if (c.inside)
      return "at " + at_text(q) +
             (c.inside_of == "the bounds" ? " the robot leaves the bounds" : " the robot overlaps " + c.inside_of);
    for (const auto& d : {in, out})
      if (d && !free_direction(c, *d)) return "at " + at_text(q) + " the motion turns into an obstacle it touches";
    if (!in || !out || (c.blocked.empty() && c.separators.empty())) return std::nullopt;
    const std::vector<Vector> around = turning_directions(c, *in, *out);
    if (same_direction(*in, *out)) {  // back the way it came: on the side it came on, or either round a wall's end
      face = turns_freely(c, around, *in, *out) ? 0 : arriving;
      return std::nullopt;
    }
    // Counter-clockwise from `in` sweeps its left, and comes to `out` from its right.
    const bool left = arriving >= 0 && turns_freely(c, around, *in, *out);
    const bool right = arriving <= 0 && turns_freely(c, around, *out, *in);
    if (left != right && is_separator(c, *out)) face = left ? -1 : 1;
    if (left || right) return std::nullopt;
    return "at " + at_text(q) + " the motion crosses a wall or passes where obstacles touch (a passage of zero width)";
  }

  // Why the straight motion a→b is blocked (its ends' own arrival and departure not included), or
  // none.
  std::optional<std::string> segment_blocked(const Point& a, const Point& b) const {
    const Seg<N> s{a, b};
    if (auto why = too_close(s)) return why;
    const Vector d = s.b - s.a, back{-d.x, -d.y};
    const std::vector<N> ts = events(s);
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const N middle = (ts[k] + ts[k + 1]) / N(2);
      if (auto why = blocked_at(at(s, middle), back, d)) return why;
      if (k > 0)
        if (auto why = blocked_at(at(s, ts[k]), back, d)) return why;
    }
    return std::nullopt;
  }

 private:
  void touch(const Obstacle<N>& o, const Point& q, Contact<N>& c) const {
    if (apart(o, box_of(q, q))) return;
    if (o.core == Core::wall) return touch_wall(o.wall, q, c);
    const auto inside = [&] {
      if (!c.inside) c.inside_of = o.name;
      c.inside = true;
    };
    if (o.core == Core::polygon && sign_of(o.radius) == 0) {
      const int side = side_of_polygon(o.rings, q);
      if (side > 0) inside();
      if (side == 0) touch_polygon(o.rings, q, c);
      return;
    }
    // A rounded core: blocked within `radius`; on the rim, the half-plane towards each nearest point.
    std::vector<Point> nearest;
    if (o.core == Core::point) nearest.push_back(o.centre);
    if (o.core == Core::segment) nearest.push_back(nearest_point(Seg<N>{o.from, o.to}, q));
    if (o.core == Core::polygon) {
      if (side_of_polygon(o.rings, q) >= 0) return inside();
      for (const auto& ring : o.rings)
        for (const Seg<N>& e : edges_of(ring)) nearest.push_back(nearest_point(e, q));
    }
    const N r2 = o.radius * o.radius;
    for (const Point& k : nearest) {
      const N d2 = squared(k - q);
      if (d2 < r2) inside();
      else if (d2 == r2) c.blocked.push_back(half_plane(k - q));
    }
  }

  void touch_bounds(const Point& q, Contact<N>& c) const {
    const auto outside = [&] {
      if (!c.inside) c.inside_of = "the bounds";
      c.inside = true;
    };
    if (box_) {
      const auto& [xmin, ymin, xmax, ymax] = *box_;
      const std::pair<N, Vector> sides[] = {{q.x - xmin, {N(-1), N(0)}},
                                            {xmax - q.x, {N(1), N(0)}},
                                            {q.y - ymin, {N(0), N(-1)}},
                                            {ymax - q.y, {N(0), N(1)}}};
      for (const auto& [room, outward] : sides) {
        if (sign_of(room) < 0) outside();
        else if (sign_of(room) == 0) c.blocked.push_back(half_plane(outward));
      }
    }
    if (disc_centre_) {
      const N d2 = squared(q - *disc_centre_), r2 = disc_radius_ * disc_radius_;
      if (sign_of(disc_radius_) < 0 || d2 > r2) outside();
      else if (d2 == r2) c.blocked.push_back(half_plane(q - *disc_centre_));
    }
  }

  std::optional<std::string> too_close(const Seg<N>& s) const {
    const std::array<N, 4> span = box_of(s.a, s.b);
    for (const Obstacle<N>& o : obstacles_) {
      if (o.core == Core::wall || (o.core == Core::polygon && sign_of(o.radius) == 0)) continue;  // contacts decide
      if (apart(o, span)) continue;
      N d2;
      if (o.core == Core::point) d2 = squared_distance(s, o.centre);
      if (o.core == Core::segment) d2 = squared_distance(s, Seg<N>{o.from, o.to});
      if (o.core == Core::polygon) {
        d2 = side_of_polygon(o.rings, s.a) >= 0 ? N(0) : N(-1);
        for (const auto& ring : o.rings)
          for (const Seg<N>& e : edges_of(ring)) {
            const N e2 = squared_distance(s, e);
            if (sign_of(d2) < 0 || e2 < d2) d2 = e2;
          }
      }
      if (d2 < o.radius * o.radius) return overlap_text(o);
    }
    return std::nullopt;
  }

  std::vector<N> events(const Seg<N>& s) const {
    std::vector<N> out{N(0), N(1)};
    const std::array<N, 4> span = box_of(s.a, s.b);
    for (const Obstacle<N>& o : obstacles_) {
      if (apart(o, span)) continue;  // no contact along s: no event
      if (o.core == Core::point) add_projection(s, o.centre, out);
      if (o.core == Core::segment) add_segment_events(s, Seg<N>{o.from, o.to}, out);
      if (o.core == Core::wall)
        for (std::size_t i = 0; i + 1 < o.wall.size(); ++i)
          add_segment_events(s, Seg<N>{o.wall[i], o.wall[i + 1]}, out);
      if (o.core == Core::polygon)
        for (const auto& ring : o.rings)
          for (const Seg<N>& e : edges_of(ring)) add_segment_events(s, e, out);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // Why coming nearer o than its radius is not allowed, in the robot's terms.
  std::string overlap_text(const Obstacle<N>& o) const {
    if (robot_ == RoundCSpace::Robot::polygon) return "the robot overlaps " + o.name + " on the way";
    if (robot_ == RoundCSpace::Robot::point) return "the motion enters " + o.name;
    return "the motion comes nearer " + o.name + " than the robot's radius allows";
  }

  std::vector<Obstacle<N>> obstacles_;
  RoundCSpace::Robot robot_;
  std::optional<std::array<N, 4>> box_;
  std::optional<Point> disc_centre_;
  N disc_radius_;
};

}  // namespace polyplan::round_rules
