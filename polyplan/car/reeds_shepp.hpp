#pragma once
// Reeds–Shepp paths (J. A. Reeds and L. A. Shepp 1990): the shortest path of a car turning with
// radius R that may reverse is one of 48 words in five families (CSC, CCC, CCCC, CCSC, CCSCC),
// each family's base formulas (8.1–8.11 of the paper) applied to the goal as given, time-flipped,
// reflected, and both.
#include <polyplan/car/steering_path.hpp>

#include <vector>

namespace polyplan {

// The shortest Reeds–Shepp path from `from` to `to`. InputError as for shortest_dubins_path.
SteeringPath shortest_reeds_shepp_path(const CarPose& from, const CarPose& to, double radius);

// Its length, without making the path.
double reeds_shepp_distance(const CarPose& from, const CarPose& to, double radius);

// Every word of the 44 formula applications that joins the poses, with its lengths (the shortest among
// them is shortest_reeds_shepp_path).
std::vector<SteeringPath> reeds_shepp_paths(const CarPose& from, const CarPose& to, double radius);

// The shortest path and each of the 44 formula applications tried for it (each of the five
// families' base formulas under its symmetries, in the order csc, ccc, cccc, ccsc, ccscc), named
// by their letters and the gears the formula fixes ("L+S+L+", "L+R-L": the last arc either way),
// with its length or infeasible: what steer --all-words lists.
SteeringWords reeds_shepp_words(const CarPose& from, const CarPose& to, double radius);

}  // namespace polyplan
