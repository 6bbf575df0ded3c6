// How the checks of round_world_check.hpp decide, all in rationals.
//
// A segment a→b is checked in three steps. (1) Its distance to every obstacle's core is at least
// the obstacle's radius (squared distances of points, segments and polygons are rational). (2)
// The points where it may touch an obstacle are listed: where it meets a polygon's edge or a
// wall, the projections of the features' ends and of the discs' centres onto it — a superset of
// the contacts, all rational. (3) At each of those points and at the midpoint between consecutive
// ones (where the contacts stay as they are along a piece), the local test below runs with the
// motion's directions −d and d.
//
// The local test at a point q: each obstacle q touches blocks an open set of directions — an open
// half-plane {d : d·u > 0}, u pointing from q to the obstacle's nearest point, for a disc, a
// rounded core or an edge; an open wedge, the polygon's inner angle, at a polygon's vertex — and
// each wall through q is a separator: rays a motion may move along but not cross. The motion is
// valid at q when the direction it arrives from and the direction it leaves along are both free
// and one turns into the other through free directions without crossing a separator. Free
// directions are tested at the sets' boundary directions and between them (consecutive boundary
// directions, with the four axes among them, are less than π apart, so their sum lies strictly
// between them: a rational direction).
#include <polyplan/geometry/round_world_check.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <functional>
#include <utility>

