#pragma once
// An independent check of a path of pieces (segments and arcs: PlanReport::pieces) in doubles,
// written apart from the planner's exact one: the pieces join the path's points in order, their
// lengths add up to the report's, an arc's ends lie on its circle, and points every 1/400 of each
// piece keep out of every disc, wall and polygon grown by the robot's radius (a polygon robot placed
// there overlaps none of them), up to 1e-9 (the doubles' own error); the start and goal are the query's. And the
// segment pieces as printed, their ends read as exact rationals, pass the exact check (`check`, the front door's
// checker): the planner prints a touching point outside its circle, never inside.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::test {

using XY = std::array<double, 2>;

inline double segment_distance(const XY& p, const XY& a, const XY& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

inline XY xy(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }

using Polygon = std::vector<std::vector<XY>>;  // rings

// The distance from p to the polygon's boundary, negative inside it.
inline double signed_distance(const XY& p, const Polygon& polygon) {
  double nearest = 1e300;
  bool inside = false;
  for (const std::vector<XY>& ring : polygon)
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const XY a = ring[k], b = ring[(k + 1) % ring.size()];
      nearest = std::min(nearest, segment_distance(p, a, b));
      if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
        inside = !inside;
    }
  return inside ? -nearest : nearest;
}

inline Polygon polygon_of(const PolygonWithHoles& polygon) {
  std::vector<Ring> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  Polygon out;
  for (const Ring& ring : rings) {
    std::vector<XY>& r = out.emplace_back();
    for (const ExactPoint& v : ring) r.push_back(xy(v));
  }
  return out;
}

// Points every 1/40 along the polygon's boundary (its vertices among them).
inline std::vector<XY> boundary_points(const Polygon& polygon) {
  std::vector<XY> out;
  for (const std::vector<XY>& ring : polygon)
    for (std::size_t k = 0; k < ring.size(); ++k)
      for (int s = 0; s < 40; ++s) {
        const XY a = ring[k], b = ring[(k + 1) % ring.size()];
        out.push_back({a[0] + s / 40.0 * (b[0] - a[0]), a[1] + s / 40.0 * (b[1] - a[1])});
      }
  return out;
}

// The world in doubles, read once: the robot's parts (or disc), the discs, the walls sampled every
// 1/200 of each piece, the polygons with their boundaries sampled every 1/40 of each edge.
struct WorldInDoubles {
  std::vector<Polygon> robot;
  double robot_radius = 0;
  std::vector<std::pair<XY, double>> discs;
  std::vector<std::pair<XY, XY>> wall_pieces;
  std::vector<XY> wall_points;
  std::vector<Polygon> obstacles;
  std::vector<std::vector<XY>> obstacle_points;
  std::vector<std::vector<XY>> robot_points;  // each part's boundary, sampled, at the origin

  explicit WorldInDoubles(const World& world) {
    for (const Ring& part : world.robot.parts) {
      std::vector<XY> placed;
      for (const ExactPoint& v : part) placed.push_back(xy(v));
      robot.push_back({placed});
      robot_points.push_back(boundary_points(robot.back()));
    }
    if (world.robot.disc) robot_radius = to_double(*world.robot.disc);
    for (const Disc& d : world.discs) discs.emplace_back(xy(d.center), to_double(d.radius));
    for (const Wall& w : world.walls)
      for (std::size_t k = 0; k + 1 < w.size(); ++k) {
        const XY a = xy(w[k]), b = xy(w[k + 1]);
        wall_pieces.emplace_back(a, b);
        for (int s = 0; s <= 200; ++s)
          wall_points.push_back({a[0] + s / 200.0 * (b[0] - a[0]), a[1] + s / 200.0 * (b[1] - a[1])});
      }
    for (const PolygonWithHoles& obstacle : world.obstacles) {
      obstacles.push_back(polygon_of(obstacle));
      obstacle_points.push_back(boundary_points(obstacles.back()));
    }
  }
};

