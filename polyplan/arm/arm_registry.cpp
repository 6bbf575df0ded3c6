#include <polyplan/arm/arm_registry.hpp>

#include <polyplan/arm/arm_grid_planner.hpp>

namespace polyplan {

// Every arm planner, one line each, in the order `polyplan planners` lists them.
template <>
const PlannerRegistry<PlanarArm>& planners<PlanarArm>() {
  static const PlannerRegistry<PlanarArm> registry{
      arm_grid_planner_entry(),
  };
  return registry;
}

}  // namespace polyplan
