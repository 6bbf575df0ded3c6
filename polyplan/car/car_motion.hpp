#pragma once
// A car's motion between two poses, the one every car planner drives: the shortest curve ignoring
// obstacles (Reeds–Shepp when the car may reverse, Dubins otherwise), and the states along it when
// each of its segments is certified free (car/car_collision.hpp).
#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/steering_path.hpp>
#include <polyplan/geometry/world.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace polyplan {

// The shortest curve from → to of a car that turns with `steering.turning_radius` and reverses
// when `steering.reverse`, and its length.
SteeringPath shortest_car_path(const CarSteering& steering, const CarPose& from, const CarPose& to);
double car_distance(const CarSteering& steering, const CarPose& from, const CarPose& to);

// The states along `path` driven from `from` turning with `radius`, one per segment, the last one
// at `to` (its position exactly, its heading as the car turned, so that headings along a path read
// continuously).
std::vector<CarState> states_along(const CarPose& from, const SteeringPath& path, const CarPose& to, double radius);
// Those states when every segment is certified free; nullopt otherwise.
std::optional<std::vector<CarState>> certified_states(const CarCollision& car, const CarPose& from,
                                                      const SteeringPath& path, const CarPose& to);

// How often a path of states changes gear (segments of no length do not count).
std::size_t gear_changes(const std::vector<CarState>& path);

// Whether a pose reached by driving (`end`) stands for `at`: equal to the rounding of the curves'
// arithmetic (their ends reach the goal to 1e-9 relative), in lengths (heading errors times the radius).
bool arrives(const CarPose& end, const CarPose& at, double radius);

}  // namespace polyplan
