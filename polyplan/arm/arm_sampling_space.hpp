#pragma once
// The sampling planners' space for a planar n-link arm (sampling/sampling_space.hpp): joint angles
// on the torus, each drawn uniformly from [0, 2π); distances are the sum of the joints' turns the
// short way round (the arm's path length); a configuration is free when the arm there is
// (arm/arm_collision.hpp, touching counts as collision); a motion is every joint turning the short
// way at a constant rate, certified by conservative advancement (arm/arm_motion.hpp).
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <memory>

namespace polyplan {

// The space of `problem`, which must outlive it.
std::unique_ptr<SamplingSpace<PlanarArm>> arm_sampling_space(const ArmProblem& problem);

}  // namespace polyplan
