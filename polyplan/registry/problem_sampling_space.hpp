#pragma once
// The front door's sampling space of a problem: the space its sampling planners plan in (a polygon
// world's translating robot, a world with discs or walls, a car, an arm), whatever its kind, for
// callers that steer and check motions themselves (Python's polyplan.space).
#include <polyplan/registry/problem.hpp>
#include <polyplan/sampling/any_sampling_space.hpp>

#include <memory>

namespace polyplan {

// The problem must outlive the space, and serves one thread at a time with it (its C-space is
// built on first use). InputError for a problem no sampling planner plans.
std::unique_ptr<AnySamplingSpace> problem_sampling_space(const Problem& problem);

}  // namespace polyplan
