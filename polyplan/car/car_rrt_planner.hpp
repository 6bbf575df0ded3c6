#pragma once
// The course's arm and car planning report's RRT with controls for a steered car: a tree from the start; each iteration
// draws a pose (the goal with probability `goal-bias`), finds the tree's nearest node by the steering curve's length
// (Reeds–Shepp or Dubins: the car's own distance), and applies every control — forward and (a Reeds–Shepp car)
// backward, each at full lock left, straight and at full lock right — for a duration `dt` at unit speed; the certified
// one that ends nearest the sample joins the tree. A new node whose steering curve to the goal is at most 4 turning
// radii long tries that curve, and ends the search at the goal exactly when it is certified free; a node within
// `goal-tolerance` of the goal (position, and heading times the turning radius) ends it there
// (fact goal_miss: how far from the goal the path ends).
// Registered as `car-rrt` for the car space.
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <cstdint>

namespace polyplan {

struct CarRrtOptions {
  double dt = 0;  // length of one control (unit speed); 0: a third of the turning radius
  double goal_bias = 0.05;
  double goal_tolerance = -1;  // negative: a tenth of the turning radius
  std::uint64_t seed = 1;
  double time = 10;
  std::size_t iterations = 100000;
};

PlannerEntry<SteeredCar> car_rrt_planner_entry();

}  // namespace polyplan
