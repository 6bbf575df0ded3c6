#include <polyplan/geometry/clearance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {
namespace {

struct Point2 {
  double x, y;
};

Point2 approximate(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Two segments that do not cross are nearest at an end of one of them.
double distance_between_segments(Point2 a, Point2 b, Point2 c, Point2 d) {
  return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d), distance_to_segment(c, a, b),
                   distance_to_segment(d, a, b)});
}

// Every boundary edge of the free space: the components' outer cycles (the walls and the
// C-obstacles they touch) and their holes.
std::vector<std::pair<Point2, Point2>> boundary_edges(const CSpace& cspace) {
  std::vector<std::pair<Point2, Point2>> edges;
  auto add = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) edges.push_back({approximate(ring[i]), approximate(ring[(i + 1) % ring.size()])});
  };
  for (const FreeComponent& c : cspace.free_components()) {
    add(c.outer);
    for (const Ring& h : c.holes) add(h);
  }
  return edges;
}

}  // namespace

double clearance_at(const CSpace& cspace, const ExactPoint& p) {
  return path_clearance(cspace, {p});
}

double path_clearance(const CSpace& cspace, const std::vector<ExactPoint>& path) {
  double nearest = std::numeric_limits<double>::infinity();
  const auto edges = boundary_edges(cspace);
  // A one-point path is the segment from the point to itself.
  const std::size_t segments = std::max<std::size_t>(path.size(), 2) - 1;
  for (std::size_t i = 0; i < segments && !path.empty(); ++i) {
    const Point2 a = approximate(path[i]), b = approximate(path[std::min(i + 1, path.size() - 1)]);
    for (const auto& [c, d] : edges) nearest = std::min(nearest, distance_between_segments(a, b, c, d));
  }
  return nearest;
}

}  // namespace polyplan
