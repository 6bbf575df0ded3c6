#pragma once
// The free space's boundary as the Bug planners walk it (bug1, bug2, tangent-bug): its cycles, each
// with the free space on its left (so a robot walking one keeps the obstacle on its right), where
// a straight way first meets them, and the edge a boundary point lies on. Everything exact: the
// points are rational, and every answer comes from exact predicates and the exact segment test.
// The boundary of a polygon world's C-space, or of a round world's whose C-obstacles are polygons
// and walls (round_boundary.cpp: a wall is a cycle of both its sides).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>

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

class Boundary {
 public:
  // The C-space (or the world) must outlive the boundary. A round world's is walked only when
  // every C-obstacle is a polygon or a wall (no arcs): otherwise InputError naming the file and
  // `who` (the planner).
  explicit Boundary(const CSpace& cspace);
  Boundary(const RoundWorld& world, const std::string& who);

  // The exact checks of the C-space it bounds, and why a query's start or goal is not free.
  PathCheck check_path(const std::vector<Point>& path) const;
  std::optional<std::string> query_not_free(const Query& query) const;
  // A polygon world's C-space (tangent-bug's visibility); std::logic_error for a round world.
  const CSpace& cspace() const;
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
  // How often the segment start-goal meets a cycle (distinct points; a wall met counts its two
  // sides, as a thin obstacle's are met going in and coming out).
  std::size_t crossings(std::size_t cycle, const Point& start, const Point& goal) const;

 private:
  const CSpace* cspace_ = nullptr;     // a polygon world's,
  const RoundWorld* round_ = nullptr;  // or a round world's
  std::vector<std::vector<Point>> cycles_;
};

}  // namespace polyplan::walk
