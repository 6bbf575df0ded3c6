#pragma once
// Hybrid A* (Dolgov, Thrun, Montemerlo and Diebel 2010) for a steered car: an A* over continuous
// poses whose closed set is a grid of cells (`cell` wide) and heading bins (`headings` of them).
// Each expansion drives the motion primitives — an arc at full lock left and right and a straight,
// `step` long, forward and (a Reeds–Shepp car) backward — each certified (car/car_collision.hpp);
// a successor replaces the node of its bin when it is cheaper. Cost: length driven, reverse
// driving times `reverse-cost`, plus `switch-cost` per gear change. Heuristic: the larger of the
// steering curve's length ignoring obstacles and (when the reference point lies in the body) the
// shortest path of a point among the obstacles ignoring heading (car/holonomic_distance.hpp);
// both bound the cost from below. Analytic expansion: every `analytic-every` expansions the
// steering curve from the expanded pose to the goal is tried, and taken when it is certified free.
//
// Not complete (the grid may merge the poses a path needs): a search that empties its open list
// says not_found. Registered as `hybrid-astar` for the car space.
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>

namespace polyplan {

struct HybridAStarOptions {
  std::size_t headings = 72;
  double cell = 0;          // 0: a quarter of the turning radius
  double step = 0;          // 0: the larger of √2 cells and the arc that turns one heading bin
  double reverse_cost = 2;  // per unit driven backward (forward: 1); at least 1
  double switch_cost = -1;  // per gear change; negative: one turning radius
  std::size_t analytic_every = 1;
  double time = 10;                 // seconds per query
  std::size_t iterations = 500000;  // expansions per query
};

PlannerEntry<SteeredCar> hybrid_astar_planner_entry();

}  // namespace polyplan
