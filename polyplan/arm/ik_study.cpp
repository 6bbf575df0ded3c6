#include <polyplan/arm/ik_study.hpp>

#include <polyplan/arm/arm_collision.hpp>

namespace polyplan {

IkStudy study_ik(const ArmProblem& problem, const IkRequest& request) {
  IkOptions options;
  options.orientation = request.orientation_radians();
  options.limits = problem.arm.limits;
  options.all = request.all;
  options.seeds = request.all ? 32 : 8;
  options.exact_target = request.exact_target;
  IkStudy study{inverse_kinematics(problem.arm, request.target, options), {}};
  const ArmCollisionChecker checker(problem);
  for (const IkSolution& s : study.answer.solutions) study.free.push_back(checker.is_free(s.angles));
  if (!request.collision_free || !study.answer.found) return study;
  IkStudy kept{{false, {}, ""}, {}};
  for (std::size_t i = 0; i < study.answer.solutions.size(); ++i)
    if (study.free[i]) kept.answer.solutions.push_back(study.answer.solutions[i]);
  kept.answer.found = !kept.answer.solutions.empty();
  if (!kept.answer.found) {
    study.answer.found = false;
    study.answer.why_not = "every solution collides";
    return study;
  }
  kept.free.assign(kept.answer.solutions.size(), true);
  return kept;
}

}  // namespace polyplan
