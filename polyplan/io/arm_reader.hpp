#pragma once
// Reading arm files (docs/design.md "Arm file"):
//
//   {"links": [5, 5], "link_width": 0.5, "self_collision": false,
//    "limits": [[lo, hi], [lo, hi]],
//    "obstacles": [ ...polygons, the same forms as a world file's... ],
//    "points": [[x, y], ...],
//    "start": [θ1, θ2], "goal": [θ1, θ2],
//    "queries": [{"name": "easy", "start": [...], "goal": [...]},
//                {"name": "reach", "start": [...], "goal_point": [x, y], "goal_orientation": φ}, ...]}
//
// Angles are radians, any finite value (planners normalise them). `links` is required; every
// other field is optional. A query's goal is either joint angles (`goal`) or a point for the end
// effector (`goal_point` [x, y]; with `goal_orientation`, the last link's absolute angle there,
// θ1 + … + θn, in radians), never both: the planners then plan to the collision-free inverse-kinematics
// solutions (arm/arm_goal_set.hpp). `limits` gives each joint's [lo, hi] in radians, lo <= hi (read
// round the circle), which inverse kinematics keeps to. Obstacle polygons are read exactly and validated by the world
// reader (io/world_reader.hpp), so their messages are the world file's. Every problem throws InputError with one line
// "<file>: <object>: <what is wrong>".
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
