#include <polyplan/arm/arm_path_check.hpp>

#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <cmath>
#include <string>

namespace polyplan {

PathCheck check_arm_path(const ArmProblem& problem, const std::vector<JointAngles>& path) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i].size() != problem.arm.joints())
      throw InputError("path[" + std::to_string(i) + "]: " + std::to_string(path[i].size()) + " angles for an arm of " +
                       std::to_string(problem.arm.joints()) + " joints");
    for (double angle : path[i])
      if (!std::isfinite(angle)) throw InputError("path[" + std::to_string(i) + "]: an angle that is not finite");
  }
  const ArmCollisionChecker checker(problem);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const JointAngles& to = path[std::min(i + 1, path.size() - 1)];
    const MotionCertificate m = certify_motion(checker, path[i], to);
    if (m.free()) continue;
    const std::string motion = "motion " + std::to_string(i) + " (configuration " + std::to_string(i) + " to " +
                               std::to_string(std::min(i + 1, path.size() - 1)) + ")";
    if (m.verdict == MotionCertificate::Verdict::collides)
      return {false,
              motion + " collides at t = " + std::to_string(m.at) + (m.contact ? ": " + m.contact->describe() : ""), i};
    return {false, motion + " is not proved free: it comes too near an obstacle at t = " + std::to_string(m.at), i};
  }
  return {};
}

}  // namespace polyplan
