#pragma once
// The free space's boundary as the Bug planners walk it (bug1, bug2, tangent-bug): its cycles, each
// with the free space on its left (so a robot walking one keeps the obstacle on its right), where
// a straight way first meets them, and the edge a boundary point lies on. Everything exact: the
// points are rational, and every answer comes from exact predicates and the exact segment test.
#include <polyplan/geometry/cspace.hpp>

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
  // `cspace` must outlive the boundary.
  explicit Boundary(const CSpace& cspace);

  const CSpace& cspace() const { return *cspace_; }
  const std::vector<std::vector<Point>>& cycles() const { return cycles_; }
  // Indices wrap round the cycle.
  const Point& vertex(std::size_t cycle, std::size_t i) const { return cycles_[cycle][i % cycles_[cycle].size()]; }

  // Where the straight way from `from` to `to` first stops being free (`from` itself when it cannot
  // set out at all); nullopt when the whole way is free.
  std::optional<Point> first_hit(const Point& from, const Point& to) const;
  // The edge the point lies on, starting there or passing through it; nullopt off the boundary.
  std::optional<Edge> edge_at(const Point& p) const;
  double perimeter(std::size_t cycle) const;
  // How often the segment start-goal meets a cycle (distinct points).
  std::size_t crossings(std::size_t cycle, const Point& start, const Point& goal) const;

 private:
  const CSpace* cspace_;
  std::vector<std::vector<Point>> cycles_;
};

}  // namespace polyplan::walk
