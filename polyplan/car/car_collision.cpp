#include <polyplan/car/car_collision.hpp>

#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/turn_enclosure.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

// Why the enclosures hold the exact sweep although they are computed in doubles.
//
// The motion certified is the exact one: from the double pose (x, y, θ), the reference point
// drives the double length L along the exact straight or about the exact centre, with exact sines
// and cosines. Let S = max(|x|, |y|) + L + R + ρ (R the turning radius, ρ the largest distance
// of a body vertex from the reference point): every coordinate below is at most a few S. Each
// enclosure point (a body vertex turned and moved by the pose, the turning centre, a vertex
// turned about it by a double angle, a tangent apex: the same divided by cos(h) ≥ cos(22.5°) >
// 0.92) is at most a dozen correctly rounded operations (relative error 2⁻⁵³ each) and libm's sin
// and cos (glibc: within an ulp or two) on such numbers, and the body's rational vertices and the
// query's rational start are rounded to doubles once (2⁻⁵³ relative). Summed, no computed point is
// farther than 64·2⁻⁵³·S = 2⁻⁴⁷·S from the exact one. Each is replaced by the four corners of the
// square of half-width δ = 2⁻⁴⁰·S around it, rounded (by at most 2⁻⁵²·S): the square of half-width
// δ − 2⁻⁵²·S > 2⁻⁴⁷·S spanned by the rounded corners holds the exact point. So the hull of the
// corners holds the hull of the exact points, which holds the sweep (turn_enclosure.cpp's proof).
// The hull itself is exact: CGAL's predicates on doubles choose among the corners, constructing
// nothing.
constexpr double kMarginPerScale = 0x1.0p-40;
// Arcs are enclosed in pieces of at most 45 degrees (an apex then stands at most 8.3 % of the
// radius beyond its circle), and a piece whose enclosure hits is halved at most this many times.
constexpr double kLongestPiece = 0.7853981633974483;
constexpr int kMostHalvings = 10;

using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using FastPoint = Fast::Point_2;

struct Vec {
  double x, y;
};

struct Obstacle {
  std::string name;
  CGAL::Bbox_2 box;
  std::vector<detail::Point> outer;
  std::vector<std::vector<detail::Point>> holes;
  std::vector<detail::Segment> edges;
  std::vector<CGAL::Bbox_2> edge_boxes;
};

std::vector<detail::Point> points_of(const Ring& ring) {
  std::vector<detail::Point> out;
  for (const ExactPoint& p : ring) out.push_back(detail::to_point(p));
  return out;
}

void add_edges(Obstacle& o, const std::vector<detail::Point>& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    o.edges.emplace_back(ring[i], ring[(i + 1) % ring.size()]);
    o.edge_boxes.push_back(o.edges.back().bbox());
  }
}

// Closed: a point on the boundary is inside.
bool inside_obstacle(const detail::Point& p, const Obstacle& o) {
  if (CGAL::bounded_side_2(o.outer.begin(), o.outer.end(), p) == CGAL::ON_UNBOUNDED_SIDE) return false;
  for (const auto& hole : o.holes)
    if (CGAL::bounded_side_2(hole.begin(), hole.end(), p) == CGAL::ON_BOUNDED_SIDE) return false;
  return true;
}

// A convex polygon (counter-clockwise, at least three vertices) meets an obstacle (closed) when
// their boundaries cross, or else when one lies inside the other: a vertex of each tells.
bool hull_hits(const std::vector<detail::Point>& hull, const CGAL::Bbox_2& box, const Obstacle& o) {
  if (!CGAL::do_overlap(box, o.box)) return false;
  for (std::size_t e = 0; e < o.edges.size(); ++e) {
    if (!CGAL::do_overlap(box, o.edge_boxes[e])) continue;
    for (std::size_t i = 0; i < hull.size(); ++i)
      if (CGAL::do_intersect(detail::Segment(hull[i], hull[(i + 1) % hull.size()]), o.edges[e])) return true;
  }
  if (inside_obstacle(hull.front(), o)) return true;
  return CGAL::bounded_side_2(hull.begin(), hull.end(), o.outer.front()) != CGAL::ON_UNBOUNDED_SIDE;
}

}  // namespace

struct CarCollision::Impl {
  double radius = 1;
  bool reverse = false;
  bool holds_reference = false;
  double body_radius = 0;
  std::vector<std::vector<Vec>> pieces;  // convex, in the car frame
  std::vector<Obstacle> obstacles;
  std::optional<CGAL::Bbox_2> inside;  // the bounds, shrunk to doubles that lie within them
  mutable std::size_t enclosures = 0;

