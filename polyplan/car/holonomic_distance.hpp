#pragma once
// A lower bound on a car's path length to a goal from the obstacles alone: the length of the
// shortest path of a point among the obstacles (ignoring heading and turning radius), the
// "holonomic with obstacles" heuristic of hybrid A* (Dolgov et al. 2010). It bounds the car's
// path from below when the reference point lies in the body (then it never enters an obstacle),
// so the planner uses it only then.
//
// Built once per goal from the exact reduced visibility graph of the obstacles for a point
// (roadmaps/visibility_graph.hpp): d(v), the shortest path length from each corner v to the goal
// (a Dijkstra from the goal over the corners the goal sees). From a position p the shortest path
// either sees the goal (length |p − goal|) or first bends at a corner v (length |p − v| + d(v)),
// so min(|p − goal|, min over v of |p − v| + d(v)) is a lower bound, without asking what p sees.
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/world.hpp>

#include <memory>
#include <vector>

namespace polyplan {

class HolonomicDistance {
 public:
  // The obstacles and bounds of `world` (its robot is ignored: a point).
  explicit HolonomicDistance(const World& world);
  ~HolonomicDistance();
  HolonomicDistance(HolonomicDistance&&) noexcept;
  HolonomicDistance& operator=(HolonomicDistance&&) noexcept;

  // Sets the goal: the corners' distances to it (a free point; a blocked one leaves every corner
  // unreachable and the bound |p − goal|).
  void set_goal(const ExactPoint& goal);
  // Whether no path of a point joins a and b: they lie in different components of the free space
  // (a point of contact belongs to the components it touches). A car whose body holds its
  // reference point, moving with clearance, then cannot go from one to the other: a proof of no path.
  bool separated(const ExactPoint& a, const ExactPoint& b) const;
  // The lower bound from (x, y) to the goal.
  double lower_bound(double x, double y) const;
  std::size_t corners() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