// A polygon robot's parts placed with their reference point at p: how far the deepest disc, wall or
// polygon reaches into one (> 0: it overlaps), doubles; walls and polygons sampled along their
// edges, each polygon's boundary against the robot's and the robot's against it.
inline double polygon_robot_depth(const WorldInDoubles& world, const XY& p) {
  std::vector<Polygon> robot = world.robot;
  for (Polygon& part : robot)
    for (XY& v : part.front()) v = {v[0] + p[0], v[1] + p[1]};
  const auto into_robot = [&](const XY& q) {
    double d = 1e300;
    for (const Polygon& part : robot) d = std::min(d, signed_distance(q, part));
    return -d;
  };
  double worst = -1e300;
  for (const auto& [centre, radius] : world.discs) worst = std::max(worst, radius + into_robot(centre));
  for (const XY& q : world.wall_points) worst = std::max(worst, into_robot(q));
  for (std::size_t o = 0; o < world.obstacles.size(); ++o) {
    for (const XY& q : world.obstacle_points[o]) worst = std::max(worst, into_robot(q));
    for (const std::vector<XY>& part : world.robot_points)
      for (const XY& q : part)
        worst = std::max(worst, -signed_distance({q[0] + p[0], q[1] + p[1]}, world.obstacles[o]));
  }
  return worst;
}

// How far inside the nearest obstacle the robot at p is (> 0: inside), doubles.
inline double depth(const WorldInDoubles& world, const XY& p) {
  if (!world.robot.empty()) return polygon_robot_depth(world, p);
  const double r = world.robot_radius;
  double worst = -1e300;
  for (const auto& [centre, radius] : world.discs)
    worst = std::max(worst, radius + r - std::hypot(p[0] - centre[0], p[1] - centre[1]));
  for (const auto& [a, b] : world.wall_pieces) worst = std::max(worst, r - segment_distance(p, a, b));
  for (const Polygon& polygon : world.obstacles) worst = std::max(worst, r - signed_distance(p, polygon));
  return worst;
}

inline XY along(const PathPiece& piece, double t) {
  if (piece.kind == PathPiece::Kind::segment)
    return {piece.from[0] + t * (piece.to[0] - piece.from[0]), piece.from[1] + t * (piece.to[1] - piece.from[1])};
  const double a = std::atan2(piece.from[1] - piece.centre[1], piece.from[0] - piece.centre[0]);
  const double turn = piece.length / piece.radius * (piece.counter_clockwise ? 1 : -1);
  return {piece.centre[0] + piece.radius * std::cos(a + t * turn),
          piece.centre[1] + piece.radius * std::sin(a + t * turn)};
}

template <class Check>
void expect_valid_pieces(const World& world, const PlanReport<ExactPoint>& report, const Check& check) {
  const auto& pieces = report.pieces;
  ASSERT_EQ(report.path.size(), pieces.size() + 1);
  const WorldInDoubles doubles(world);
  double total = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const PathPiece& piece = pieces[k];
    SCOPED_TRACE("piece " + std::to_string(k));
    EXPECT_NEAR(piece.from[0], to_double(report.path[k].x), 1e-9);
    EXPECT_NEAR(piece.from[1], to_double(report.path[k].y), 1e-9);
    EXPECT_NEAR(piece.to[0], to_double(report.path[k + 1].x), 1e-9);
    EXPECT_NEAR(piece.to[1], to_double(report.path[k + 1].y), 1e-9);
    if (piece.kind == PathPiece::Kind::arc)
      for (const auto& end : {piece.from, piece.to})
        EXPECT_NEAR(std::hypot(end[0] - piece.centre[0], end[1] - piece.centre[1]), piece.radius, 1e-9);
    else EXPECT_NEAR(std::hypot(piece.to[0] - piece.from[0], piece.to[1] - piece.from[1]), piece.length, 1e-9);
    const XY end = along(piece, 1.0);
    EXPECT_NEAR(end[0], piece.to[0], 1e-9);
    EXPECT_NEAR(end[1], piece.to[1], 1e-9);
    for (int s = 0; s <= 400; ++s) EXPECT_LE(depth(doubles, along(piece, s / 400.0)), 1e-9);
    if (piece.kind == PathPiece::Kind::segment) {
      const auto exact = check(std::vector<ExactPoint>{report.path[k], report.path[k + 1]});
      EXPECT_TRUE(exact.valid) << exact.reason;
    }
    total += piece.length;
  }
  EXPECT_NEAR(total, report.length, 1e-9 * std::max(1.0, report.length));
}

}  // namespace polyplan::test
