#pragma once
// Whether a car's path (its segments, each driven from its start pose) is a motion of the car and
// free: `polyplan check` on a car's world. The car moves only along arcs of its turning radius
// and straights in its heading's direction, so each segment must start where the one before it
// ends (the car neither jumps nor slides sideways), reverse only when the car may, and sweep a
// body that car/car_collision.hpp proves free. A motion too near an obstacle to prove is not
// valid: polyplan never accepts contact it cannot prove free.
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/world.hpp>

#include <vector>

namespace polyplan {

// std::invalid_argument when the world's robot is not a car.
PathCheck check_car_path(const World& world, const std::vector<CarPathSegment>& path);

// The segments a car drove through `poses` (its planner's path: a pose at each segment's end):
// between each two, the shortest straight or arc of `radius`, in either gear, whose end arrives at
// the next pose (car_motion.hpp's arrives). InputError naming the pair that no one segment joins.
std::vector<CarPathSegment> car_segments_through(const std::vector<CarPose>& poses, double radius);

}  // namespace polyplan
