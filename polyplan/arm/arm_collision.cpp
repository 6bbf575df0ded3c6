#include <polyplan/arm/arm_collision.hpp>

#include <polyplan/arm/detail/outward_rounding.hpp>
#include <polyplan/arm/detail/true_arm_bounds.hpp>
#include <polyplan/geometry/rational.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

// Epick: double coordinates, exact (filtered) predicates. Nothing here constructs a new point
// from others except the kinematics themselves, which are doubles by nature.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;

// A closed axis-aligned box of double coordinates. Comparisons of doubles are exact, so a box
// that misses another box (or a point) proves that what it bounds misses it too.
struct Box {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
  double xmax = -std::numeric_limits<double>::infinity(), ymax = xmax;
  void add(const Point& p) {
    xmin = std::min(xmin, p.x());
    ymin = std::min(ymin, p.y());
    xmax = std::max(xmax, p.x());
    ymax = std::max(ymax, p.y());
  }
  void add(const Box& b) {
    xmin = std::min(xmin, b.xmin);
    ymin = std::min(ymin, b.ymin);
    xmax = std::max(xmax, b.xmax);
    ymax = std::max(ymax, b.ymax);
  }
  bool overlaps(const Box& o) const { return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax; }
  bool contains(const Point& p) const { return xmin <= p.x() && p.x() <= xmax && ymin <= p.y() && p.y() <= ymax; }
};

constexpr double infinity = std::numeric_limits<double>::infinity();

using detail::above;
using detail::below;
using detail::Interval;
using detail::RoundingUpward;

// The box grown by d (≥ 0, +infinity for no limit) on every side, rounded outward: what lies
// outside it lies farther than d from the box, on one axis and so in distance.
Box grown(const Box& b, double d) {
  if (!std::isfinite(d)) {
    Box all;
    all.xmin = all.ymin = -std::numeric_limits<double>::infinity();
    all.xmax = all.ymax = std::numeric_limits<double>::infinity();
    return all;
  }
  Box g;
  g.xmin = below(b.xmin - d), g.ymin = below(b.ymin - d);
  g.xmax = above(b.xmax + d), g.ymax = above(b.ymax + d);
  return g;
}

// A lower bound of the squared gap between two boxes (0 when they overlap). RoundingUpward must
// be in force: each difference rounded up and negated is a lower bound of the gap on its axis,
// and −(−dx·dx − dy·dy), each operation rounded up, one of the sum of squares. Plain doubles,
// not intervals: this runs for every obstacle and edge near every link.
inline double squared_gap_below(const Box& a, const Box& b) {
  const double dx = std::max({0.0, -(a.xmax - b.xmin), -(b.xmax - a.xmin)});
  const double dy = std::max({0.0, -(a.ymax - b.ymin), -(b.ymax - a.ymin)});
  return -((-dx) * dx - dy * dy);
}

// Whether something whose box lies a squared gap of at least `squared_box_gap` from the link's
// can be skipped, when `radius` bounds how far the true shapes may lie from the computed ones: it
// lies apart from the link (gap > radius, so the computed shapes do not meet either) and its
// clearance cannot come below `enough` (gap − radius ≥ enough). RoundingUpward must be in force
// (the squares of the radius and of enough + radius round up).
inline bool cannot_matter(double squared_box_gap, double radius, double enough) {
  if (!std::isfinite(enough)) return false;
  const double reach = enough + radius;
  return squared_box_gap > radius * radius && squared_box_gap >= reach * reach;
}

// A clearance: a lower bound of the distance between the computed shapes less the radius that
// bounds how far the true shapes lie from them, never below 0. RoundingUpward must be in force.
double clearance_below(double distance, double radius) { return std::max(0.0, -(radius - distance)); }

