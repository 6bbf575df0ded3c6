#pragma once
// The free space's boundary as the Bug planners walk it (bug1, bug2, tangent-bug): its cycles, each
// with the free space on its left (so a robot walking one keeps the obstacle on its right), where
// a straight way first meets them, and the edge a boundary point lies on. Everything exact: the
// points are rational, and every answer comes from exact predicates and the exact segment test.
// The boundary of a polygon world's C-space (a round world's, with arcs and walls:
// detail/arc_boundary.hpp).
#include <polyplan/geometry/cspace.hpp>

#include <polyplan/geometry/path_check.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::walk {

using Point = ExactPoint;

// Exact arithmetic on points: the cross and dot products of a − o and b − o, the squared distance,
// the point a + t(b − a). `distance` is the double nearest to nothing in particular: a measure.
Rational cross(const Point& o, const Point& a, const Point& b);
Rational dot(const Point& o, const Point& a, const Point& b);
Rational squared(const Point& a, const Point& b);
Point along(const Point& a, const Point& b, const Rational& t);
double distance(const Point& a, const Point& b);
// "(x, y)" with six decimals, for facts and messages.
std::string text(const Point& p);

// The parameters t ∈ [0, 1] of p + t(q − p) where the segment a-b meets the segment p-q (both
// ends of a collinear overlap), appended to `out`. p ≠ q.
void meetings(const Point& p, const Point& q, const Point& a, const Point& b, std::vector<Rational>& out);

// An edge of a cycle: from vertex(cycle, index) to the next vertex.
struct Edge {
  std::size_t cycle = 0, index = 0;
};

// How the robot went from one point of its walk to the next when not straight: along a boundary
// edge, forwards (the free space on its left) or back.
struct Along {
  Edge edge;
  bool forward = true;
};

class Boundary {
 public:
  using Point = walk::Point;  // (the Bug planners' B::Point)
  // The C-space must outlive the boundary.
  explicit Boundary(const CSpace& cspace);

  // The exact checks of the C-space it bounds, and why a query's start or goal is not free.
  PathCheck check_path(const std::vector<Point>& path) const;
  std::optional<std::string> query_not_free(const Query& query) const;
  // The C-space (tangent-bug's visibility).
  const CSpace& cspace() const { return *cspace_; }
  const std::vector<std::vector<Point>>& cycles() const { return cycles_; }
  // Indices wrap round the cycle.
  const Point& vertex(std::size_t cycle, std::size_t i) const { return cycles_[cycle][i % cycles_[cycle].size()]; }

  // Where the straight way from `from` to `to` first stops being free (`from` itself when it cannot
  // set out at all); nullopt when the whole way is free.
  std::optional<Point> first_hit(const Point& from, const Point& to) const;
  // The edge the point lies on, starting there or passing through it; nullopt off the boundary.
  // Where several do (both sides of a wall, a pinch), the one a motion along `heading` runs into
  // (the obstacle on its right ahead), if any.
  std::optional<Edge> edge_at(const Point& p, const Point& heading = {0, 0}) const;
  double perimeter(std::size_t cycle) const;

  // The walk along an edge, as the Bug planners take it whatever the boundary (detail/arc_boundary.hpp
  // answers the same for arcs): the edge's ends; the points of the segment s-g on its part from a
  // to b (both on it, a first), in walking order; on which side of the edge's way at x the point p
  // lies (1 left, -1 right, 0 ahead or behind); the part's point nearest p; the part's length.
  std::size_t size(std::size_t cycle) const { return cycles_[cycle].size(); }
  const Point& start(Edge e) const { return vertex(e.cycle, e.index); }
  const Point& end(Edge e) const { return vertex(e.cycle, e.index + 1); }
  std::vector<Point> line_points(Edge e, const Point& a, const Point& b, const Point& s, const Point& g) const;
  int side(Edge e, const Point& x, const Point& p) const;
  Point nearest(Edge e, const Point& a, const Point& b, const Point& p) const;
  double length(Edge, const Point& a, const Point& b) const { return distance(a, b); }
  static Point point(const ExactPoint& p) { return p; }
  static Rational squared_distance(const Point& a, const Point& b) { return squared(a, b); }
  static Rational number(const Rational& q) { return q; }
  // How often the segment start-goal meets a cycle (distinct points; a wall met counts its two
  // sides, as a thin obstacle's are met going in and coming out).
  std::size_t crossings(std::size_t cycle, const Point& start, const Point& goal) const;

 private:
  const CSpace* cspace_;
  std::vector<std::vector<Point>> cycles_;
};

}  // namespace polyplan::walk
