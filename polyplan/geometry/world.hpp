#pragma once
// The world a file describes: obstacles, bounds, robot, queries — all in exact numbers.
#include <polyplan/geometry/rational.hpp>

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
};

// A translating robot: its parts in the robot frame; the reference point is the origin.
// No parts means a point robot.
struct Robot {
  std::vector<Ring> parts;  // counter-clockwise once validated
  bool is_point() const { return parts.empty(); }
};

struct World {
  std::string source;  // the file it was read from, for messages
  std::optional<Bounds> bounds;
  std::vector<PolygonWithHoles> obstacles;
  std::vector<std::string> obstacle_names;  // "obstacles[3]" or "obstacles.wkt polygon 2", for messages
  Robot robot;
  // start/goal of the world, followed by its `queries`; empty when the file has none.
  std::vector<Query> queries;
};

// The starts and goals of the world's queries, then `more`: the points a frame around an
// unbounded free space must hold.
inline std::vector<ExactPoint> query_points(const World& world, std::vector<ExactPoint> more = {}) {
  for (const Query& q : world.queries) more.insert(more.end(), {q.start, q.goal});
  return more;
}

}  // namespace polyplan