// A lower bound of the squared distance from p to the segment ab (a == b allowed), in real
// arithmetic on the doubles' values. RoundingUpward must be in force.
double squared_distance_below(const Point& p, const Point& a, const Point& b) {
  const Interval vx = Interval(b.x()) - Interval(a.x()), vy = Interval(b.y()) - Interval(a.y());
  const Interval wx = Interval(p.x()) - Interval(a.x()), wy = Interval(p.y()) - Interval(a.y());
  if ((vx * wx + vy * wy).sup() <= 0) return (CGAL::square(wx) + CGAL::square(wy)).inf();  // nearest: a
  const Interval ux = Interval(p.x()) - Interval(b.x()), uy = Interval(p.y()) - Interval(b.y());
  if ((vx * ux + vy * uy).inf() >= 0) return (CGAL::square(ux) + CGAL::square(uy)).inf();  // nearest: b
  // Between the ends, or too near one to tell: no point of the segment is nearer than its line.
  return (CGAL::square(vx * wy - vy * wx) / (CGAL::square(vx) + CGAL::square(vy))).inf();
}

// A closed convex shape given by 1 vertex (a point), 2 (a segment) or 4 (a strictly convex
// quadrilateral, counter-clockwise): a link, or an edge of an obstacle.
struct Convex {
  std::array<Point, 4> v;
  int n = 0;
  Box box;
};

Convex make_segment(const Point& a, const Point& b) {
  Convex s;
  s.v[0] = a;
  s.v[1] = b;
  s.n = a == b ? 1 : 2;  // an edge whose two rationals round to one double is a point
  s.box.add(a);
  s.box.add(b);
  return s;
}

bool strictly_convex(const std::array<Point, 4>& v) {
  for (int i = 0; i < 4; ++i)
    if (CGAL::orientation(v[i], v[(i + 1) % 4], v[(i + 2) % 4]) != CGAL::LEFT_TURN) return false;
  return true;
}

bool contains(const Convex& s, const Point& p) {
  switch (s.n) {
    case 1: return s.v[0] == p;
    case 2:
      return CGAL::orientation(s.v[0], s.v[1], p) == CGAL::COLLINEAR &&
             CGAL::collinear_are_ordered_along_line(s.v[0], p, s.v[1]);
    default:  // inside or on the boundary: never strictly to the right of an edge
      for (int i = 0; i < 4; ++i)
        if (CGAL::orientation(s.v[i], s.v[(i + 1) % 4], p) == CGAL::RIGHT_TURN) return false;
      return true;
  }
}

int edge_count(const Convex& s) { return s.n == 4 ? 4 : s.n - 1; }
Segment edge(const Convex& s, int i) { return {s.v[i], s.v[(i + 1) % s.n]}; }

// Two closed convex shapes meet when their boundaries cross or touch, or one lies inside the other
// (then it contains any vertex of it).
bool meets(const Convex& a, const Convex& b) {
  if (!a.box.overlaps(b.box)) return false;
  if (a.n == 1) return contains(b, a.v[0]);
  if (b.n == 1) return contains(a, b.v[0]);
  for (int i = 0; i < edge_count(a); ++i)
    for (int j = 0; j < edge_count(b); ++j)
      if (CGAL::do_intersect(edge(a, i), edge(b, j))) return true;
  return contains(b, a.v[0]) || contains(a, b.v[0]);
}

// A lower bound of the squared distance from p to the segment ab's box. RoundingUpward must be in
// force. Cheaper than the distance itself, which it bounds from below.
inline double squared_gap_to_box_below(const Point& p, const Point& a, const Point& b) {
  const double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x());
  const double y0 = std::min(a.y(), b.y()), y1 = std::max(a.y(), b.y());
  const double dx = std::max({0.0, -(p.x() - x0), -(x1 - p.x())});
  const double dy = std::max({0.0, -(p.y() - y0), -(y1 - p.y())});
  return -((-dx) * dx - dy * dy);
}

// The smaller of `best` and a lower bound of the squared distance from p to the boundary of s,
// which is its distance to s when p lies outside s: edges whose box lies at least `best` away are
// not measured. RoundingUpward must be in force.
double squared_distance_to_boundary_below(const Point& p, const Convex& s, double best = infinity) {
  if (s.n == 1) return std::min(best, squared_distance_below(p, s.v[0], s.v[0]));
  for (int i = 0; i < edge_count(s); ++i) {
    const Point &a = s.v[i], &b = s.v[(i + 1) % s.n];
    if (squared_gap_to_box_below(p, a, b) >= best) continue;
    best = std::min(best, squared_distance_below(p, a, b));
  }
  return best;
}

