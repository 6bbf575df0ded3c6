#include <polyplan/geometry/clearance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {

namespace {

// The point of the segment a-b nearest to p.
Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0;
  return {a.x + t * dx, a.y + t * dy};
}

double distance(Vec2 p, Vec2 q) { return std::hypot(p.x - q.x, p.y - q.y); }

// The distance between the segments a-b and c-d (not crossing), and the point of a-b where it is
// attained: two such segments are nearest at an end of one of them.
PathBottleneck nearest_between_segments(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  PathBottleneck best{distance(a, nearest_on_segment(a, c, d)), a};
  auto consider = [&](double distance_here, Vec2 at) {
    if (distance_here < best.clearance) best = {distance_here, at};
  };
  consider(distance(b, nearest_on_segment(b, c, d)), b);
  for (Vec2 end : {c, d}) {
    const Vec2 on_path = nearest_on_segment(end, a, b);
    consider(distance(end, on_path), on_path);
  }
  return best;
}

}  // namespace

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) { return distance(p, nearest_on_segment(p, a, b)); }

double distance_between_segments(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return nearest_between_segments(a, b, c, d).clearance;
}

namespace {

// Every boundary edge of the free space: the components' outer cycles (the walls and the
// C-obstacles they touch) and their holes.
std::vector<std::pair<Vec2, Vec2>> boundary_edges(const CSpace& cspace) {
  std::vector<std::pair<Vec2, Vec2>> edges;
  auto add = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      edges.push_back({approximate(ring[i]), approximate(ring[(i + 1) % ring.size()])});
  };
  for (const FreeComponent& c : cspace.free_components()) {
    add(c.outer);
    for (const Ring& h : c.holes) add(h);
  }
  return edges;
}

}  // namespace

double clearance_at(const CSpace& cspace, const ExactPoint& p) { return path_clearance(cspace, {p}); }

double path_clearance(const CSpace& cspace, const std::vector<ExactPoint>& path) {
  return path_bottleneck(cspace, path).clearance;
}

PathBottleneck path_bottleneck(const CSpace& cspace, const std::vector<ExactPoint>& path) {
  PathBottleneck best{std::numeric_limits<double>::infinity(), {}};
  const auto edges = boundary_edges(cspace);
  // A one-point path is the segment from the point to itself.
  const std::size_t segments = std::max<std::size_t>(path.size(), 2) - 1;
  for (std::size_t i = 0; i < segments && !path.empty(); ++i) {
    const Vec2 a = approximate(path[i]), b = approximate(path[std::min(i + 1, path.size() - 1)]);
    for (const auto& [c, d] : edges) {
      const PathBottleneck here = nearest_between_segments(a, b, c, d);
      if (here.clearance < best.clearance) best = here;
    }
  }
  return best;
}

}  // namespace polyplan
