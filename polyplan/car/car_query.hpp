#pragma once
// A car query as the car's planners read it: its start and goal poses, whether they can be planned
// (the body free at both, in one sentence naming what it meets), and the box poses are drawn from.
#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/holonomic_distance.hpp>
#include <polyplan/geometry/world.hpp>

#include <optional>
#include <string>

namespace polyplan {

// The pose of a query's start or goal: its position rounded to doubles, its theta in radians.
CarPose start_pose(const Query& query);
CarPose goal_pose(const Query& query);

// "[1.5, 2, 90°]": a car pose as messages name it.
std::string to_string(const CarPose& pose);

// "the start [3, 0, 0°] is not free: the car's body meets obstacles[0]" when the start or goal
// is blocked; nullopt when both are free.
std::optional<std::string> car_query_not_free(const CarCollision& car, const Query& query);

// Why no motion of the car joins the query's start and goal, when `holonomic` (built when the
// car's body holds its reference point, car/holonomic_distance.hpp) proves it: start and goal in
// different components of the reference point's free space. nullopt otherwise.
std::optional<std::string> car_query_unreachable(const HolonomicDistance* holonomic, const Query& query);

// Where a car's sampling planners draw positions: the bounds, or the box of the obstacles and
// the queries grown by a tenth of its diagonal (plus one) on every side.
struct CarSamplingBox {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};
CarSamplingBox car_sampling_box(const World& world);

}  // namespace polyplan
