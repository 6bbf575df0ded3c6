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

// The squared gap between two boxes (0 when they overlap), rounded as it may be.
double squared_gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, b.xmin - a.xmax, a.xmin - b.xmax});
  const double dy = std::max({0.0, b.ymin - a.ymax, a.ymin - b.ymax});
  return dx * dx + dy * dy;
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
    case 1:
      return s.v[0] == p;
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
  Box everything;  // of the kept obstacles and points
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
  struct NearEdge {
    double gap;  // squared, in the default rounding: only the order of the distances' work
    const Convex* edge;
    double rounding;  // its obstacle's
  };
  mutable std::vector<NearEdge> near_edges;
  mutable std::vector<const PointObstacle*> near_points;
  mutable ArmClearances split;
  mutable std::size_t checks = 0;

  Impl(const Arm& a, const std::vector<PolygonWithHoles>& polygons, const std::vector<Eigen::Vector2d>& point_list)
      : arm(a), true_arm(arm) {
    if (arm.links.empty()) throw std::invalid_argument("ArmCollisionChecker: the arm has no links");
    for (double l : arm.links)
      if (!(l > 0) || !std::isfinite(l)) throw std::invalid_argument("ArmCollisionChecker: a link length is not positive and finite");
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
      if (polygon.outer.size() < 3) throw std::invalid_argument("ArmCollisionChecker: an obstacle has fewer than 3 vertices");
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
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw std::invalid_argument("ArmCollisionChecker: a point is not finite");
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
      else
        corners[0] = joints[k], corners[1] = joints[k + 1];
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

  // The clearance of the true link k (after place_enclosed) to the obstacle polygons and points:
  // 0 when the computed link meets one (then `contact` is set unless it already holds one);
  // otherwise the smallest lower bound below `enough` or, when none is below it, a value of at
  // least `enough` (+infinity when nothing was measured).
  //  - First, rounding to nearest: contact, exactly, and the edges and points near enough to
  //    matter: those whose boxes reach into the link's box grown by enough + the radii (outward).
  //  - Then the distances of those, all at once with the processor rounding upward (switching the
  //    rounding costs more than a distance), skipping (cannot_matter) what lies apart from the
  //    link and at least the clearance still needed beyond its radius.
  double obstacle_clearance(std::size_t k, double enough, std::optional<ArmContact>& contact) const {
    const Convex& link = links[k];
    const double r = link_radius[k];
    const Box near = grown(link.box, above(above(enough + r) + everything_rounding));
    const auto met = [&](ArmContact c) {
      if (!contact) contact = c;
      return 0.0;
    };
    near_edges.clear();
    if (near.overlaps(everything))
      for (const Obstacle& o : obstacles) {
        if (!near.overlaps(o.box)) continue;
        if (link_meets(link, o)) return met({k, ArmContact::With::polygon, o.index});
        for (const Convex& e : o.edges)
          if (near.overlaps(e.box)) near_edges.push_back({squared_gap(link.box, e.box), &e, o.rounding});
      }
    near_points.clear();
    for (const PointObstacle& p : points) {
      if (!near.contains(p.p)) continue;
      if (link.box.contains(p.p) && contains(link, p.p)) return met({k, ArmContact::With::point, p.index});
      near_points.push_back(&p);
    }
    // Nearest boxes first: the clearance falls soonest, and the farther edges are skipped.
    std::sort(near_edges.begin(), near_edges.end(), [](const NearEdge& x, const NearEdge& y) { return x.gap < y.gap; });

    double best = infinity;
    const RoundingUpward upward;  // from here on only interval code: each sum below rounds up
    for (const auto& [gap, e, rounding] : near_edges) {
      // Apart from an obstacle's closed region, the link is nearest to its boundary: one of the edges.
      const double radius = r + rounding;
      if (cannot_matter(squared_gap_below(link.box, e->box), radius, std::min(best, enough))) continue;
      best = std::min(best, clearance_below(distance_apart_below(link, *e), radius));
    }
    for (const PointObstacle* p : near_points) {
      if (cannot_matter(squared_gap_below(link.box, p->box), r, std::min(best, enough))) continue;
      best = std::min(best, clearance_below(root_below(squared_distance_to_boundary_below(p->p, link)), r));
    }
    return best;
  }

  // The clearance between the true links k and m (self-collision, |k − m| ≥ 2), as
  // obstacle_clearance measures it: +infinity when it cannot be below `enough`, 0 when the
  // computed links meet (then `contact` is set unless it already holds one).
  double pair_clearance(std::size_t k, std::size_t m, double enough, std::optional<ArmContact>& contact) const {
    const Convex& a = links[k];
    const Convex& b = links[m];
    if (meets(a, b)) {
      if (!contact) contact = ArmContact{std::min(k, m), ArmContact::With::link, std::max(k, m)};
      return 0;
    }
    const RoundingUpward upward;
    const double radius = link_radius[k] + link_radius[m];
    if (cannot_matter(squared_gap_below(a.box, b.box), radius, enough)) return infinity;
    return clearance_below(distance_apart_below(a, b), radius);
  }

  void clearances(const JointAngles& q, ArmClearances& out, double enough) const {
    place_enclosed(q, {});
    const std::size_t n = arm.joints();
    out.links.assign(n, infinity);
    if (arm.self_collision) out.pairs.assign(n * n, infinity);
    else out.pairs.clear();
    out.contact.reset();
    // In first_contact's order, so that the first contact recorded is the one it reports.
    for (std::size_t k = 0; k < n; ++k) {
      out.links[k] = obstacle_clearance(k, enough, out.contact);
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m) out.pairs[k * n + m] = out.pairs[m * n + k] = pair_clearance(k, m, enough, out.contact);
    }
  }

  ArmSafeStep safe_step(const JointAngles& q, std::span<const double> link_speed, std::span<const double> pair_speed,
                        double horizon, std::span<const double> spread) const {
    const std::size_t n = arm.joints();
    if (link_speed.size() != n || pair_speed.size() != (arm.self_collision ? n * n : 0))
      throw std::invalid_argument("ArmCollisionChecker::safe_step: " + std::to_string(link_speed.size()) + " link speeds and " +
                                  std::to_string(pair_speed.size()) + " pair speeds for an arm of " + std::to_string(n) +
                                  " links" + (arm.self_collision ? " with" : " without") + " self-collision");
    const auto valid = [](double x) { return x >= 0 && std::isfinite(x); };
    if (!(horizon >= 0) || !std::all_of(link_speed.begin(), link_speed.end(), valid) ||
        !std::all_of(pair_speed.begin(), pair_speed.end(), valid))
      throw std::invalid_argument("ArmCollisionChecker::safe_step: speeds must be finite and not negative, the horizon not negative");
    place_enclosed(q, spread);
    using detail::covered_above;
    using detail::lasts_below;
    ArmSafeStep result;
    double step = horizon;
    // In first_contact's order, so that the contact reported is the one it reports. A clearance
    // above speed · step cannot lower the step: that is what "enough" tells the measurements.
    for (std::size_t k = 0; k < n; ++k) {
      const double c = obstacle_clearance(k, covered_above(link_speed[k], step), result.contact);
      if (result.contact) return result;
      step = std::min(step, lasts_below(c, link_speed[k]));
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m) {
          const double v = pair_speed[k * n + m];
          const double cm = pair_clearance(k, m, covered_above(v, step), result.contact);
          if (result.contact) return result;
          step = std::min(step, lasts_below(cm, v));
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
std::optional<ArmContact> ArmCollisionChecker::first_contact(const JointAngles& angles) const { return impl_->contact(angles); }

void ArmCollisionChecker::clearances(const JointAngles& q, ArmClearances& out, double enough) const {
  impl_->clearances(q, out, enough);
}

void ArmCollisionChecker::clearances(const JointAngles& q, std::vector<double>& out) const {
  ArmClearances& split = impl_->split;
  impl_->clearances(q, split, infinity);
  out = split.links;
  const std::size_t n = out.size();
  if (!split.pairs.empty())
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t m = 0; m < n; ++m) out[k] = std::min(out[k], split.pairs[k * n + m]);
}

ArmSafeStep ArmCollisionChecker::safe_step(const JointAngles& q, std::span<const double> link_speed,
                                           std::span<const double> pair_speed, double horizon, std::span<const double> spread) const {
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