// The distances again in plain doubles, fast, with an error bound: they only choose which
// candidates the interval bounds are computed for (obstacle_clearance), never a clearance's value.
//
// Error bound. In any rounding mode each operation errs by less than 2^-52 relative. With every
// coordinate at most M in magnitude, the differences are at most 2M and err by at most 2^-51·M;
// whatever t the clamped quotient gives, a + t·v lies on the segment, so a wrong t only moves the
// point measured along it, by |Δt|·|v| ≤ 2^-47·M; the squared distance then errs by at most
// 2^8·2^-52·M² = 2^-44·M² (a dozen operations on values up to 16·M²), and the distance, since
// |√x − √y| ≤ √|x − y|, by at most 2^-22·M. gather allows 2^-20·M, 4 times that; the minimum
// over vertex–edge pairs keeps the bound.
double squared_point_segment_distance(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y();
  const double wx = p.x() - a.x(), wy = p.y() - a.y();
  const double vv = vx * vx + vy * vy;
  const double t = vv > 0 ? std::clamp((wx * vx + wy * vy) / vv, 0.0, 1.0) : 0.0;
  const double dx = wx - t * vx, dy = wy - t * vy;
  return dx * dx + dy * dy;
}
double squared_distance_to_boundary(const Point& p, const Convex& s) {
  if (s.n == 1) return squared_point_segment_distance(p, s.v[0], s.v[0]);
  double best = infinity;
  for (int i = 0; i < edge_count(s); ++i)
    best = std::min(best, squared_point_segment_distance(p, s.v[i], s.v[(i + 1) % s.n]));
  return best;
}
double distance_apart(const Convex& a, const Convex& b) {
  double best = infinity;
  for (int i = 0; i < a.n; ++i) best = std::min(best, squared_distance_to_boundary(a.v[i], b));
  for (int i = 0; i < b.n; ++i) best = std::min(best, squared_distance_to_boundary(b.v[i], a));
  return std::sqrt(best);
}
// The largest coordinate, in magnitude, of two boxes: M of the fast distances' error bound.
double largest_coordinate(const Box& a, const Box& b) {
  return std::max({std::fabs(a.xmin), std::fabs(a.xmax), std::fabs(a.ymin), std::fabs(a.ymax), std::fabs(b.xmin),
                   std::fabs(b.xmax), std::fabs(b.ymin), std::fabs(b.ymax)});
}

// A lower bound of the square root of a lower bound (with RoundingUpward in force the root rounds
// up; the double below it does not exceed the real root).
double root_below(double squared) { return squared > 0 ? below(std::sqrt(squared)) : 0.0; }

// A lower bound of the distance between two closed convex shapes that do not meet: the nearest
// pair of points of two disjoint convex polygons (or segments, or points) always has a vertex of
// one of them. RoundingUpward must be in force.
double distance_apart_below(const Convex& a, const Convex& b) {
  double best = infinity;
  for (int i = 0; i < a.n; ++i) best = squared_distance_to_boundary_below(a.v[i], b, best);
  for (int i = 0; i < b.n; ++i) best = squared_distance_to_boundary_below(b.v[i], a, best);
  return root_below(best);
}

struct Obstacle {
  std::size_t index = 0;  // in the problem's obstacles
  Box box;
  // How far the file's exact vertices may lie from their nearest doubles (an ulp in each
  // coordinate, rounded up): the exact polygon lies within this of the one measured.
  double rounding = 0;
  std::vector<Convex> edges;  // of the outer boundary and of the holes
  std::vector<Point> outer;
  std::vector<std::vector<Point>> holes;
};

// The closed region: inside or on the outer boundary, and not strictly inside a hole.
bool region_contains(const Obstacle& o, const Point& p) {
  if (!o.box.contains(p)) return false;
  if (CGAL::bounded_side_2(o.outer.begin(), o.outer.end(), p, Kernel()) == CGAL::ON_UNBOUNDED_SIDE) return false;
  for (const auto& hole : o.holes)
    if (CGAL::bounded_side_2(hole.begin(), hole.end(), p, Kernel()) == CGAL::ON_BOUNDED_SIDE) return false;
  return true;
}

// A connected closed link that touches no boundary edge lies in one face of the obstacle's
// boundary: inside the region or outside it, which any one of its points tells.
bool link_meets(const Convex& link, const Obstacle& o) {
  if (!link.box.overlaps(o.box)) return false;
  for (const Convex& e : o.edges)
    if (meets(link, e)) return true;
  return region_contains(o, link.v[0]);
}

