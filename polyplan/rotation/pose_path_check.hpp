#pragma once
// Whether a rotating robot's path is a free motion, each step as the rotation planner moves: a
// translation at one exact rotation (checked exactly in the C-space of the robot so turned) or a
// turn on the spot (proved free for every intermediate angle by the turn's enclosures,
// geometry/turn_enclosure.hpp, a turn of more than rotation_check_step degrees in steps of at
// most that). A step that moves and turns at once is not a motion the planner makes.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/world.hpp>

#include <string>
#include <vector>

namespace polyplan {

// A long turn is proved in parts no longer than this (degrees): an enclosure of a short turn is tight.
inline constexpr double rotation_check_step = 5;

PathCheck check_pose_path(const World& world, const std::vector<Pose>& path);

// A pose as a path gives it: (x, y, degrees), turned by the exact rotation the planner uses for
// that angle (exact_rotation), or (x, y, sin, cos) exactly. InputError beginning with `where` for
// another count of numbers, or a sin and cos that are not an exact rotation.
Pose pose_from_row(const std::vector<Rational>& row, const std::string& where);

}  // namespace polyplan
