#pragma once
// RRT-Connect (Kuffner & LaValle 2000) over any sampling space: a tree from the start and one from
// the goal (with several goals, a forest rooted at each: the path ends at the goal whose tree it meets). Each iteration
// extends one tree a step toward a sample, then the other tree steps toward the new node again and again (each step a
// certified motion) until it reaches it exactly or is stopped; the trees swap roles every iteration. Registered as
// `rrtconnect` for polygon worlds and arms.
#include <polyplan/sampling/rrt_planner.hpp>

namespace polyplan {

struct RrtConnectOptions : SamplingLimits {
  double step = 0;  // the step η of every extension; 0: a fifth of the space's extent
};

// The registry's `rrtconnect` for a space: option step and the sampling limits. Facts: tree_size
// (both trees), start_tree_size, goal_tree_size.
template <class Space>
PlannerEntry<Space> rrt_connect_planner_entry(SamplingSpaceFactory<Space> make_space);

}  // namespace polyplan