struct PointObstacle {
  Point p;                // the file's point is a double (arm files round their numbers once)
  std::size_t index = 0;  // in the problem's points
  Box box;                // p alone
};

// An upper bound of the distance between a rational coordinate pair and its nearest doubles
// (to_double rounds to nearest: within half an ulp per coordinate; a whole ulp is allowed).
double rounding_of(const Point& rounded) {
  const RoundingUpward upward;
  const auto ulp = [](double x) { return above(std::fabs(x)) - std::fabs(x); };
  return ulp(rounded.x()) + ulp(rounded.y());
}

std::vector<Point> to_points(const Ring& ring) {
  std::vector<Point> out;
  out.reserve(ring.size());
  for (const ExactPoint& q : ring) out.emplace_back(to_double(q.x), to_double(q.y));
  return out;
}

void add_edges(const std::vector<Point>& ring, std::vector<Convex>& edges) {
  for (std::size_t i = 0; i < ring.size(); ++i) edges.push_back(make_segment(ring[i], ring[(i + 1) % ring.size()]));
}

}  // namespace

std::string ArmContact::describe() const {
  const std::string what = with == With::polygon ? "obstacles[" + std::to_string(index) + "]"
                           : with == With::point ? "points[" + std::to_string(index) + "]"
                                                 : "link " + std::to_string(index + 1);
  return "link " + std::to_string(link + 1) + " meets " + what;
}

struct ArmCollisionChecker::Impl {
  Arm arm;
  std::vector<Obstacle> obstacles;  // only those the arm can reach
  std::vector<PointObstacle> points;
  Box everything;                  // of the kept obstacles and points
  double everything_rounding = 0;  // the largest rounding of the kept obstacles
  // Scratch for one check, kept to avoid allocating per call.
  mutable std::vector<Eigen::Vector2d> joints, directions;
  mutable std::vector<double> headings;
  mutable std::vector<Convex> links;
  // After place_enclosed: links[k] lies within link_radius[k] of the true link k, at every
  // configuration the spread covers.
  mutable detail::TrueArmBounds true_arm;
  mutable std::vector<double> link_radius;
  // obstacle_clearance's candidates: edges near a link (with their obstacle's rounding), points.
  // gather's candidates: an edge or a point with a lower bound of its clearance from the fast
  // distance, and the radius (the link's and the obstacle's rounding) its interval bound subtracts.
  struct Measured {
    double fast_below;
    const Convex* edge;
    const PointObstacle* point;
    double radius;
    double error;  // the fast distance's error bound
  };
  mutable std::vector<Measured> measured;
  mutable std::vector<std::size_t> candidate_begin;  // [k]: link k's first candidate
  mutable std::vector<double> nearest;               // [k]: the smaller of reach[k] and every candidate's upper bound
  mutable std::vector<bool> link_hit, pair_hit;
  mutable ArmClearances split;
  mutable std::size_t checks = 0;

