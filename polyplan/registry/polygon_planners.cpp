#include <polyplan/registry/registry.hpp>

#include <polyplan/roadmaps/trapezoid_planner.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/roadmaps/voronoi_planner.hpp>
#if POLYPLAN_WITH_GRIDS
#include <polyplan/grids/gvd_grid_planner.hpp>
#include <polyplan/grids/raster_planner.hpp>
#endif
#if POLYPLAN_WITH_HOMOTOPY
#include <polyplan/homotopy/homotopy_planner.hpp>
#include <polyplan/homotopy/tether_planner.hpp>
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
#if POLYPLAN_WITH_ROTATION
#include <polyplan/rotation/rotation_planner.hpp>
#endif
#if POLYPLAN_WITH_SAMPLING
#include <polyplan/sampling/lazy_prm_planner.hpp>
#include <polyplan/sampling/polygon_sampling_space.hpp>
#include <polyplan/sampling/prm_planner.hpp>
#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/rrt_star_planner.hpp>
#endif

namespace polyplan {

// Every planner of polygon worlds, one line each, in the order `polyplan planners` lists them;
// those of a family this build leaves out (cmake -DPOLYPLAN_FAMILIES) are not compiled in.
template <>
const PlannerRegistry<TranslatingRobot>& planners<TranslatingRobot>() {
  static const PlannerRegistry<TranslatingRobot> registry{
      "visibility",
      {
          visibility_planner_entry(VisibilityKind::reduced),
          visibility_planner_entry(VisibilityKind::full),
#if POLYPLAN_WITH_GRIDS
          raster_planner_entry<TranslatingRobot>(),
#endif
          trapezoid_planner_entry(),
          voronoi_planner_entry(),
#if POLYPLAN_WITH_GRIDS
          gvd_grid_planner_entry<TranslatingRobot>(),
#endif
#if POLYPLAN_WITH_INCREMENTAL
          replanning_planner_entry<TranslatingRobot>(ReplanAlgorithm::dstar_lite),
          replanning_planner_entry<TranslatingRobot>(ReplanAlgorithm::lpastar),
          replanning_planner_entry<TranslatingRobot>(ReplanAlgorithm::astar),
#endif
#if POLYPLAN_WITH_REACTIVE
          potential_field_planner_entry(),
          navigation_function_planner_entry(),
          bug_planner_entry<TranslatingRobot>(BugKind::bug1),
          bug_planner_entry<TranslatingRobot>(BugKind::bug2),
          tangent_bug_planner_entry<TranslatingRobot>(),
#endif
#if POLYPLAN_WITH_HOMOTOPY
          homotopy_planner_entry(),
          tether_planner_entry(),
#endif
#if POLYPLAN_WITH_SAMPLING
          prm_planner_entry<TranslatingRobot>(polygon_sampling_space),
          lazy_prm_planner_entry<TranslatingRobot>(polygon_sampling_space),
          rrt_planner_entry<TranslatingRobot>(polygon_sampling_space),
          rrt_star_planner_entry<TranslatingRobot>(polygon_sampling_space),
          rrt_connect_planner_entry<TranslatingRobot>(polygon_sampling_space),
#endif
      }};
  return registry;
}

// Every planner of rotating polygon robots.
template <>
const PlannerRegistry<RotatingRobot>& planners<RotatingRobot>() {
#if POLYPLAN_WITH_ROTATION
  static const PlannerRegistry<RotatingRobot> registry{"rotation", {rotation_planner_entry()}};
#else
  static const auto registry = PlannerRegistry<RotatingRobot>::left_out("rotation");
#endif
  return registry;
}

}  // namespace polyplan
