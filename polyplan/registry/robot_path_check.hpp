#pragma once
// Whether a path file is a valid motion of a problem's robot, each robot by its own motion model:
// `polyplan check PROBLEM PATH`. A translating robot's path is a polyline ({"path": [[x, y], ...]}),
// checked exactly in its C-space (geometry/path_check.hpp); a rotating robot's, poses ([x, y,
// degrees] or [x, y, sin, cos]) each step a translation or a turn on the spot
// (rotation/pose_path_check.hpp); a car's, its segments ({"segments": [...]}, as plan --json writes
// them) checked by the car's model (car/car_path_check.hpp), a polyline would let the car slide
// sideways; an arm's, joint angles, each motion certified (arm/arm_path_check.hpp).
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/registry/problem.hpp>

#include <string>

namespace polyplan {

// InputError for a bad path file, or a path of a family this build is without.
PathCheck check_path_file(const Problem& problem, const std::string& path_file);

// A translating robot's polyline in a world: in its C-space, or exactly among its discs and walls
// for a point or disc robot (geometry/round_world_check.hpp).
PathCheck check_translating_path(const Problem& problem, const std::vector<ExactPoint>& points);

}  // namespace polyplan
