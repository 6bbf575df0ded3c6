#include <polyplan/reactive/boundary_walk.hpp>

#include <polyplan/geometry/path_check.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace polyplan::walk {

Rational cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
Rational dot(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y);
}
Rational squared(const Point& a, const Point& b) { return dot(a, b, b); }
Point along(const Point& a, const Point& b, const Rational& t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}
double distance(const Point& a, const Point& b) { return std::sqrt(to_double(squared(a, b))); }
std::string text(const Point& p) {
  return "(" + std::to_string(to_double(p.x)) + ", " + std::to_string(to_double(p.y)) + ")";
}

void meetings(const Point& p, const Point& q, const Point& a, const Point& b, std::vector<Rational>& out) {
  const Rational da = cross(p, q, a), db = cross(p, q, b), pq = squared(p, q);
  const auto keep = [&](const Point& x) {
    const Rational t = dot(p, x, q) / pq;
    if (t >= 0 && t <= 1) out.push_back(t);
  };
  if (da == 0 && db == 0) {
    keep(a), keep(b);
    return;
  }
  if ((da > 0 && db > 0) || (da < 0 && db < 0)) return;
  const Point x = along(a, b, da / (da - db));  // on the line p-q
  const Rational s = dot(a, x, b), ab = squared(a, b);
  if (s >= 0 && s <= ab) keep(x);
}

namespace {

// The free space's boundary cycles, each walked with the free space on its left.
std::vector<std::vector<Point>> boundary_cycles(const CSpace& cspace) {
  std::vector<std::vector<Point>> cycles;
  const auto add = [&](const Ring& ring, bool free_inside) {
    if (ring.size() < 2) return;
    Rational area = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) area += cross({0, 0}, ring[i], ring[(i + 1) % ring.size()]);
    std::vector<Point> cycle(ring.begin(), ring.end());
    if ((area > 0) != free_inside) std::reverse(cycle.begin(), cycle.end());
    cycles.push_back(std::move(cycle));
  };
  for (const FreeComponent& c : cspace.free_components()) {
    add(c.outer, true);
    for (const Ring& hole : c.holes) add(hole, false);
  }
  return cycles;
}

}  // namespace

Boundary::Boundary(const CSpace& cspace) : cspace_(&cspace), cycles_(boundary_cycles(cspace)) {}

PathCheck Boundary::check_path(const std::vector<Point>& path) const { return polyplan::check_path(*cspace_, path); }

std::optional<std::string> Boundary::query_not_free(const Query& query) const { return cspace_->query_not_free(query); }

std::optional<Point> Boundary::first_hit(const Point& from, const Point& to) const {
  const auto free = [&](const Point& end) { return check_path({from, end}).valid; };
  if (free(to)) return std::nullopt;
  std::vector<Rational> ts{0, 1};
  for (std::size_t c = 0; c < cycles_.size(); ++c)
    for (std::size_t i = 0; i < cycles_[c].size(); ++i) meetings(from, to, vertex(c, i), vertex(c, i + 1), ts);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  for (std::size_t k = 0; k + 1 < ts.size(); ++k)
    if (!free(along(from, to, ts[k + 1]))) return along(from, to, ts[k]);
  return from;  // not reached: the whole way would be free
}

std::optional<Edge> Boundary::edge_at(const Point& p, const Point& heading) const {
  std::optional<Edge> first;
  for (std::size_t c = 0; c < cycles_.size(); ++c)
    for (std::size_t i = 0; i < cycles_[c].size(); ++i) {
      const Point &a = vertex(c, i), &b = vertex(c, i + 1);
      if (p == b || cross(a, b, p) != 0) continue;
      const Rational s = dot(a, p, b);
      if (s < 0 || s >= squared(a, b)) continue;
      const Point ahead{b.x - a.x, b.y - a.y};
      if (cross({0, 0}, ahead, heading) < 0) return Edge{c, i};  // heading into the obstacle on its right
      if (!first) first = Edge{c, i};
    }
  return first;
}

double Boundary::perimeter(std::size_t cycle) const {
  double sum = 0;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i) sum += distance(vertex(cycle, i), vertex(cycle, i + 1));
  return sum;
}

std::vector<Point> Boundary::line_points(Edge, const Point& a, const Point& b, const Point& s, const Point& g) const {
  std::vector<Rational> ts;
  if (!(a == b)) meetings(a, b, s, g, ts);
  std::sort(ts.begin(), ts.end());
  std::vector<Point> out;
  for (const Rational& t : ts) out.push_back(along(a, b, t));
  return out;
}

int Boundary::side(Edge e, const Point&, const Point& p) const { return sgn(cross(start(e), end(e), p)); }

Point Boundary::nearest(Edge, const Point& a, const Point& b, const Point& p) const {
  if (a == b) return a;
  return along(a, b, std::clamp(Rational(dot(a, p, b) / squared(a, b)), Rational(0), Rational(1)));
}

std::size_t Boundary::crossings(std::size_t cycle, const Point& start, const Point& goal) const {
  // Where, and how an edge crossing the line properly crosses it (1: left to right, 2: right to
  // left, 0: it ends on the line): a wall's two sides cross at one point both ways.
  std::vector<std::pair<Rational, int>> met;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i) {
    const Point &a = vertex(cycle, i), &b = vertex(cycle, i + 1);
    const int sa = sgn(cross(start, goal, a)), sb = sgn(cross(start, goal, b));
    const int way = sa * sb < 0 ? (sa > 0 ? 1 : 2) : 0;
    std::vector<Rational> ts;
    meetings(start, goal, a, b, ts);
    for (const Rational& t : ts) met.emplace_back(t, way);
  }
  std::sort(met.begin(), met.end());
  return static_cast<std::size_t>(std::unique(met.begin(), met.end()) - met.begin());
}

}  // namespace polyplan::walk