  Impl(const Arm& a, const std::vector<PolygonWithHoles>& polygons, const std::vector<Eigen::Vector2d>& point_list)
      : arm(a), true_arm(arm) {
    if (arm.links.empty()) throw std::invalid_argument("ArmCollisionChecker: the arm has no links");
    for (double l : arm.links)
      if (!(l > 0) || !std::isfinite(l))
        throw std::invalid_argument("ArmCollisionChecker: a link length is not positive and finite");
    if (!(arm.link_width >= 0) || !std::isfinite(arm.link_width))
      throw std::invalid_argument("ArmCollisionChecker: the link width is negative or not finite");
    const double reach = arm.reach();
    if (!std::isfinite(reach)) throw std::invalid_argument("ArmCollisionChecker: the arm's length is not finite");
    // Whatever lies outside the disc of radius reach can never be touched. The box around it is
    // widened far beyond the rounding of the computed coordinates and of the reach, and of the
    // obstacles' vertices, so dropping is always safe.
    Box reachable;
    const double r = reach * (1 + 1e-6);
    reachable.add(Point(-r, -r));
    reachable.add(Point(r, r));

    for (std::size_t i = 0; i < polygons.size(); ++i) {
      const PolygonWithHoles& polygon = polygons[i];
      if (polygon.outer.size() < 3)
        throw std::invalid_argument("ArmCollisionChecker: an obstacle has fewer than 3 vertices");
      Obstacle o;
      o.index = i;
      o.outer = to_points(polygon.outer);
      for (const Point& p : o.outer) o.box.add(p);
      if (!o.box.overlaps(reachable)) continue;
      add_edges(o.outer, o.edges);
      for (const Ring& hole : polygon.holes) {
        o.holes.push_back(to_points(hole));
        add_edges(o.holes.back(), o.edges);
      }
      for (const Convex& e : o.edges) o.rounding = std::max(o.rounding, rounding_of(e.v[0]));
      everything.add(o.box);
      everything_rounding = std::max(everything_rounding, o.rounding);
      obstacles.push_back(std::move(o));
    }
    for (std::size_t i = 0; i < point_list.size(); ++i) {
      const Eigen::Vector2d& p = point_list[i];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        throw std::invalid_argument("ArmCollisionChecker: a point is not finite");
      const Point q(p.x(), p.y());
      if (!reachable.contains(q)) continue;
      PointObstacle kept{q, i, {}};
      kept.box.add(q);
      everything.add(q);
      points.push_back(kept);
    }
  }

  // links[k] as a closed convex shape; a rectangle too thin to be strictly convex in doubles is
  // its segment (the rectangle then differs from the segment by rounding only).
  void shape_link(std::size_t k, Convex& out) const {
    std::array<Eigen::Vector2d, 4> corners;
    const std::size_t n = link_outline_into(arm, joints, k, corners);
    out.box = Box();
    if (n == 4) {
      for (int i = 0; i < 4; ++i) out.v[i] = Point(corners[i].x(), corners[i].y());
      if (strictly_convex(out.v)) {
        out.n = 4;
        for (const Point& p : out.v) out.box.add(p);
        return;
      }
    }
    out = make_segment(Point(joints[k].x(), joints[k].y()), Point(joints[k + 1].x(), joints[k + 1].y()));
  }

  // Puts the arm in configuration q: joints and link shapes. Counts one check.
  void place(const JointAngles& q) const {
    joint_positions_into(arm, q, joints);  // validates the angles
    ++checks;
    const std::size_t n = arm.joints();
    links.resize(n);
    for (std::size_t k = 0; k < n; ++k) shape_link(k, links[k]);
  }

  // place, and for the clearances: link_radius[k] bounds how far the computed links[k] may lie
  // from the true link k at every configuration within spread[j] of q in each joint (empty: q).
  void place_enclosed(const JointAngles& q, std::span<const double> spread) const {
    const std::size_t n = arm.joints();
    if (!spread.empty() && spread.size() != n)
      throw std::invalid_argument("ArmCollisionChecker: " + std::to_string(spread.size()) + " spreads for an arm of " +
                                  std::to_string(n) + " links");
    if (!std::all_of(spread.begin(), spread.end(), [](double s) { return s >= 0 && std::isfinite(s); }))
      throw std::invalid_argument("ArmCollisionChecker: a spread is negative or not finite");
    joint_positions_into(arm, q, joints, &headings, &directions);  // validates the angles
    ++checks;
    links.resize(n);
    for (std::size_t k = 0; k < n; ++k) shape_link(k, links[k]);  // exact convexity tests: to nearest
    link_radius.resize(n);
    const RoundingUpward upward;
    true_arm.enclose(q, spread, headings, directions, joints);
    for (std::size_t k = 0; k < n; ++k) {
      const Convex& link = links[k];
      std::array<Eigen::Vector2d, 4> corners;
      if (link.n == 4)
        for (int i = 0; i < 4; ++i) corners[static_cast<std::size_t>(i)] = {link.v[i].x(), link.v[i].y()};
      else corners[0] = joints[k], corners[1] = joints[k + 1];
      link_radius[k] = true_arm.link_radius(k, std::span(corners.data(), link.n == 4 ? 4 : 2));
    }
  }

  std::optional<ArmContact> contact(const JointAngles& angles) const {
    place(angles);
    const std::size_t n = arm.joints();
    for (std::size_t k = 0; k < n; ++k) {
      if (const auto met = obstacle_contact(k)) return met;
      if (arm.self_collision)
        for (std::size_t j = k + 2; j < n; ++j)
          if (meets(links[k], links[j])) return ArmContact{k, ArmContact::With::link, j};
    }
    return std::nullopt;
  }

