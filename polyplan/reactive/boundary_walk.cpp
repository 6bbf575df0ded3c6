#include <polyplan/reactive/boundary_walk.hpp>

#include <polyplan/geometry/path_check.hpp>

#include <algorithm>
#include <cmath>

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

std::optional<Point> Boundary::first_hit(const Point& from, const Point& to) const {
  if (check_segment(*cspace_, from, to).valid) return std::nullopt;
  std::vector<Rational> ts{0, 1};
  for (std::size_t c = 0; c < cycles_.size(); ++c)
    for (std::size_t i = 0; i < cycles_[c].size(); ++i) meetings(from, to, vertex(c, i), vertex(c, i + 1), ts);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  for (std::size_t k = 0; k + 1 < ts.size(); ++k)
    if (!check_segment(*cspace_, from, along(from, to, ts[k + 1])).valid) return along(from, to, ts[k]);
  return from;  // not reached: the whole way would be free
}

std::optional<Edge> Boundary::edge_at(const Point& p) const {
  for (std::size_t c = 0; c < cycles_.size(); ++c)
    for (std::size_t i = 0; i < cycles_[c].size(); ++i) {
      const Point &a = vertex(c, i), &b = vertex(c, i + 1);
      if (p == b || cross(a, b, p) != 0) continue;
      const Rational s = dot(a, p, b);
      if (s >= 0 && s < squared(a, b)) return Edge{c, i};
    }
  return std::nullopt;
}

double Boundary::perimeter(std::size_t cycle) const {
  double sum = 0;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i) sum += distance(vertex(cycle, i), vertex(cycle, i + 1));
  return sum;
}

std::size_t Boundary::crossings(std::size_t cycle, const Point& start, const Point& goal) const {
  std::vector<Rational> ts;
  for (std::size_t i = 0; i < cycles_[cycle].size(); ++i)
    meetings(start, goal, vertex(cycle, i), vertex(cycle, i + 1), ts);
  std::sort(ts.begin(), ts.end());
  return static_cast<std::size_t>(std::unique(ts.begin(), ts.end()) - ts.begin());
}

}  // namespace polyplan::walk
