#pragma once
// What TangentBug senses, and where the points its walk stops at lie, on each kind of boundary:
// the discontinuities of its sensed region, the points at the sensor's range on a straight way,
// the first point of a boundary part nearer the goal than d_followed, where a slide along a piece
// ends. tangent_bug_planner.cpp walks either boundary with them.
//
//   PolygonSenses  a polygon world's boundary (rational points): the discontinuities are the near
//                  ends of the windows of the exact visibility polygon (visibility_region.hpp); an
//                  event where a circle meets a line (the range, d_followed) is irrational, so the
//                  walk stops at the rational point on the same line a few ulps past it.
//   ArcSenses      a round world's boundary of segments and arcs (real algebraic points, CORE): the
//                  discontinuities are the corners of the boundary and the points where a sight
//                  line from the robot touches an arc, kept where the robot sees them within range
//                  and its sight runs on past them into the free space; the points where it
//                  touches, hits or crosses d_followed are exact, those at the range rational
//                  fractions of the way to the goal a few ulps within it.
//
// Only tangent_bug_planner.cpp and the two senses' units include this header (CORE, CGAL).
#include <polyplan/geometry/root_sum.hpp>
#include <polyplan/reactive/boundary_walk.hpp>
#include <polyplan/reactive/detail/arc_boundary.hpp>
#include <polyplan/reactive/visibility_region.hpp>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace polyplan::walk {

// A point that may be a discontinuity, and whether it was computed from the robot's position x
// (a touching point from x: a real algebraic number of higher degree than x's), not from the world.
template <class P>
struct Sighting {
  P point;
  bool from_x = false;
};

// A range sensor of radius `range` (inf: unlimited) on the boundary B's points.
template <class B>
class RangeSensor {
 public:
  using Boundary = B;
  using Point = typename B::Point;
  using Number = decltype(B::squared_distance(std::declval<Point>(), std::declval<Point>()));

  explicit RangeSensor(double range)
      : range_(range), squared_range_(std::isinf(range) ? Number(0) : B::number(Rational(range) * Rational(range))) {}
  double range() const { return range_; }
  bool senses(const Point& x, const Point& p) const {
    return std::isinf(range_) || B::squared_distance(x, p) <= squared_range_;
  }

 private:
  double range_;
  Number squared_range_;
};

class PolygonSenses : public RangeSensor<Boundary> {
 public:
  PolygonSenses(const Boundary& boundary, double range);

  // The walk's length so far, which decides max-distance: exactly, a sum of square roots, since
  // every point of a polygon walk is rational (`walked`, its double, is not needed).
  using Travel = RootSum;
  static void extend(Travel& travel, const Point& a, const Point& b, double) {
    travel.add(Boundary::squared_distance(a, b));
  }
  // Whether going on from a to b would take the walk beyond `most`: copied and summed exactly
  // only where the bounds cannot tell.
  static double walked_so_far(const Travel& travel) { return travel.approximate(); }
  static bool beyond(const Travel& travel, const Point& a, const Point& b, double, const Rational& most) {
    const Rational square = Boundary::squared_distance(a, b);
    if (const int sign = compare_bounds(travel.bounds() + root_bounds(square), rational_bounds(most))) return sign > 0;
    Travel further = travel;
    further.add(square);
    return compare(further, most) > 0;
  }

  // The points that may be discontinuities of the robot's sensed region at x, and whether one is
  // (sensed, seen, the sight running on past it): asked only of those a decision needs. `from_x`:
  // whether to include points computed from x (ArcSenses' touching points).
  std::vector<Sighting<Point>> candidates(const Point& x, bool from_x) const;
  bool discontinuity(const Point& x, const Point& o) const;
  // The sensed region at x, for a picture (the visibility polygon within range).
  std::vector<Point> region(const Point& x) const;
  // On the way from x to the goal, `hit` or `end` on it beyond the range: the point at the range
  // short of `hit`, and the point at the range from x.
  Point short_of(const Point& x, const Point& hit, const Point& goal) const;
  Point ahead(const Point& x, const Point& end, const Point& goal) const;
  // Following edge e from a to b (forwards or back): the first point nearer the goal than
  // d_followed (squared: `record`); nullopt when there is none.
  std::optional<Point> nearer_than(Edge e, bool forward, const Point& a, const Point& b, const Point& goal,
                                   const Rational& record) const;
  // Sliding along edge e from x towards `nearest` (the part's point nearest the goal): where it stops.
  Point slide_end(Edge, bool, const Point&, const Point& nearest, const Point&) const { return nearest; }
  // The point a fraction of the way from a to b (going along edge `along`, if any).
  Point cut(const Point& a, const Point& b, double fraction, const std::optional<Along>& along) const;

 private:
  const Boundary* boundary_;
  VisibilityRegions regions_;
};

class ArcSenses : public RangeSensor<ArcBoundary> {
 public:
  ArcSenses(const ArcBoundary& boundary, double range);

  // The walk's length so far: an arc's length is not algebraic, so CORE cannot compare it; in
  // doubles, as the walk measures its pieces (docs/exactness.md).
  using Travel = double;
  static void extend(Travel& travel, const AP&, const AP&, double walked) { travel += walked; }
  static double walked_so_far(Travel travel) { return travel; }
  static bool beyond(Travel travel, const AP&, const AP&, double walked, const Rational& most) {
    return travel + walked > to_double(most);
  }

  std::vector<Sighting<AP>> candidates(const AP& x, bool from_x) const;
  bool discontinuity(const AP& x, const AP& o) const;
  // (No picture of the sensed region among arcs.)
  std::vector<ExactPoint> region(const AP&) const { return {}; }
  // Points of the way x→goal at rational fractions of it (x + t (goal − x)), the first a few ulps
  // within the range: a point computed from x by a rational step keeps x's degree, where one at the
  // exact range (a square root of x's numbers) would double it at every stop.
  AP short_of(const AP& x, const AP& hit, const AP& goal) const;
  AP ahead(const AP& x, const AP& end, const AP& goal) const;
  std::optional<AP> nearer_than(Edge e, bool forward, const AP& a, const AP& b, const AP& goal,
                                const Algebraic& record) const;
  // On an arc, the slide stops where the goal comes into sight past the arc's own circle (where a
  // line from the goal touches it), if that comes before `nearest`.
  AP slide_end(Edge e, bool forward, const AP& x, const AP& nearest, const AP& goal) const;
  // Along an arc the walk cannot stop at a fraction of its length (an angle): it stays at a.
  AP cut(const AP& a, const AP& b, double fraction, const std::optional<Along>& along) const;

 private:
  // Whether, walking edge e forwards or back, x comes strictly before y.
  bool before(Edge e, bool forward, const AP& x, const AP& y) const {
    return forward ? boundary_->before(e, x, y) : boundary_->before(e, y, x);
  }

  const ArcBoundary* boundary_;
};

}  // namespace polyplan::walk