  // The first obstacle or point the placed links[k] meets, in first_contact's order: only what its
  // box overlaps can meet it.
  std::optional<ArmContact> obstacle_contact(std::size_t k) const {
    const Convex& link = links[k];
    if (!link.box.overlaps(everything)) return std::nullopt;
    for (const Obstacle& o : obstacles)
      if (link_meets(link, o)) return ArmContact{k, ArmContact::With::polygon, o.index};
    for (const PointObstacle& p : points)
      if (link.box.contains(p.p) && contains(link, p.p)) return ArmContact{k, ArmContact::With::point, p.index};
    return std::nullopt;
  }

  // After place_enclosed, rounding to nearest: what each link meets, exactly, and which obstacles
  // may hold its clearance. For each link k in first_contact's order: link_hit[k] when it meets an
  // obstacle or a point, pair_hit[k·n + m] when (self-collision) it meets a later link m ≥ k + 2,
  // the first such contact into `contact` unless it holds one. Otherwise every edge and point
  // within reach of it, as their boxes tell (the link's box grown outward by the reach, its radius
  // and the obstacles' rounding), gets a fast distance (plain doubles, with an error bound) as a
  // candidate: measured[candidate_begin[k] .. candidate_begin[k + 1]). Each fast distance, plus its
  // error, bounds some true clearance from above and shrinks the reach for those after it, as the
  // single pass of a collision checker does in doubles. The reach: `enough` for every link when
  // link_speed is empty (clearances); otherwise (safe_step) what link k covers at its speed in
  // the largest step still possible: `enough` (the horizon) at first, then no more than any
  // link's clearance so far over its speed.
  void gather(std::span<const double> link_speed, double enough, std::optional<ArmContact>& contact) const {
    const std::size_t n = arm.joints();
    const auto met = [&](ArmContact c) {
      if (!contact) contact = c;
    };
    link_hit.assign(n, false);
    pair_hit.assign(arm.self_collision ? n * n : 0, false);
    measured.clear();
    candidate_begin.assign(1, 0);
    nearest.assign(n, 0.0);
    double step = enough;  // safe_step: above the step it will find
    for (std::size_t k = 0; k < n; ++k) {
      const Convex& link = links[k];
      const double r = link_radius[k];
      double& within = nearest[k];
      within = link_speed.empty() ? enough : detail::covered_above(link_speed[k], step);
      Box near = grown(link.box, above(above(within + r) + everything_rounding));
      // A candidate's fast clearance: lower and upper bounds of some true clearance.
      const auto candidate = [&](double fast, double radius, const Box& box, const Convex* edge,
                                 const PointObstacle* point) {
        const double error = above(0x1p-20 * largest_coordinate(link.box, box));
        measured.push_back({below(below(fast - radius) - error), edge, point, radius, error});
        const double upper = above(above(fast - radius) + error);
        if (upper < within) within = upper, near = grown(link.box, above(above(within + r) + everything_rounding));
      };
      if (near.overlaps(everything))
        for (const Obstacle& o : obstacles) {
          if (!near.overlaps(o.box)) continue;
          if (link_meets(link, o)) {
            met({k, ArmContact::With::polygon, o.index}), link_hit[k] = true;
            break;
          }
          // Apart from an obstacle's closed region, the link is nearest to its boundary: one of the edges.
          for (const Convex& e : o.edges)
            if (near.overlaps(e.box)) candidate(distance_apart(link, e), above(r + o.rounding), e.box, &e, nullptr);
        }
      for (const PointObstacle& p : points) {
        if (link_hit[k] || !near.contains(p.p)) continue;
        if (link.box.contains(p.p) && contains(link, p.p))
          met({k, ArmContact::With::point, p.index}), link_hit[k] = true;
        else candidate(std::sqrt(squared_distance_to_boundary(p.p, link)), r, p.box, nullptr, &p);
      }
      if (link_hit[k]) measured.resize(candidate_begin.back());
      candidate_begin.push_back(measured.size());
      if (!link_speed.empty() && link_speed[k] > 0) step = std::min(step, above(within / link_speed[k]));
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m)
          if (meets(link, links[m])) met({k, ArmContact::With::link, m}), pair_hit[k * n + m] = true;
    }
  }

  // The clearance of the true link k to the obstacle polygons and points, after gather: 0 when it
  // meets one, otherwise the smallest lower bound below `enough` or, when none is below it, a value
  // of at least `enough` (+infinity when nothing was measured). Interval bounds are computed only
  // for the candidates whose fast clearance may be the smallest: a candidate whose lower bound
  // exceeds what another's upper bound (gather's nearest) or `enough` allows is farther for sure.
  // RoundingUpward must be in force (one guard for every link: switching the rounding costs more
  // than a distance).
  double obstacle_clearance(std::size_t k, double enough, ClearanceUse use) const {
    if (link_hit[k]) return 0;
    const Convex& link = links[k];
    const double limit = std::min(nearest[k], enough);
    double best = infinity;
    for (std::size_t i = candidate_begin[k]; i < candidate_begin[k + 1]; ++i) {
      const Measured& m = measured[i];
      if (m.fast_below > limit) continue;
      // The fast clearance less its error is a lower bound too (the error analysis above); it
      // falls short of the interval bound by at most twice the error, which costs a clearance of
      // 2^10 errors or more at most 2^-9 of the step it allows. Nearer contact, where that would
      // refuse or shorten steps, the interval bound is computed.
      if (use == ClearanceUse::stepping && m.fast_below >= 1024 * m.error) {
        best = std::min(best, m.fast_below);
        continue;
      }
      const double d = m.edge ? distance_apart_below(link, *m.edge)
                              : root_below(squared_distance_to_boundary_below(m.point->p, link));
      best = std::min(best, clearance_below(d, m.radius));
    }
    return best;
  }

  // The clearance between the true links k and m (self-collision, |k − m| ≥ 2) after gather, as
  // obstacle_clearance measures it: 0 when the computed links meet, +infinity when it cannot be
  // below `enough`. RoundingUpward must be in force.
  double pair_clearance(std::size_t k, std::size_t m, double enough) const {
    if (pair_hit[k * arm.joints() + m]) return 0;
    const Convex& a = links[k];
    const Convex& b = links[m];
    const double radius = link_radius[k] + link_radius[m];
    if (cannot_matter(squared_gap_below(a.box, b.box), radius, enough)) return infinity;
    return clearance_below(distance_apart_below(a, b), radius);
  }

  void clearances(const JointAngles& q, ArmClearances& out, double enough, ClearanceUse use) const {
    place_enclosed(q, {});
    const std::size_t n = arm.joints();
    out.contact.reset();
    gather({}, enough, out.contact);
    out.links.assign(n, infinity);
    if (arm.self_collision) out.pairs.assign(n * n, infinity);
    else out.pairs.clear();
    const RoundingUpward upward;
    for (std::size_t k = 0; k < n; ++k) {
      out.links[k] = obstacle_clearance(k, enough, use);
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m)
          out.pairs[k * n + m] = out.pairs[m * n + k] = pair_clearance(k, m, enough);
    }
  }

  ArmSafeStep safe_step(const JointAngles& q, std::span<const double> link_speed, std::span<const double> pair_speed,
                        double horizon, std::span<const double> spread) const {
    const std::size_t n = arm.joints();
    if (link_speed.size() != n || pair_speed.size() != (arm.self_collision ? n * n : 0))
      throw std::invalid_argument("ArmCollisionChecker::safe_step: " + std::to_string(link_speed.size()) +
                                  " link speeds and " + std::to_string(pair_speed.size()) +
                                  " pair speeds for an arm of " + std::to_string(n) + " links" +
                                  (arm.self_collision ? " with" : " without") + " self-collision");
    const auto valid = [](double x) { return x >= 0 && std::isfinite(x); };
    if (!(horizon >= 0) || !std::all_of(link_speed.begin(), link_speed.end(), valid) ||
        !std::all_of(pair_speed.begin(), pair_speed.end(), valid))
      throw std::invalid_argument(
          "ArmCollisionChecker::safe_step: speeds must be finite and not negative, the horizon not negative");
    place_enclosed(q, spread);
    using detail::covered_above;
    using detail::lasts_below;
    // A clearance above speed · step cannot lower the step: nothing farther is gathered.
    ArmSafeStep result;
    gather(link_speed, horizon, result.contact);
    if (result.contact) return result;
    double step = horizon;
    const RoundingUpward upward;  // covered_above and lasts_below bound in any rounding
    for (std::size_t k = 0; k < n; ++k) {
      step =
          std::min(step, lasts_below(obstacle_clearance(k, covered_above(link_speed[k], step), ClearanceUse::stepping),
                                     link_speed[k]));
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m) {
          const double v = pair_speed[k * n + m];
          step = std::min(step, lasts_below(pair_clearance(k, m, covered_above(v, step)), v));
        }
    }
    result.step = step;
    return result;
  }
};

