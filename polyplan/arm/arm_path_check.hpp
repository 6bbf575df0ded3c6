#pragma once
// Whether an arm's path (its configurations in order, joint angles in radians) is a free motion:
// every motion between consecutive configurations certified as the planners certify it
// (arm_motion.hpp's conservative advancement, never sampled). A motion too near an obstacle to
// prove is not valid.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/geometry/path_check.hpp>

#include <vector>

namespace polyplan {

// InputError for a configuration whose joint count is not the arm's or whose angles are not finite.
PathCheck check_arm_path(const ArmProblem& problem, const std::vector<JointAngles>& path);

}  // namespace polyplan
