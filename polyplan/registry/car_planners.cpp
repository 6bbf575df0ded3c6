#include <polyplan/registry/registry.hpp>

#if POLYPLAN_WITH_CAR
#include <polyplan/car/car_rrt_planner.hpp>
#include <polyplan/car/car_sampling_space.hpp>
#include <polyplan/car/hybrid_astar_planner.hpp>
#include <polyplan/sampling/lazy_prm_planner.hpp>
#include <polyplan/sampling/prm_planner.hpp>
#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/rrt_star_planner.hpp>
#endif

namespace polyplan {

// Every planner of a steered car, one line each, in the order `polyplan planners` lists them.
template <>
const PlannerRegistry<SteeredCar>& planners<SteeredCar>() {
#if POLYPLAN_WITH_CAR
  static const PlannerRegistry<SteeredCar> registry{"hybrid-astar",
                                                    {
                                                        hybrid_astar_planner_entry(),
                                                        car_rrt_planner_entry(),
                                                        prm_planner_entry<SteeredCar>(car_sampling_space),
                                                        lazy_prm_planner_entry<SteeredCar>(car_sampling_space),
                                                        rrt_planner_entry<SteeredCar>(car_sampling_space),
                                                        rrt_star_planner_entry<SteeredCar>(car_sampling_space),
                                                        rrt_connect_planner_entry<SteeredCar>(car_sampling_space),
                                                    }};
#else
  static const auto registry = PlannerRegistry<SteeredCar>::left_out("car");
#endif
  return registry;
}

}  // namespace polyplan