  // The pose's body pieces (world coordinates, doubles) and the margin for a motion of `length`.
  double margin(const CarPose& pose, double length) const {
    // No absolute term: a world drawn in units of 1e-60 gets margins of its own scale (S >= R > 0,
    // and 2^-40 S stays a normal double for every S the supported range allows).
    return kMarginPerScale * (std::max(std::abs(pose.x), std::abs(pose.y)) + length + radius + body_radius);
  }
  std::vector<Vec> placed(const std::vector<Vec>& piece, const CarPose& pose) const {
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    std::vector<Vec> out;
    for (const Vec& u : piece) out.push_back({pose.x + c * u.x - s * u.y, pose.y + s * u.x + c * u.y});
    return out;
  }

  // The name of what the hull of `points` grown by `margin` meets, or nullptr.
  const std::string* hull_blocked(const std::vector<Vec>& points, double margin) const {
    ++enclosures;
    std::vector<FastPoint> corners, hull;
    for (const Vec& p : points)
      for (const double dx : {-margin, margin})
        for (const double dy : {-margin, margin}) corners.emplace_back(p.x + dx, p.y + dy);
    CGAL::convex_hull_2(corners.begin(), corners.end(), std::back_inserter(hull));
    static const std::string bounds_word = "the bounds";
    CGAL::Bbox_2 box = hull.front().bbox();
    for (const FastPoint& p : hull) box += p.bbox();
    if (inside && !(inside->xmin() <= box.xmin() && box.xmax() <= inside->xmax() && inside->ymin() <= box.ymin() &&
                    box.ymax() <= inside->ymax()))
      return &bounds_word;
    std::vector<detail::Point> exact;
    for (const FastPoint& p : hull) exact.emplace_back(p.x(), p.y());
    for (const Obstacle& o : obstacles)
      if (hull_hits(exact, box, o)) return &o.name;
    return nullptr;
  }

  const std::string* pose_blocked(const CarPose& pose) const {
    const double m = margin(pose, 0);
    for (const auto& piece : pieces)
      if (const std::string* hit = hull_blocked(placed(piece, pose), m)) return hit;
    return nullptr;
  }

  bool straight_free(const CarPose& start, const SteeringSegment& segment) const {
    const CarPose end = drive(start, segment, radius, segment.length);
    const double m = margin(start, segment.length);
    for (const auto& piece : pieces) {
      std::vector<Vec> points = placed(piece, start), at_end = placed(piece, end);
      points.insert(points.end(), at_end.begin(), at_end.end());
      if (hull_blocked(points, m)) return false;
    }
    return true;
  }

  // The body's vertices relative to the turning centre `c` at the arc's start, turned through
  // [from, to] (radians, counter-clockwise, |to − from| ≤ 45°): the hull of their ends and apexes.
  bool arc_piece_free(const std::vector<std::vector<Vec>>& relative, Vec c, double from, double to, double m,
                      int halvings) const {
    const double mid = (from + to) / 2, stretch = 1 / std::cos((to - from) / 2);
    const auto turned = [&](const Vec& r, double angle, double scale) {
      const double co = std::cos(angle) * scale, si = std::sin(angle) * scale;
      return Vec{c.x + co * r.x - si * r.y, c.y + si * r.x + co * r.y};
    };
    bool free = true;
    for (const auto& piece : relative) {
      std::vector<Vec> points;
      for (const Vec& r : piece)
        points.insert(points.end(), {turned(r, from, 1), turned(r, to, 1), turned(r, mid, stretch)});
      if (hull_blocked(points, m)) {
        free = false;
        break;
      }
    }
    if (free) return true;
    if (halvings == kMostHalvings) return false;
    for (const auto& piece : relative) {  // the body itself at the middle: a hit there is a collision
      std::vector<Vec> points;
      for (const Vec& r : piece) points.push_back(turned(r, mid, 1));
      if (hull_blocked(points, m)) return false;
    }
    return arc_piece_free(relative, c, from, mid, m, halvings + 1) &&
           arc_piece_free(relative, c, mid, to, m, halvings + 1);
  }

  bool arc_free(const CarPose& start, const SteeringSegment& segment) const {
    const double side = segment.steer == Steer::left ? 1 : -1;
    const Vec c{start.x - side * radius * std::sin(start.theta), start.y + side * radius * std::cos(start.theta)};
    const double turn = side * segment.gear * segment.length / radius;  // counter-clockwise about c
    std::vector<std::vector<Vec>> relative;
    for (const auto& piece : pieces) {
      std::vector<Vec> r;
      for (const Vec& w : placed(piece, start)) r.push_back({w.x - c.x, w.y - c.y});
      relative.push_back(std::move(r));
    }
    const double m = margin(start, segment.length);
    const int count = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / kLongestPiece)));
    for (int k = 0; k < count; ++k)
      if (!arc_piece_free(relative, c, turn * k / count, turn * (k + 1) / count, m, 0)) return false;
    return true;
  }
};

