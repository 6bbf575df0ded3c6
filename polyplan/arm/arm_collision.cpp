#include <polyplan/arm/arm_collision.hpp>

#include <polyplan/geometry/rational.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

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

struct Obstacle {
  std::size_t index = 0;  // in the problem's obstacles
  Box box;
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
  Point p;
  std::size_t index = 0;  // in the problem's points
};

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
  // Scratch for one check, kept to avoid allocating per call.
  mutable std::vector<Eigen::Vector2d> joints;
  mutable std::vector<Convex> links;
  mutable std::size_t checks = 0;

  Impl(const Arm& a, const std::vector<PolygonWithHoles>& polygons, const std::vector<Eigen::Vector2d>& point_list) : arm(a) {
    if (arm.links.empty()) throw std::invalid_argument("ArmCollisionChecker: the arm has no links");
    for (double l : arm.links)
      if (!(l > 0) || !std::isfinite(l)) throw std::invalid_argument("ArmCollisionChecker: a link length is not positive and finite");
    if (!(arm.link_width >= 0) || !std::isfinite(arm.link_width))
      throw std::invalid_argument("ArmCollisionChecker: the link width is negative or not finite");
    const double reach = arm.reach();
    if (!std::isfinite(reach)) throw std::invalid_argument("ArmCollisionChecker: the arm's length is not finite");
    // Whatever lies outside the disc of radius reach can never be touched. The box around it is
    // widened far beyond the rounding of the computed coordinates, so dropping is always safe.
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
      everything.add(o.box);
      obstacles.push_back(std::move(o));
    }
    for (std::size_t i = 0; i < point_list.size(); ++i) {
      const Eigen::Vector2d& p = point_list[i];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw std::invalid_argument("ArmCollisionChecker: a point is not finite");
      const Point q(p.x(), p.y());
      if (!reachable.contains(q)) continue;
      points.push_back({q, i});
      everything.add(q);
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

  std::optional<ArmContact> contact(const JointAngles& angles) const {
    joint_positions_into(arm, angles, joints);  // validates the angles
    ++checks;
    const std::size_t n = arm.joints();
    links.resize(n);
    for (std::size_t k = 0; k < n; ++k) shape_link(k, links[k]);
    for (std::size_t k = 0; k < n; ++k) {
      const Convex& link = links[k];
      if (link.box.overlaps(everything)) {
        for (const Obstacle& o : obstacles)
          if (link_meets(link, o)) return ArmContact{k, ArmContact::With::polygon, o.index};
        for (const PointObstacle& p : points)
          if (link.box.contains(p.p) && contains(link, p.p)) return ArmContact{k, ArmContact::With::point, p.index};
      }
      if (arm.self_collision)
        for (std::size_t j = k + 2; j < n; ++j)
          if (meets(link, links[j])) return ArmContact{k, ArmContact::With::link, j};
    }
    return std::nullopt;
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
std::size_t ArmCollisionChecker::checks() const { return impl_->checks; }

}  // namespace polyplan
