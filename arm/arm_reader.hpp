#pragma once
// Reading arm files (DESIGN.md "Arm file"):
//
//   {"links": [5, 5], "link_width": 0.5, "self_collision": false,
//    "obstacles": [ ...polygons, the same forms as a world file's... ],
//    "points": [[x, y], ...],
//    "start": [θ1, θ2], "goal": [θ1, θ2],
//    "queries": [{"name": "easy", "start": [...], "goal": [...]}, ...]}
//
// Angles are radians, any finite value (planners normalise them). `links` is required; every
// other field is optional. Obstacle polygons are read exactly and validated by the world reader
// (geometry/world_reader.hpp), so their messages are the world file's. Every problem throws
// InputError with one line "<file>: <object>: <what is wrong>".
#include "arm/angles.hpp"
#include "arm/arm.hpp"
#include "geometry/world.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace polyplan {

struct ArmQuery {
  std::string name;  // "start/goal" (the top-level pair), the query's "name", or "queries[2]"
  JointAngles start, goal;
};

struct ArmProblem {
  std::string source;  // the file read, for messages
  Arm arm;
  std::vector<PolygonWithHoles> obstacles;  // exact, validated and oriented as in World
  std::vector<std::string> obstacle_names;  // "obstacles[3]"
  std::vector<Eigen::Vector2d> points;      // point obstacles
  // The top-level start/goal first (if present), then `queries` in file order. Names are unique.
  std::vector<ArmQuery> queries;
};

// Reads and validates an arm file. Unknown fields are warnings: appended to `warnings` when it is
// given, otherwise printed to stderr as "warning: <file>: <object>: unknown field ... ignored".
ArmProblem read_arm_problem(const std::string& path, std::vector<std::string>* warnings = nullptr);

// The same from text already in memory; `name` stands for the file in messages.
ArmProblem parse_arm_problem(const std::string& text, const std::string& name,
                             std::vector<std::string>* warnings = nullptr);

}  // namespace polyplan
