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
// (io/world_reader.hpp), so their messages are the world file's. Every problem throws
// InputError with one line "<file>: <object>: <what is wrong>".
#include <polyplan/geometry/arm_problem.hpp>

#include <string>
#include <vector>

namespace polyplan {

// Reads and validates an arm file. Unknown fields are warnings: appended to `warnings` when it is
// given, otherwise printed to stderr as "warning: <file>: <object>: unknown field ... ignored".
ArmProblem read_arm_problem(const std::string& path, std::vector<std::string>* warnings = nullptr);

// The same from text already in memory; `name` stands for the file in messages.
ArmProblem parse_arm_problem(const std::string& text, const std::string& name,
                             std::vector<std::string>* warnings = nullptr);

}  // namespace polyplan
