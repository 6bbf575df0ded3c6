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

// A closed disc: an obstacle, the bounds of a sphere world (the free space is inside it), or
// (its radius alone) a disc robot.
struct Disc {
  ExactPoint center;
  Rational radius;  // > 0 once validated
};

// A wall of zero thickness: a polyline a robot may touch but never cross.
using Wall = std::vector<ExactPoint>;

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

// A disc robot ("robot": {"disc": r}) has no parts and its radius in `disc`: not a point.
struct Robot {
  std::vector<Ring> parts;  // counter-clockwise once validated
  std::optional<CarSteering> car;
  std::optional<Rational> disc;  // a disc robot's radius, > 0 once validated
  bool is_point() const { return parts.empty() && !disc; }
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
  // Round things and thin walls (docs/design.md "World file"): disc obstacles, walls of zero
  // thickness, and bounds that are a disc rather than `bounds`' box (at most one of the two).
  std::vector<Disc> discs;
  std::vector<Wall> walls;
  std::optional<Disc> disc_bounds;
};

// What the world holds beyond polygons and a polygon or point robot, in the file's words
// ("discs", "walls", "disc bounds", "a disc robot"); empty for a polygon world. A planner or a
// command that plans over polygons only refuses a world for which this is not empty, naming them.
std::vector<std::string> round_features(const World& world);
// The same as messages name them: "discs, walls, a disc robot" (empty for a polygon world).
std::string round_features_text(const World& world);

// InputError "<source>: discs, walls: <who> holds polygons and a polygon or point robot only ..."
// when the world has round features: for code built on polygons alone (the C-space, a car's
// collision test), so that nothing plans straight through them.
void refuse_round_features(const World& world, const std::string& who);

// InputError "<source>: <object>: <problem>" for a radius that is not > 0, a wall without two
// distinct points (repeated consecutive points are dropped), box and disc bounds together, or a
// disc robot with parts or a car. validate_world (geometry/world_validation.hpp) calls it.
void check_round_features(World& world);

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
