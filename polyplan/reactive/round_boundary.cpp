// The Bug planners' boundary of a round world (boundary_walk.hpp) whose C-obstacles are polygons
// and walls (radius 0: a point robot among polygons and walls, or a polygon robot's Minkowski
// sums): every polygon edge, both sides of every wall and every side of the box become directed
// segments with the free space meant to lie on their left; they are cut wherever two meet, and a
// piece is kept where the exact rules (geometry/detail/round_rules.hpp) find its midpoint free and
// the way to its left open — so an edge inside another obstacle, or with another obstacle against
// it, drops out, and a wall keeps both its sides. The pieces are linked into cycles as a face of
// an arrangement is walked: at each point the next piece is the first one clockwise from the way
// back (a wall's end turns the walk round onto its other side).
#include <polyplan/reactive/boundary_walk.hpp>

#include <polyplan/geometry/detail/round_rules.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

namespace polyplan::walk {
namespace {

struct Piece {
  Point from, to;
  auto key() const { return std::tie(from.x, from.y, to.x, to.y); }
  friend bool operator<(const Piece& a, const Piece& b) { return a.key() < b.key(); }
  friend bool operator==(const Piece& a, const Piece& b) { return a.key() == b.key(); }
};

void refuse_arcs(const RoundWorld& world, const std::string& who) {
  if (!straight_edged(world.cspace()))
    throw InputError(world.world().source + ": " + round_features_text(world.world()) + ": the planner " + who +
                     " follows boundaries of straight edges only, and this world's C-obstacles have arcs (discs, a "
                     "disc robot or disc bounds): use visibility, the sampling planners or the grids");
}

std::vector<Piece> sides(const RoundCSpace& space) {
  std::vector<Piece> out;
  for (const RoundCore& core : space.obstacles) {
    for (const Ring& ring : core.rings)  // the polygon on each edge's left: walked the other way
      for (std::size_t k = 0; k < ring.size(); ++k) out.push_back({ring[(k + 1) % ring.size()], ring[k]});
    if (core.kind == RoundCore::Kind::wall)
      for (std::size_t k = 0; k + 1 < core.points.size(); ++k) {
        out.push_back({core.points[k], core.points[k + 1]});
        out.push_back({core.points[k + 1], core.points[k]});
      }
  }
  if (const auto& b = space.box) {  // the free space inside: counter-clockwise
    const Point corners[] = {{b->xmin, b->ymin}, {b->xmax, b->ymin}, {b->xmax, b->ymax}, {b->xmin, b->ymax}};
    for (int k = 0; k < 4; ++k) out.push_back({corners[k], corners[(k + 1) % 4]});
  }
  return out;
}

// Every piece cut at every point where another meets it.
std::vector<Piece> cut(const std::vector<Piece>& pieces) {
  std::vector<Piece> out;
  for (const Piece& p : pieces) {
    std::vector<Rational> ts{0, 1};
    for (const Piece& q : pieces) meetings(p.from, p.to, q.from, q.to, ts);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k)
      out.push_back({along(p.from, p.to, ts[k]), along(p.from, p.to, ts[k + 1])});
  }
  return out;
}

bool bounds_free_space(const round_rules::RoundRules<Rational>& rules, const Piece& p) {
  const Point m = along(p.from, p.to, Rational(1, 2));
  const round_rules::P<Rational> left{p.from.y - p.to.y, p.to.x - p.from.x};
  return !rules.blocked_at({m.x, m.y}, std::nullopt, left);
}

// Which of u, v comes first turning counter-clockwise from r (r itself first of all).
bool turns_before(const Point& r, const Point& u, const Point& v) {
  const Point o{0, 0};
  const auto half = [&](const Point& w) {
    const Rational c = cross(o, r, w);
    return c > 0 || (c == 0 && dot(o, r, w) > 0) ? 0 : 1;
  };
  const int hu = half(u), hv = half(v);
  return hu != hv ? hu < hv : cross(o, u, v) > 0;
}

std::vector<std::vector<Point>> link(const std::vector<Piece>& pieces) {
  std::map<std::pair<Rational, Rational>, std::vector<std::size_t>> starting;
  for (std::size_t i = 0; i < pieces.size(); ++i) starting[{pieces[i].from.x, pieces[i].from.y}].push_back(i);
  // The piece after j: of those leaving its end, the last counter-clockwise from the way back
  // (the first clockwise), the way back itself only when nothing else leaves.
  const auto next = [&](std::size_t j) {
    const Point& v = pieces[j].to;
    const Point back{pieces[j].from.x - v.x, pieces[j].from.y - v.y};
    const auto it = starting.find({v.x, v.y});
    if (it == starting.end()) throw std::logic_error("walk::Boundary: the boundary stops at " + text(v));
    const auto way = [&](std::size_t k) { return Point{pieces[k].to.x - v.x, pieces[k].to.y - v.y}; };
    return *std::max_element(it->second.begin(), it->second.end(),
                             [&](std::size_t a, std::size_t b) { return turns_before(back, way(a), way(b)); });
  };
  std::vector<std::vector<Point>> cycles;
  std::vector<bool> used(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (used[i]) continue;
    std::vector<Point>& cycle = cycles.emplace_back();
    for (std::size_t j = i; !used[j]; j = next(j)) {
      used[j] = true;
      cycle.push_back(pieces[j].from);
    }
  }
  return cycles;
}

}  // namespace

Boundary::Boundary(const RoundWorld& world, const std::string& who) : round_(&world) {
  refuse_arcs(world, who);
  const round_rules::RoundRules<Rational> rules(world.cspace(), [](const Rational& q) { return q; });
  std::vector<Piece> kept;
  for (const Piece& p : cut(sides(world.cspace())))
    if (bounds_free_space(rules, p)) kept.push_back(p);
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  cycles_ = link(kept);
}

}  // namespace polyplan::walk