CarCollision::CarCollision(const World& world) : impl_(std::make_unique<Impl>()) {
  if (!world.robot.car) throw std::invalid_argument("CarCollision: the world's robot is not a car");
  refuse_round_features(world, "a car's collision test");
  Impl& s = *impl_;
  s.radius = world.robot.car->turning_radius;
  s.reverse = world.robot.car->reverse;
  const std::vector<Ring> pieces =
      world.robot.is_point() ? std::vector<Ring>{{ExactPoint{0, 0}}} : convex_pieces(world.robot);
  const detail::Point origin(0, 0);
  for (const Ring& piece : pieces) {
    std::vector<Vec> vertices;
    for (const ExactPoint& p : piece) {
      vertices.push_back({to_double(p.x), to_double(p.y)});
      s.body_radius = std::max(s.body_radius, std::hypot(vertices.back().x, vertices.back().y));
    }
    s.pieces.push_back(std::move(vertices));
    const auto exact = points_of(piece);
    s.holds_reference |= exact.size() < 3
                             ? exact.front() == origin
                             : CGAL::bounded_side_2(exact.begin(), exact.end(), origin) != CGAL::ON_UNBOUNDED_SIDE;
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    Obstacle o;
    o.name = i < world.obstacle_names.size() ? world.obstacle_names[i] : "obstacles[" + std::to_string(i) + "]";
    o.outer = points_of(world.obstacles[i].outer);
    add_edges(o, o.outer);
    for (const Ring& hole : world.obstacles[i].holes) {
      o.holes.push_back(points_of(hole));
      add_edges(o, o.holes.back());
    }
    o.box = CGAL::bbox_2(o.outer.begin(), o.outer.end());
    s.obstacles.push_back(std::move(o));
  }
  if (const auto& b = world.bounds) {
    const auto up = [](const Rational& q) { return std::nextafter(to_double(q), HUGE_VAL); };
    const auto down = [](const Rational& q) { return std::nextafter(to_double(q), -HUGE_VAL); };
    s.inside = CGAL::Bbox_2(up(b->xmin), up(b->ymin), down(b->xmax), down(b->ymax));
  }
}

CarCollision::~CarCollision() = default;
CarCollision::CarCollision(CarCollision&&) noexcept = default;
CarCollision& CarCollision::operator=(CarCollision&&) noexcept = default;

double CarCollision::turning_radius() const { return impl_->radius; }
bool CarCollision::reverse() const { return impl_->reverse; }
bool CarCollision::body_holds_reference_point() const { return impl_->holds_reference; }
std::size_t CarCollision::enclosures_tested() const { return impl_->enclosures; }

// The segment's enclosure holds every exact point of the sweep grown by δ − 2⁻⁴⁷·S − 2⁻⁵²·S >
// 2⁻⁴¹·S (the analysis above); the computed `end` lies within 2⁻⁴⁷·S of the exact end. A body
// point moves by at most |Δ position| + ρ·|Δ heading| between `end` and `to`; up to 2⁻⁴³·S, with
// the end's own rounding, that stays within 2⁻⁴¹·S of the exact end pose's body: inside.
bool CarCollision::arrival_is_covered(const CarPose& start, const SteeringSegment& segment, const CarPose& end,
                                      const CarPose& to) const {
  const double room = std::ldexp(impl_->margin(start, segment.length), -3) * (1 - 1e-9);  // 2⁻⁴³·S, rounded down
  const double moved = std::hypot(to.x - end.x, to.y - end.y) +
                       impl_->body_radius * std::abs(std::remainder(to.theta - end.theta, 2 * pi));
  return moved * (1 + 1e-9) <= room;
}

bool CarCollision::pose_is_free(const CarPose& pose) const { return !impl_->pose_blocked(pose); }

std::optional<std::string> CarCollision::pose_blocked_by(const CarPose& pose) const {
  if (const std::string* hit = impl_->pose_blocked(pose)) return *hit;
  return std::nullopt;
}

bool CarCollision::segment_is_free(const CarPose& start, const SteeringSegment& segment) const {
  if (!std::isfinite(start.x) || !std::isfinite(start.y) || !std::isfinite(start.theta) ||
      !std::isfinite(segment.length) || segment.length < 0)
    return false;
  if (segment.length == 0) return pose_is_free(start);
  return segment.steer == Steer::straight ? impl_->straight_free(start, segment) : impl_->arc_free(start, segment);
}

}  // namespace polyplan
