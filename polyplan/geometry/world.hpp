#pragma once
// The world a file describes: obstacles, bounds, robot, queries — all in exact numbers.
#include <polyplan/geometry/rational.hpp>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {

// A closed polygon's vertices, without repeating the first one at the end.
using Ring = std::vector<ExactPoint>;

struct PolygonWithHoles {
  Ring outer;               // counter-clockwise once validated
  std::vector<Ring> holes;  // clockwise once validated
};

struct Bounds {
  Rational xmin, ymin, xmax, ymax;
};

struct Query {
  ExactPoint start, goal;
  std::string name;  // "start/goal" or "queries[2]", for messages
  // A rotating robot's orientation at the start and at the goal, in degrees counter-clockwise
  // (the file's [x, y, theta]); none for [x, y]: the robot as its parts are written, 0 degrees.
  // Translating planners plan for the robot at 0 degrees (cli: a theta other than 0 needs
  // --planner rotation).
  std::optional<double> start_theta = std::nullopt, goal_theta = std::nullopt;
};

// A translating robot: its parts in the robot frame; the reference point is the origin.
// No parts means a point robot.
// A robot that steers like a car ("robot": {"parts": [...], "car": {...}}): its parts are the body
// in the car's frame, whose origin is the reference point (the rear-axle centre) and whose +x the
// heading; it drives arcs of `turning_radius` and straights, forward, and backward too when
// `reverse` (a Reeds–Shepp car; otherwise a Dubins car).
struct CarSteering {
  double turning_radius = 1;
  bool reverse = false;
};

struct Robot {
  std::vector<Ring> parts;  // counter-clockwise once validated
  std::optional<CarSteering> car;
  bool is_point() const { return parts.empty(); }
};

// A change of the world while a robot drives (the file's "changes"; read by the replanning
// planners, dstar-lite and its kin): once the robot has made `after_moves` moves, an obstacle
// appears (`added`) or one disappears (`removed`: its number among the world's obstacles, then
// those added by earlier changes, in order). Changes are listed by after_moves, never decreasing.
struct WorldChange {
  std::size_t after_moves = 0;
  std::optional<PolygonWithHoles> added;
  std::optional<std::size_t> removed;
  std::string name;  // "changes[2]", for messages
};

struct World {
  std::string source;  // the file it was read from, for messages
  std::optional<Bounds> bounds;
  std::vector<PolygonWithHoles> obstacles;
  std::vector<std::string> obstacle_names;  // "obstacles[3]" or "obstacles.wkt polygon 2", for messages
  Robot robot;
  // start/goal of the world, followed by its `queries`; empty when the file has none.
  std::vector<Query> queries;
  std::vector<WorldChange> changes;  // empty: the world stays as it is
};

// The starts and goals of the world's queries, then `more`: the points a frame around an
// unbounded free space must hold.
inline std::vector<ExactPoint> query_points(const World& world, std::vector<ExactPoint> more = {}) {
  for (const Query& q : world.queries) more.insert(more.end(), {q.start, q.goal});
  return more;
}

// Whether an orientation is other than 0 degrees (modulo 360), and whether a query of the world
// gives one: only the rotation planner answers such a world.
inline bool turned(const std::optional<double>& theta) { return theta && std::fmod(*theta, 360.0) != 0; }

inline bool turns_the_robot(const World& world) {
  for (const Query& q : world.queries)
    if (turned(q.start_theta) || turned(q.goal_theta)) return true;
  return false;
}

}  // namespace polyplan
