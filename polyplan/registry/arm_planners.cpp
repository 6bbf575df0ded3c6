#include <polyplan/registry/registry.hpp>

#if POLYPLAN_WITH_ARM
#include <polyplan/arm/arm_grid_planner.hpp>
#include <polyplan/arm/arm_sampling_space.hpp>
#include <polyplan/sampling/lazy_prm_planner.hpp>
#include <polyplan/sampling/prm_planner.hpp>
#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/rrt_star_planner.hpp>
#endif

namespace polyplan {

// Every arm planner, one line each, in the order `polyplan planners` lists them.
template <>
const PlannerRegistry<PlanarArm>& planners<PlanarArm>() {
#if POLYPLAN_WITH_ARM
  static const PlannerRegistry<PlanarArm> registry{"grid",
                                                   {
                                                       arm_grid_planner_entry(),
                                                       prm_planner_entry<PlanarArm>(arm_sampling_space),
                                                       lazy_prm_planner_entry<PlanarArm>(arm_sampling_space),
                                                       rrt_planner_entry<PlanarArm>(arm_sampling_space),
                                                       rrt_star_planner_entry<PlanarArm>(arm_sampling_space),
                                                       rrt_connect_planner_entry<PlanarArm>(arm_sampling_space),
                                                   }};
#else
  static const auto registry = PlannerRegistry<PlanarArm>::left_out("arm");
#endif
  return registry;
}

}  // namespace polyplan
