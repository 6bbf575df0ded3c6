#include <polyplan/registry/registry.hpp>

#include <polyplan/car/car_rrt_planner.hpp>
#include <polyplan/car/hybrid_astar_planner.hpp>

namespace polyplan {

// Every planner of a steered car, one line each, in the order `polyplan planners` lists them.
template <>
const PlannerRegistry<SteeredCar>& planners<SteeredCar>() {
  static const PlannerRegistry<SteeredCar> registry{
      hybrid_astar_planner_entry(),
      car_rrt_planner_entry(),
  };
  return registry;
}

}  // namespace polyplan
