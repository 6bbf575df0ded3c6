#pragma once
// RRT (LaValle 1998) over any sampling space: a tree from the start; each iteration draws a
// sample (the goal itself with probability goal_bias), finds the nearest node and extends toward
// the sample — E1: to the sample itself, E2: a step of at most `step` — when that motion is
// certified free. The query is answered when an extension reaches the goal exactly (with several
// goals, the bias draws one of them uniformly, and reaching any one answers). Registered
// as `rrt` for polygon worlds and arms.
#include <polyplan/sampling/sampling_planner.hpp>

namespace polyplan {

// How a tree grows toward a sample.
enum class Extension {
  to_sample,  // E1: the whole way to the sample, in one motion
  by_step,    // E2: at most `step` toward it
};

struct RrtOptions : SamplingLimits {
  double goal_bias = 0.05;  // probability of drawing the goal as the sample
  double step = 0;          // E2's step η; 0: a fifth of the space's extent (OMPL's range)
  Extension extend = Extension::by_step;
};

// The registry's `rrt` for a space: options goal-bias, step, extend (e1|e2) and the sampling
// limits (seed, time, iterations, shortcut). Facts: tree_size beside the shared ones.
template <class Space>
PlannerEntry<Space> rrt_planner_entry(SamplingSpaceFactory<Space> make_space);

// The options `goal-bias` (a probability), `step` and `extend` (e1|e2) of tree planners whose
// options derive from RrtOptions.
template <class Options>
OptionTable<Options>& add_tree_options(OptionTable<Options>& table) {
  static_assert(std::is_base_of_v<RrtOptions, Options>);
  return table
      .add("goal-bias", static_cast<double Options::*>(&RrtOptions::goal_bias), "probability of sampling the goal",
           in_range(0, 1))
      .add("step", static_cast<double Options::*>(&RrtOptions::step),
           "E2's step: the farthest one extension goes (0: a fifth of the space's extent)", at_least(0))
      .add("extend", static_cast<Extension Options::*>(&RrtOptions::extend),
           "E1: to the sample; E2: one step toward it",
           std::vector<std::pair<std::string, Extension>>{{"e1", Extension::to_sample}, {"e2", Extension::by_step}});
}

// The step an extension takes: 0 (all the way) for E1, otherwise `step` or its default. Throws
// std::invalid_argument for a goal bias outside [0, 1] or a negative step.
double extension_step(const RrtOptions& options, double extent);

}  // namespace polyplan
