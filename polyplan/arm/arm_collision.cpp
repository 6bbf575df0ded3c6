#include <polyplan/arm/arm_collision.hpp>

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

// The squared distance between two boxes (0 when they overlap), as computed in doubles. Used
// only to skip what cannot matter, always after subtracting the safety margin (see
// safety_margin); squared, because that test runs for every obstacle near every link.
double squared_gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, b.xmin - a.xmax, a.xmin - b.xmax});
  const double dy = std::max({0.0, b.ymin - a.ymax, a.ymin - b.ymax});
  return dx * dx + dy * dy;
}

// The safety margin subtracted from every double-computed distance, for shapes whose coordinates
// are at most `extent` in absolute value, on an arm of n links and the given reach:
// 1e-12 · max(1, (n/10)²) · (reach + 1 + extent). What it absorbs, in units u = 2^-53 ≈ 1.1e-16:
//  - the distance formulas below: a few u times the coordinates involved;
//  - the kinematic coordinates against the true arm at the same angles: the heading of link k is
//    a sum of k angles in [0, 2π) (up to 2πk, rounded k times), so a link turns by up to
//    n · 2πn · u, which moves it by up to that times the reach (7e-14 · reach for n = 10, growing
//    as n², hence the factor); cos, sin and the sums of link vectors add a few u · reach;
//  - the interpolated angles of a motion (each rounded by about 2 · 2π · u, so the headings by up
//    to n times that: 1.4e-14 · reach for n = 10) and the rounding of its step sizes, a few u · reach.
// Together about 1e-13 · reach for n = 10: the margin is 10 times that, and still far below any
// clearance worth planning with.
double safety_margin(std::size_t links, double reach, double extent) {
  const double n = static_cast<double>(links);
  return 1e-12 * std::max(1.0, n * n / 100) * (reach + 1 + extent);
}

// A clearance: the computed distance minus the margin, never below 0.
double clearance_of(double distance, double margin) { return std::max(0.0, distance - margin); }

// Whether something whose box lies `squared_box_gap` (squared) from the link's can be skipped:
// it lies apart from the link (box gap − margin > 0, so it cannot meet it) and cannot bring the
// clearance below `enough` (box gap − margin ≥ enough).
bool cannot_matter(double squared_box_gap, double margin, double enough) {
  const double reach = enough + margin;
  return squared_box_gap > margin * margin && squared_box_gap >= reach * reach;
}

