#pragma once
// The sampling planners' space for a planar n-link arm (sampling/sampling_space.hpp): joint angles
// on the torus, each drawn uniformly from [0, 2π); distances are the sum of the joints' turns the
// short way round (the arm's path length); a configuration is free when the arm there is
// (arm/arm_collision.hpp, touching counts as collision); a motion is every joint turning the short
// way at a constant rate, certified by conservative advancement (arm/arm_motion.hpp). A query's
// goals are its goal set (arm/arm_goal_set.hpp): for a goal point, its free IK solutions — none
// makes the query no_path (out of reach) or not_found —, and a path's report names the one reached
// (set_goal_facts).
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <memory>

namespace polyplan {

// The space of `problem`, which must outlive it.
std::unique_ptr<SamplingSpace<PlanarArm>> arm_sampling_space(const ArmProblem& problem);

}  // namespace polyplan