namespace polyplan {
namespace {

using Point = ExactPoint;
using Vector = ExactPoint;  // a direction or a difference of points

Vector operator-(const Point& a, const Point& b) { return {a.x - b.x, a.y - b.y}; }
Point operator+(const Point& a, const Vector& v) { return {a.x + v.x, a.y + v.y}; }
Vector scaled(const Vector& v, const Rational& t) { return {v.x * t, v.y * t}; }
Rational dot(const Vector& a, const Vector& b) { return a.x * b.x + a.y * b.y; }
Rational cross(const Vector& a, const Vector& b) { return a.x * b.y - a.y * b.x; }
Rational squared(const Vector& v) { return dot(v, v); }
int sign(const Rational& r) { return sgn(r); }

struct Segment {
  Point a, b;
};

// The parameter in [0, 1] of the point of segment s nearest q.
Rational nearest_parameter(const Segment& s, const Point& q) {
  const Vector d = s.b - s.a;
  const Rational length = squared(d);
  if (length == 0) return 0;
  const Rational t = dot(q - s.a, d) / length;
  return t < 0 ? Rational(0) : t > 1 ? Rational(1) : t;
}

Point at(const Segment& s, const Rational& t) { return s.a + scaled(s.b - s.a, t); }
Point nearest_point(const Segment& s, const Point& q) { return at(s, nearest_parameter(s, q)); }
Rational squared_distance(const Segment& s, const Point& q) { return squared(nearest_point(s, q) - q); }

bool on_segment(const Segment& s, const Point& q) {
  return cross(s.b - s.a, q - s.a) == 0 && dot(q - s.a, q - s.b) <= 0;
}

bool segments_meet(const Segment& s, const Segment& t) {
  const int o1 = sign(cross(s.b - s.a, t.a - s.a)), o2 = sign(cross(s.b - s.a, t.b - s.a));
  const int o3 = sign(cross(t.b - t.a, s.a - t.a)), o4 = sign(cross(t.b - t.a, s.b - t.a));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(s, t.a) || on_segment(s, t.b) || on_segment(t, s.a) || on_segment(t, s.b);
}

Rational squared_distance(const Segment& s, const Segment& t) {
  if (segments_meet(s, t)) return 0;
  return std::min(
      {squared_distance(s, t.a), squared_distance(s, t.b), squared_distance(t, s.a), squared_distance(t, s.b)});
}

// The polygon's rings, each with the region's interior to the left of its edges (validated:
// outer counter-clockwise, holes clockwise).
std::vector<Ring> rings_of(const PolygonWithHoles& p) {
  std::vector<Ring> rings{p.outer};
  rings.insert(rings.end(), p.holes.begin(), p.holes.end());
  return rings;
}

std::vector<Segment> edges_of(const Ring& ring) {
  std::vector<Segment> edges;
  for (std::size_t i = 0; i < ring.size(); ++i) edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return edges;
}

// Where q lies with respect to a ring's closed region (the side its edges' left is): -1 outside,
// 0 on its boundary, 1 inside; by the crossing number, exact.
int side_of_ring(const Ring& ring, const Point& q) {
  bool inside = false;
  for (const Segment& e : edges_of(ring)) {
    if (on_segment(e, q)) return 0;
    if ((e.a.y > q.y) != (e.b.y > q.y)) {
      const Rational x = e.a.x + (q.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
      if (x > q.x) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// -1 outside the polygon with holes, 0 on its boundary, 1 in its interior.
int side_of_polygon(const PolygonWithHoles& p, const Point& q) {
  const int outer = side_of_ring(p.outer, q);
  if (outer <= 0) return outer;
  for (const Ring& hole : p.holes) {
    const int in_hole = side_of_ring(hole, q);
    if (in_hole >= 0) return in_hole == 0 ? 0 : -1;
  }
  return 1;
}

// An open set of directions one obstacle blocks at a point, with the directions bounding it.
struct Blocked {
  std::function<bool(const Vector&)> contains;
  std::vector<Vector> boundary;
};

Blocked half_plane(const Vector& towards) {
  return {[towards](const Vector& d) { return sign(dot(d, towards)) > 0; },
          {Vector{-towards.y, towards.x}, Vector{towards.y, -towards.x}}};
}

// The open wedge turning counter-clockwise from direction `from` to direction `to`.
Blocked wedge(const Vector& from, const Vector& to) {
  const int turn = sign(cross(from, to));
  return {[from, to, turn](const Vector& d) {
            if (turn > 0) return sign(cross(from, d)) > 0 && sign(cross(d, to)) > 0;
            if (turn < 0) return !(sign(cross(to, d)) >= 0 && sign(cross(d, from)) >= 0);
            return sign(cross(from, d)) > 0;  // a straight angle: the half-plane left of `from`
          },
          {from, to}};
}

// What a point meets: nothing, the inside of an obstacle, or its boundary (the directions it blocks
// there, the walls' rays).
struct Contact {
  bool inside = false;
  std::string inside_of;  // the first obstacle it is inside ("discs[2]"), or "the bounds"
  std::vector<Blocked> blocked;
  std::vector<Vector> separators;
};

// Counter-clockwise order of directions, exactly: by half-plane, then by turn.
bool before(const Vector& a, const Vector& b) {
  const auto upper = [](const Vector& v) { return v.y > 0 || (v.y == 0 && v.x > 0); };
  if (upper(a) != upper(b)) return upper(a);
  return sign(cross(a, b)) > 0;
}

bool same_direction(const Vector& a, const Vector& b) { return sign(cross(a, b)) == 0 && sign(dot(a, b)) > 0; }

}  // namespace

struct RoundWorld::Impl {
  // An obstacle: its core, its radius (the robot's added), and its name for messages.
  struct Obstacle {
    enum class Core { point, segment, polygon, wall } core = Core::point;
    Point centre;                               // point
    Point from, to;                             // segment: a wall's piece met by a disc robot
    const PolygonWithHoles* polygon = nullptr;  // polygon: one of `polygons`
    std::vector<Point> wall;                    // wall (radius 0): the whole polyline, its rays
    Rational radius;                            // 0 only for a polygon or a wall met by a point robot
    std::string name;
  };

  World world;  // kept still: `obstacles` point into its polygons
  std::vector<Obstacle> obstacles;
  std::optional<Bounds> box;  // already shrunk by the robot's radius
  std::optional<Disc> disc;   // likewise
  Rational robot;

  Contact contact(const Point& q) const;
  void touch(const Obstacle& o, const Point& q, Contact& c) const;
  void touch_bounds(const Point& q, Contact& c) const;
  std::optional<std::string> blocked_at(const Point& q, const std::optional<Vector>& in,
                                        const std::optional<Vector>& out) const;
  std::optional<std::string> too_close(const Segment& s) const;
  std::vector<Rational> events(const Segment& s) const;
};

namespace {

// Directions of the polygon's interior at q on its boundary: a half-plane on an edge, the inner
// angle at a vertex.
void touch_polygon(const PolygonWithHoles& p, const Point& q, Contact& c) {
  for (const Ring& ring : rings_of(p))
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point& v = ring[i];
      const Point& next = ring[(i + 1) % ring.size()];
      const Point& previous = ring[(i + ring.size() - 1) % ring.size()];
      if (v == q) c.blocked.push_back(wedge(next - v, previous - v));
      else if (on_segment({v, next}, q) && !(next == q))
        c.blocked.push_back(half_plane(Vector{-(next.y - v.y), next.x - v.x}));
    }
}

// A wall's rays from q: along the piece q is on, or to both neighbours at a vertex.
void touch_wall(const std::vector<Point>& wall, const Point& q, Contact& c) {
  for (std::size_t i = 0; i < wall.size(); ++i) {
    if (wall[i] == q) {
      if (i > 0) c.separators.push_back(wall[i - 1] - q);
      if (i + 1 < wall.size()) c.separators.push_back(wall[i + 1] - q);
    } else if (i + 1 < wall.size() && on_segment({wall[i], wall[i + 1]}, q) && !(wall[i + 1] == q)) {
      c.separators.push_back(wall[i] - q);
      c.separators.push_back(wall[i + 1] - q);
    }
  }
}

}  // namespace

void RoundWorld::Impl::touch(const Obstacle& o, const Point& q, Contact& c) const {
  using Core = Obstacle::Core;
  if (o.core == Core::wall) return touch_wall(o.wall, q, c);
  const auto inside = [&] {
    if (!c.inside) c.inside_of = o.name;
    c.inside = true;
  };
  if (o.core == Core::polygon && o.radius == 0) {
    const int side = side_of_polygon(*o.polygon, q);
    if (side > 0) inside();
    if (side == 0) touch_polygon(*o.polygon, q, c);
    return;
  }
  // A rounded core: blocked within `radius`; on the rim, the half-plane towards each nearest point.
  std::vector<Point> nearest;
  if (o.core == Core::point) nearest.push_back(o.centre);
  if (o.core == Core::segment) nearest.push_back(nearest_point(Segment{o.from, o.to}, q));
  if (o.core == Core::polygon) {
    if (side_of_polygon(*o.polygon, q) >= 0) return inside();
    for (const Ring& ring : rings_of(*o.polygon))
      for (const Segment& e : edges_of(ring)) nearest.push_back(nearest_point(e, q));
  }
  const Rational r2 = o.radius * o.radius;
  for (const Point& k : nearest) {
    const Rational d2 = squared(k - q);
    if (d2 < r2) inside();
    else if (d2 == r2) c.blocked.push_back(half_plane(k - q));
  }
}

void RoundWorld::Impl::touch_bounds(const Point& q, Contact& c) const {
  const auto outside = [&] {
    if (!c.inside) c.inside_of = "the bounds";
    c.inside = true;
  };
  if (box) {
    const std::pair<Rational, Vector> sides[] = {
        {q.x - box->xmin, {-1, 0}}, {box->xmax - q.x, {1, 0}}, {q.y - box->ymin, {0, -1}}, {box->ymax - q.y, {0, 1}}};
    for (const auto& [room, outward] : sides) {
      if (room < 0) outside();
      else if (room == 0) c.blocked.push_back(half_plane(outward));
    }
  }
  if (disc) {
    const Rational d2 = squared(q - disc->center), r2 = disc->radius * disc->radius;
    if (disc->radius < 0 || d2 > r2) outside();
    else if (d2 == r2) c.blocked.push_back(half_plane(q - disc->center));
  }
}

Contact RoundWorld::Impl::contact(const Point& q) const {
  Contact c;
  for (const Obstacle& o : obstacles) touch(o, q, c);
  touch_bounds(q, c);
  return c;
}

namespace {

bool free_direction(const Contact& c, const Vector& d) {
  return std::none_of(c.blocked.begin(), c.blocked.end(), [&](const Blocked& b) { return b.contains(d); });
}

bool is_separator(const Contact& c, const Vector& d) {
  return std::any_of(c.separators.begin(), c.separators.end(), [&](const Vector& s) { return same_direction(s, d); });
}

// Every direction the contact's sets and separators turn at, the axes, and `in` and `out`, sorted
// counter-clockwise without repeats.
std::vector<Vector> turning_directions(const Contact& c, const Vector& in, const Vector& out) {
  std::vector<Vector> all{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, in, out};
  for (const Blocked& b : c.blocked) all.insert(all.end(), b.boundary.begin(), b.boundary.end());
  all.insert(all.end(), c.separators.begin(), c.separators.end());
  std::sort(all.begin(), all.end(), before);
  all.erase(std::unique(all.begin(), all.end(), same_direction), all.end());
  return all;
}

// Whether turning counter-clockwise from `in` to `out` keeps to free directions and crosses no
// separator (touching one at either end is sliding along its wall).
bool turns_freely(const Contact& c, const std::vector<Vector>& around, const Vector& in, const Vector& out) {
  const auto index = [&](const Vector& v) {
    return static_cast<std::size_t>(
        std::find_if(around.begin(), around.end(), [&](const Vector& w) { return same_direction(v, w); }) -
        around.begin());
  };
  const std::size_t n = around.size(), to = index(out);
  for (std::size_t i = index(in);; i = (i + 1) % n) {
    const Vector& here = around[i];
    const Vector& next = around[(i + 1) % n];
    if (!free_direction(c, here + next)) return false;  // between two turning directions
    if ((i + 1) % n == to) return true;
    if (!free_direction(c, next) || is_separator(c, next)) return false;
  }
}

std::string at_text(const Point& q) { return "(" + to_string(q.x) + ", " + to_string(q.y) + ")"; }

}  // namespace

std::optional<std::string> RoundWorld::Impl::blocked_at(const Point& q, const std::optional<Vector>& in,
                                                        const std::optional<Vector>& out) const {
  const Contact c = contact(q);
  if (c.inside)
    return "at " + at_text(q) +
           (c.inside_of == "the bounds" ? " the robot leaves the bounds" : " the robot overlaps " + c.inside_of);
  for (const auto& d : {in, out})
    if (d && !free_direction(c, *d)) return "at " + at_text(q) + " the motion turns into an obstacle it touches";
  if (!in || !out || same_direction(*in, *out) || (c.blocked.empty() && c.separators.empty())) return std::nullopt;
  const std::vector<Vector> around = turning_directions(c, *in, *out);
  if (turns_freely(c, around, *in, *out) || turns_freely(c, around, *out, *in)) return std::nullopt;
  return "at " + at_text(q) + " the motion crosses a wall or passes where obstacles touch (a passage of zero width)";
}

std::optional<std::string> RoundWorld::Impl::too_close(const Segment& s) const {
  using Core = Obstacle::Core;
  for (const Obstacle& o : obstacles) {
    if (o.core == Core::wall || (o.core == Core::polygon && o.radius == 0)) continue;  // their contacts decide
    Rational d2;
    if (o.core == Core::point) d2 = squared_distance(s, o.centre);
    if (o.core == Core::segment) d2 = squared_distance(s, Segment{o.from, o.to});
    if (o.core == Core::polygon) {
      d2 = side_of_polygon(*o.polygon, s.a) >= 0 ? Rational(0) : Rational(-1);
      for (const Ring& ring : rings_of(*o.polygon))
        for (const Segment& e : edges_of(ring)) {
          const Rational e2 = squared_distance(s, e);
          if (d2 < 0 || e2 < d2) d2 = e2;
        }
    }
    if (d2 < o.radius * o.radius)
      return robot == 0 ? "the motion enters " + o.name
                        : "the motion comes nearer " + o.name + " than the robot's radius allows";
  }
  return std::nullopt;
}

namespace {

// The parameters in (0, 1) along s of q's projection, and of where s crosses segment e.
void add_projection(const Segment& s, const Point& q, std::vector<Rational>& out) {
  const Rational t = nearest_parameter(s, q);
  if (t > 0 && t < 1) out.push_back(t);
}

void add_crossing(const Segment& s, const Segment& e, std::vector<Rational>& out) {
  const Vector d = s.b - s.a, f = e.b - e.a;
  const Rational denominator = cross(d, f);
  if (denominator == 0) return;  // parallel: the projections of e's ends bound any overlap
  const Rational t = cross(e.a - s.a, f) / denominator, u = cross(e.a - s.a, d) / denominator;
  if (t > 0 && t < 1 && u >= 0 && u <= 1) out.push_back(t);
}

void add_segment_events(const Segment& s, const Segment& e, std::vector<Rational>& out) {
  add_projection(s, e.a, out);
  add_projection(s, e.b, out);
  add_crossing(s, e, out);
}

}  // namespace

std::vector<Rational> RoundWorld::Impl::events(const Segment& s) const {
  using Core = Obstacle::Core;
  std::vector<Rational> out{0, 1};
  for (const Obstacle& o : obstacles) {
    if (o.core == Core::point) add_projection(s, o.centre, out);
    if (o.core == Core::segment) add_segment_events(s, Segment{o.from, o.to}, out);
    if (o.core == Core::wall)
      for (std::size_t i = 0; i + 1 < o.wall.size(); ++i) add_segment_events(s, {o.wall[i], o.wall[i + 1]}, out);
    if (o.core == Core::polygon)
      for (const Ring& ring : rings_of(*o.polygon))
        for (const Segment& e : edges_of(ring)) add_segment_events(s, e, out);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

RoundWorld::RoundWorld(const World& world) : impl_(nullptr) {
  if (!world.robot.parts.empty())
    throw InputError(world.source +
                     ": robot: a polygon robot among discs or walls (its C-obstacles are rounded "
                     "polygons): not checked yet; a point or a disc robot is");
  auto impl = std::make_unique<Impl>();
  impl->world = world;
  impl->robot = world.robot.disc.value_or(0);
  const Rational& rho = impl->robot;
  using Core = Impl::Obstacle::Core;
  for (std::size_t i = 0; i < impl->world.obstacles.size(); ++i)
    impl->obstacles.push_back({Core::polygon, {}, {}, {}, &impl->world.obstacles[i], {}, rho, world.obstacle_names[i]});
  for (std::size_t i = 0; i < world.discs.size(); ++i)
    impl->obstacles.push_back({Core::point,
                               world.discs[i].center,
                               {},
                               {},
                               nullptr,
                               {},
                               world.discs[i].radius + rho,
                               "discs[" + std::to_string(i) + "]"});
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    const Wall& wall = world.walls[i];
    const std::string name = "walls[" + std::to_string(i) + "]";
    if (rho == 0) impl->obstacles.push_back({Core::wall, {}, {}, {}, nullptr, wall, 0, name});
    else
      for (std::size_t k = 0; k + 1 < wall.size(); ++k)
        impl->obstacles.push_back({Core::segment, {}, wall[k], wall[k + 1], nullptr, {}, rho, name});
  }
  if (world.bounds)
    impl->box =
        Bounds{world.bounds->xmin + rho, world.bounds->ymin + rho, world.bounds->xmax - rho, world.bounds->ymax - rho};
  if (world.disc_bounds) impl->disc = Disc{world.disc_bounds->center, world.disc_bounds->radius - rho};
  impl_ = std::move(impl);
}

const World& RoundWorld::world() const { return impl_->world; }
const std::optional<Bounds>& RoundWorld::reference_box() const { return impl_->box; }
const std::optional<Disc>& RoundWorld::reference_disc() const { return impl_->disc; }

RoundWorld::~RoundWorld() = default;
RoundWorld::RoundWorld(RoundWorld&&) noexcept = default;
RoundWorld& RoundWorld::operator=(RoundWorld&&) noexcept = default;

std::optional<std::string> RoundWorld::config_not_free(const ExactPoint& q) const {
  const Contact c = impl_->contact(q);
  if (c.inside)
    return "(" + to_string(q.x) + ", " + to_string(q.y) +
           ") is not free: " + (c.inside_of == "the bounds" ? "outside the bounds" : "it overlaps " + c.inside_of);
  return std::nullopt;
}

PathCheck RoundWorld::check_segment(const ExactPoint& a, const ExactPoint& b) const { return check_path({a, b}); }

PathCheck RoundWorld::check_path(const std::vector<ExactPoint>& given) const {
  std::vector<Point> path;
  for (const Point& p : given)
    if (path.empty() || !(path.back() == p)) path.push_back(p);
  if (path.empty()) return {false, "the path is empty", std::nullopt};
  const auto invalid = [](std::size_t segment, const std::string& why) { return PathCheck{false, why, segment}; };
  for (std::size_t i = 0; i < path.size(); ++i) {
    std::optional<Vector> in, out;
    if (i > 0) in = path[i - 1] - path[i];
    if (i + 1 < path.size()) out = path[i + 1] - path[i];
    if (auto why = impl_->blocked_at(path[i], in, out)) return invalid(i == 0 ? 0 : i - 1, *why);
  }
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Segment s{path[i], path[i + 1]};
    if (auto why = impl_->too_close(s)) return invalid(i, *why);
    const Vector d = s.b - s.a, back{-d.x, -d.y};
    const std::vector<Rational> ts = impl_->events(s);
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const Rational middle = (ts[k] + ts[k + 1]) / 2;
      if (auto why = impl_->blocked_at(at(s, middle), back, d)) return invalid(i, *why);
      if (k > 0)
        if (auto why = impl_->blocked_at(at(s, ts[k]), back, d)) return invalid(i, *why);
    }
  }
  return {};
}

}  // namespace polyplan