ArmCollisionChecker::ArmCollisionChecker(const ArmProblem& problem)
    : ArmCollisionChecker(problem.arm, problem.obstacles, problem.points) {}

ArmCollisionChecker::ArmCollisionChecker(const Arm& arm, const std::vector<PolygonWithHoles>& obstacles,
                                         const std::vector<Eigen::Vector2d>& points)
    : impl_(std::make_unique<Impl>(arm, obstacles, points)) {}

ArmCollisionChecker::~ArmCollisionChecker() = default;
ArmCollisionChecker::ArmCollisionChecker(ArmCollisionChecker&&) noexcept = default;
ArmCollisionChecker& ArmCollisionChecker::operator=(ArmCollisionChecker&&) noexcept = default;

const Arm& ArmCollisionChecker::arm() const { return impl_->arm; }
bool ArmCollisionChecker::is_free(const JointAngles& angles) const { return !impl_->contact(angles); }
std::optional<ArmContact> ArmCollisionChecker::first_contact(const JointAngles& angles) const {
  return impl_->contact(angles);
}

void ArmCollisionChecker::clearances(const JointAngles& q, ArmClearances& out, double enough, ClearanceUse use) const {
  impl_->clearances(q, out, enough, use);
}

void ArmCollisionChecker::clearances(const JointAngles& q, std::vector<double>& out) const {
  ArmClearances& split = impl_->split;
  impl_->clearances(q, split, infinity, ClearanceUse::reading);
  out = split.links;
  const std::size_t n = out.size();
  if (!split.pairs.empty())
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t m = 0; m < n; ++m) out[k] = std::min(out[k], split.pairs[k * n + m]);
}

