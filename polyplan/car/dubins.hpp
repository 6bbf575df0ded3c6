#pragma once
// Dubins paths (L. E. Dubins 1957): the shortest forward-only path of a car turning with radius
// R between two poses is one of the six words LSL, RSR, LSR, RSL, RLR, LRL (Shkel and Lumelsky
// 2001 give each word's lengths in closed form).
#include <polyplan/car/steering_path.hpp>

#include <vector>

namespace polyplan {

// The shortest Dubins path from `from` to `to`. InputError for a radius that is not positive and
// finite or a pose that is not finite.
SteeringPath shortest_dubins_path(const CarPose& from, const CarPose& to, double radius);

// Its length, without making the path (what a planner's metric asks, many times).
double dubins_distance(const CarPose& from, const CarPose& to, double radius);

// Every word of the six that joins the poses, each with its lengths (the shortest among them is
// shortest_dubins_path).
std::vector<SteeringPath> dubins_paths(const CarPose& from, const CarPose& to, double radius);

// The shortest path and each of the six words in the order LSL, RSR, LSR, RSL, RLR, LRL, with its
// length or infeasible (LSR and RSL when their circles overlap, RLR and LRL when theirs lie more
// than 4 radii apart): what steer --all-words lists.
SteeringWords dubins_words(const CarPose& from, const CarPose& to, double radius);

}  // namespace polyplan
