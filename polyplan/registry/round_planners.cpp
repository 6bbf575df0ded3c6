// Every planner of a point or disc robot among discs, walls and polygons (RoundRobot): the exact
// shortest paths of the tangent visibility graph, the sampling planners over the exact rational
// checks of geometry/round_world_check.hpp, the occupancy grid rasterised exactly
// (geometry/round_rasterize.hpp) and driven by the replanning planners as the world's "changes"
// happen, and the reactive planners (the Bugs, TangentBug, the potential field and the navigation function).
#include <polyplan/registry/registry.hpp>
#include <polyplan/roadmaps/tangent_visibility.hpp>

#if POLYPLAN_WITH_GRIDS
#include <polyplan/grids/gvd_grid_planner.hpp>
#include <polyplan/grids/raster_planner.hpp>
#endif
#if POLYPLAN_WITH_INCREMENTAL
#include <polyplan/incremental/replanning_planner.hpp>
#endif
#if POLYPLAN_WITH_REACTIVE
#include <polyplan/reactive/bug_planner.hpp>
#include <polyplan/reactive/navigation_function_planner.hpp>
#include <polyplan/reactive/potential_field_planner.hpp>
#include <polyplan/reactive/tangent_bug_planner.hpp>
#endif
#if POLYPLAN_WITH_SAMPLING
#include <polyplan/sampling/lazy_prm_planner.hpp>
#include <polyplan/sampling/prm_planner.hpp>
#include <polyplan/sampling/round_sampling_space.hpp>
#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/rrt_star_planner.hpp>
#endif

namespace polyplan {
namespace {

// An entry that says it plans with discs, walls and a disc robot (world_queries.hpp's refusal
// lists it among those that do).
PlannerEntry<RoundRobot> round(PlannerEntry<RoundRobot> entry) {
  entry.plans_round_worlds = true;
  return entry;
}

}  // namespace

template <>
const PlannerRegistry<RoundRobot>& planners<RoundRobot>() {
  static const PlannerRegistry<RoundRobot> registry{
      "visibility",
      {
          round(tangent_visibility_planner_entry()),
#if POLYPLAN_WITH_SAMPLING
          round(prm_planner_entry<RoundRobot>(round_sampling_space)),
          round(lazy_prm_planner_entry<RoundRobot>(round_sampling_space)),
          round(rrt_planner_entry<RoundRobot>(round_sampling_space)),
          round(rrt_star_planner_entry<RoundRobot>(round_sampling_space)),
          round(rrt_connect_planner_entry<RoundRobot>(round_sampling_space)),
#endif
#if POLYPLAN_WITH_GRIDS
          round(raster_planner_entry<RoundRobot>()),
          round(gvd_grid_planner_entry<RoundRobot>()),
#endif
#if POLYPLAN_WITH_INCREMENTAL
          round(replanning_planner_entry<RoundRobot>(ReplanAlgorithm::dstar_lite)),
          round(replanning_planner_entry<RoundRobot>(ReplanAlgorithm::lpastar)),
          round(replanning_planner_entry<RoundRobot>(ReplanAlgorithm::astar)),
#endif
#if POLYPLAN_WITH_REACTIVE
          round(round_navigation_function_planner_entry()),
          round(round_potential_field_planner_entry()),
          round(bug_planner_entry<RoundRobot>(BugKind::bug1)),
          round(bug_planner_entry<RoundRobot>(BugKind::bug2)),
          round(tangent_bug_planner_entry<RoundRobot>()),
#endif
      }};
  return registry;
}

}  // namespace polyplan