ArmSafeStep ArmCollisionChecker::safe_step(const JointAngles& q, std::span<const double> link_speed,
                                           std::span<const double> pair_speed, double horizon,
                                           std::span<const double> spread) const {
  return impl_->safe_step(q, link_speed, pair_speed, horizon, spread);
}

std::size_t ArmCollisionChecker::checks() const { return impl_->checks; }

std::optional<std::string> query_not_free(const ArmCollisionChecker& checker, const ArmQuery& query) {
  const std::size_t joints = checker.arm().joints();
  // A goal in the workspace has no configuration to test here: its goal set (arm/arm_goal_set.hpp)
  // holds only free configurations.
  const bool workspace = query.goal_point.has_value();
  if (workspace && !query.goal.empty())
    return "the query " + query.name + " has both goal angles and a goal point: its goal is one or the other";
  if (workspace && query.start.size() != joints)
    return "the query " + query.name + " has " + std::to_string(query.start.size()) + " start angles for an arm of " +
           std::to_string(joints) + " joints";
  if (!workspace && (query.start.size() != joints || query.goal.size() != joints))
    return "the query " + query.name + " has " + std::to_string(query.start.size()) + " start and " +
           std::to_string(query.goal.size()) + " goal angles for an arm of " + std::to_string(joints) + " joints";
  if (workspace && !(std::isfinite(query.goal_point->point.x()) && std::isfinite(query.goal_point->point.y()) &&
                     std::isfinite(query.goal_point->orientation.value_or(0))))
    return "the query " + query.name + "'s goal point (or orientation) is not a finite number";
  if (const auto contact = checker.first_contact(query.start)) return "the start collides: " + contact->describe();
  if (workspace) return std::nullopt;
  if (const auto contact = checker.first_contact(query.goal)) return "the goal collides: " + contact->describe();
  return std::nullopt;
}

}  // namespace polyplan
