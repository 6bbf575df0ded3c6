#include <polyplan/registry/problem_sampling_space.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/detail/space_door.hpp>
#include <polyplan/sampling/polygon_sampling_space.hpp>
#include <polyplan/sampling/round_sampling_space.hpp>

#if POLYPLAN_WITH_ARM
#include <polyplan/arm/arm_sampling_space.hpp>
#endif
#if POLYPLAN_WITH_CAR
#include <polyplan/car/car_sampling_space.hpp>
#endif

namespace polyplan {
namespace {

using detail::SpaceTag;

// Each space's sampling space, built as its registry's sampling planners build theirs; none for a
// space without sampling planners (a turning robot's, and a family this build left out).
template <class Tag, class Built>
std::unique_ptr<AnySamplingSpace> space_for(Tag, const Built&) {
  return nullptr;
}
std::unique_ptr<AnySamplingSpace> space_for(SpaceTag<TranslatingRobot>, const CSpace& cspace) {
  return any_sampling_space(polygon_sampling_space(cspace));
}
std::unique_ptr<AnySamplingSpace> space_for(SpaceTag<RoundRobot>, const RoundWorld& world) {
  return any_sampling_space(round_sampling_space(world));
}
#if POLYPLAN_WITH_CAR
std::unique_ptr<AnySamplingSpace> space_for(SpaceTag<SteeredCar>, const World& world) {
  return any_sampling_space(car_sampling_space(world));
}
#endif
#if POLYPLAN_WITH_ARM
std::unique_ptr<AnySamplingSpace> space_for(SpaceTag<PlanarArm>, const ArmProblem& arm) {
  return any_sampling_space(arm_sampling_space(arm));
}
#endif

}  // namespace

std::unique_ptr<AnySamplingSpace> problem_sampling_space(const Problem& problem) {
  std::unique_ptr<AnySamplingSpace> space;
  // The first space whose door plans the problem is the one its planners plan in (space_door.hpp).
  detail::any_space([&](auto tag) {
    const auto& door = detail::space_door<typename decltype(tag)::Space>();
    if (!door.plans(problem)) return false;
    space = space_for(tag, door.built_from(problem));
    return true;
  });
  if (!space)
    throw InputError(problem.source() + ": no sampling planner plans this problem, so it has no sampling space");
  return space;
}

}  // namespace polyplan