// The squared distance from p to the segment ab (a == b allowed), in doubles. Clamping the
// projection keeps the nearest point on the segment, so rounding moves the result by a few ulps of
// the coordinates only (see safety_margin). Squared: the square root is taken once, of the
// smallest (sqrt is monotone and correctly rounded, so that is the smallest distance).
double squared_point_segment_distance(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y();
  const double wx = p.x() - a.x(), wy = p.y() - a.y();
  const double vv = vx * vx + vy * vy;
  const double t = vv > 0 ? std::clamp((wx * vx + wy * vy) / vv, 0.0, 1.0) : 0.0;
  const double dx = wx - t * vx, dy = wy - t * vy;
  return dx * dx + dy * dy;
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

// The squared distance from p to the boundary of s, which is its distance to s when p lies outside s.
double squared_distance_to_boundary(const Point& p, const Convex& s) {
  if (s.n == 1) return squared_point_segment_distance(p, s.v[0], s.v[0]);
  double best = infinity;
  for (int i = 0; i < edge_count(s); ++i) best = std::min(best, squared_point_segment_distance(p, s.v[i], s.v[(i + 1) % s.n]));
  return best;
}
double distance_to_boundary(const Point& p, const Convex& s) { return std::sqrt(squared_distance_to_boundary(p, s)); }

// The distance between two closed convex shapes that do not meet: the nearest pair of points of
// two disjoint convex polygons (or segments, or points) always has a vertex of one of them.
double distance_apart(const Convex& a, const Convex& b) {
  double best = infinity;
  for (int i = 0; i < a.n; ++i) best = std::min(best, squared_distance_to_boundary(a.v[i], b));
  for (int i = 0; i < b.n; ++i) best = std::min(best, squared_distance_to_boundary(b.v[i], a));
  return std::sqrt(best);
}

struct Obstacle {
  std::size_t index = 0;  // in the problem's obstacles
  Box box;
  double margin = 0;  // safety_margin for its coordinates
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
  Box box;                // p alone
  double margin = 0;      // safety_margin for its coordinates
};

double largest_coordinate(const Box& b) { return std::max({std::fabs(b.xmin), std::fabs(b.xmax), std::fabs(b.ymin), std::fabs(b.ymax)}); }

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
  double everything_margin = 0;  // the largest margin of the kept obstacles and points
  double link_pair_margin = 0;   // safety_margin between two links
  // Scratch for one check, kept to avoid allocating per call.
  mutable std::vector<Eigen::Vector2d> joints;
  mutable std::vector<Convex> links;
  mutable ArmClearances split;
  mutable std::size_t checks = 0;

  Impl(const Arm& a, const std::vector<PolygonWithHoles>& polygons, const std::vector<Eigen::Vector2d>& point_list) : arm(a) {
    if (arm.links.empty()) throw std::invalid_argument("ArmCollisionChecker: the arm has no links");
    for (double l : arm.links)
      if (!(l > 0) || !std::isfinite(l)) throw std::invalid_argument("ArmCollisionChecker: a link length is not positive and finite");
    if (!(arm.link_width >= 0) || !std::isfinite(arm.link_width))
      throw std::invalid_argument("ArmCollisionChecker: the link width is negative or not finite");
    const double reach = arm.reach();
    if (!std::isfinite(reach)) throw std::invalid_argument("ArmCollisionChecker: the arm's length is not finite");
    link_pair_margin = safety_margin(arm.joints(), reach, reach);
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
      Box every_vertex = o.box;  // holes too, should one stray outside the outer boundary
      for (const Ring& hole : polygon.holes) {
        o.holes.push_back(to_points(hole));
        add_edges(o.holes.back(), o.edges);
        for (const Point& p : o.holes.back()) every_vertex.add(p);
      }
      o.margin = safety_margin(arm.joints(), reach, largest_coordinate(every_vertex));
      everything.add(o.box);
      everything_margin = std::max(everything_margin, o.margin);
      obstacles.push_back(std::move(o));
    }
    for (std::size_t i = 0; i < point_list.size(); ++i) {
      const Eigen::Vector2d& p = point_list[i];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw std::invalid_argument("ArmCollisionChecker: a point is not finite");
      const Point q(p.x(), p.y());
      if (!reachable.contains(q)) continue;
      PointObstacle kept{q, i, {}, 0};
      kept.box.add(q);
      kept.margin = safety_margin(arm.joints(), reach, largest_coordinate(kept.box));
      everything.add(q);
      everything_margin = std::max(everything_margin, kept.margin);
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

  std::optional<ArmContact> contact(const JointAngles& angles) const {
    place(angles);
    const std::size_t n = arm.joints();
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

  // The clearance of the placed links[k] to the obstacle polygons and points: the smallest one
  // below `enough` or, when none is below it, a value of at least `enough` (+infinity when nothing
  // was measured). What cannot matter (cannot_matter) is skipped, which never skips anything the
  // link may meet: meeting is decided exactly for every obstacle whose box overlaps the link's.
  // The first obstacle or point met, in first_contact's order, goes into `contact` unless it already
  // holds one; with stop_at_contact the search ends there.
  double obstacle_clearance(std::size_t k, double enough, bool stop_at_contact, std::optional<ArmContact>& contact) const {
    const Convex& link = links[k];
    double best = infinity;
    if (cannot_matter(squared_gap(link.box, everything), everything_margin, enough)) return best;
    const auto found = [&](ArmContact c) {
      if (!contact) contact = c;
      best = 0;
      return stop_at_contact;
    };
    for (const Obstacle& o : obstacles) {
      if (cannot_matter(squared_gap(link.box, o.box), o.margin, std::min(best, enough))) continue;
      if (link_meets(link, o)) {
        if (found({k, ArmContact::With::polygon, o.index})) return best;
        continue;
      }
      // Apart from the closed region, the link is nearest to its boundary: one of the edges.
      for (const Convex& e : o.edges) {
        if (best == 0) break;
        if (cannot_matter(squared_gap(link.box, e.box), o.margin, std::min(best, enough))) continue;
        best = std::min(best, clearance_of(distance_apart(link, e), o.margin));
      }
    }
    for (const PointObstacle& p : points) {
      if (cannot_matter(squared_gap(link.box, p.box), p.margin, std::min(best, enough))) continue;
      if (contains(link, p.p)) {
        if (found({k, ArmContact::With::point, p.index})) return best;
        continue;
      }
      best = std::min(best, clearance_of(distance_to_boundary(p.p, link), p.margin));
    }
    return best;
  }

  // The clearance between the placed links[k] and links[m] (self-collision, |k − m| ≥ 2), as
  // obstacle_clearance measures it: +infinity when it cannot be below `enough`, 0 when they meet
  // (then `contact` is set unless it already holds one).
  double pair_clearance(std::size_t k, std::size_t m, double enough, std::optional<ArmContact>& contact) const {
    const Convex& a = links[k];
    const Convex& b = links[m];
    if (cannot_matter(squared_gap(a.box, b.box), link_pair_margin, enough)) return infinity;
    if (meets(a, b)) {
      if (!contact) contact = ArmContact{std::min(k, m), ArmContact::With::link, std::max(k, m)};
      return 0;
    }
    return clearance_of(distance_apart(a, b), link_pair_margin);
  }

  void clearances(const JointAngles& q, ArmClearances& out, double enough) const {
    place(q);
    const std::size_t n = arm.joints();
    out.links.assign(n, infinity);
    if (arm.self_collision) out.pairs.assign(n * n, infinity);
    else out.pairs.clear();
    out.contact.reset();
    // In first_contact's order, so that the first contact recorded is the one it reports.
    for (std::size_t k = 0; k < n; ++k) {
      out.links[k] = obstacle_clearance(k, enough, false, out.contact);
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m) out.pairs[k * n + m] = out.pairs[m * n + k] = pair_clearance(k, m, enough, out.contact);
    }
  }

  ArmSafeStep safe_step(const JointAngles& q, std::span<const double> link_speed, std::span<const double> pair_speed,
                        double horizon) const {
    const std::size_t n = arm.joints();
    if (link_speed.size() != n || pair_speed.size() != (arm.self_collision ? n * n : 0))
      throw std::invalid_argument("ArmCollisionChecker::safe_step: " + std::to_string(link_speed.size()) + " link speeds and " +
                                  std::to_string(pair_speed.size()) + " pair speeds for an arm of " + std::to_string(n) +
                                  " links" + (arm.self_collision ? " with" : " without") + " self-collision");
    const auto valid = [](double x) { return x >= 0 && std::isfinite(x); };
    if (!(horizon >= 0) || !std::all_of(link_speed.begin(), link_speed.end(), valid) ||
        !std::all_of(pair_speed.begin(), pair_speed.end(), valid))
      throw std::invalid_argument("ArmCollisionChecker::safe_step: speeds must be finite and not negative, the horizon not negative");
    place(q);
    // How long a clearance c lasts at speed v: c / v, forever for a positive c that does not move,
    // and not at all for c = 0 (which may be a contact within the margin).
    const auto lasts = [](double c, double v) { return c == 0 ? 0.0 : v > 0 ? c / v : infinity; };
    // The distance covered at speed v in the time `step` (0 · ∞ would be NaN for an endless horizon).
    const auto covered = [](double v, double step) { return v > 0 ? v * step : 0.0; };
    ArmSafeStep result;
    double step = horizon;
    // In first_contact's order, so that the contact reported is the one it reports. A clearance
    // above speed · step cannot lower the step: that is what "enough" tells the measurements.
    for (std::size_t k = 0; k < n; ++k) {
      const double c = obstacle_clearance(k, covered(link_speed[k], step), true, result.contact);
      if (result.contact) return result;
      step = std::min(step, lasts(c, link_speed[k]));
      if (arm.self_collision)
        for (std::size_t m = k + 2; m < n; ++m) {
          const double v = pair_speed[k * n + m];
          const double cm = pair_clearance(k, m, covered(v, step), result.contact);
          if (result.contact) return result;
          step = std::min(step, lasts(cm, v));
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
                                           std::span<const double> pair_speed, double horizon) const {
  return impl_->safe_step(q, link_speed, pair_speed, horizon);
}

std::size_t ArmCollisionChecker::checks() const { return impl_->checks; }

std::optional<std::string> query_not_free(const ArmCollisionChecker& checker, const ArmQuery& query) {
  const std::size_t joints = checker.arm().joints();
  if (query.start.size() != joints || query.goal.size() != joints)
    return "the query " + query.name + " has " + std::to_string(query.start.size()) + " start and " +
           std::to_string(query.goal.size()) + " goal angles for an arm of " + std::to_string(joints) + " joints";
  for (const auto* end : {&query.start, &query.goal})
    if (const auto contact = checker.first_contact(*end))
      return std::string(end == &query.start ? "the start" : "the goal") + " collides: " + contact->describe();
  return std::nullopt;
}

}  // namespace polyplan
