#pragma once
// RRT* (Karaman & Frazzoli 2011) over any sampling space: RRT whose new node takes, among its
// neighbours, the parent that reaches it most cheaply, and then becomes the parent of each
// neighbour it reaches more cheaply (rewiring); every such motion certified. Neighbours are the
// k nearest within one step, k = ⌈e·(1 + 1/d)·log n⌉, or those within r = min(step, γ·(log n / n)^(1/d)) with
// γ = 2·((1 + 1/d)·volume / unit ball)^(1/d). Anytime: it goes on improving the path until the
// time or iteration limit, so with the defaults it always runs to a limit. With several goals
// (SamplingSpace::goals) the bias draws any one, each may join the tree, and the solution is the
// cheapest path to any of them. Registered as `rrtstar` for polygon worlds and arms.
#include <polyplan/sampling/rrt_planner.hpp>

namespace polyplan {

enum class Rewiring { k_nearest, radius };

struct RrtStarOptions : RrtOptions {
  Rewiring rewire = Rewiring::k_nearest;
  // rewire = k: the neighbours considered, a fixed number (the course's k = 3, 11, 47, 73) or, 0,
  // ⌈e·(1 + 1/d)·log n⌉ (k grows with the tree: the rule that keeps RRT* asymptotically optimal).
  std::size_t k = 0;
  // Anytime, it stops at its time limit: an iteration count small enough to stop it early on an
  // easy problem stopped it before its first path on hard ones (20000 failed the 6R arm).
  RrtStarOptions() {
    time = 5;
    iterations = 1000000000;
  }
};

// The registry's `rrtstar` for a space: options rewire (k|radius), k, goal-bias, step, extend and the
// sampling limits (by default it stops at 5 s; the iteration limit is 10^9). Facts: tree_size, solutions (how often the
// path improved), rewired (motions that replaced a parent).
template <class Space>
PlannerEntry<Space> rrt_star_planner_entry(SamplingSpaceFactory<Space> make_space);

}  // namespace polyplan
