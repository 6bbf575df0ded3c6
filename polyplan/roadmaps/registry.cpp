#include <polyplan/roadmaps/registry.hpp>

#include <polyplan/roadmaps/gvd_grid_planner.hpp>
#include <polyplan/roadmaps/lazy_prm_planner.hpp>
#include <polyplan/roadmaps/polygon_sampling_space.hpp>
#include <polyplan/roadmaps/prm_planner.hpp>
#include <polyplan/roadmaps/raster_planner.hpp>
#include <polyplan/roadmaps/rotation_planner.hpp>
#include <polyplan/roadmaps/rrt_connect_planner.hpp>
#include <polyplan/roadmaps/rrt_planner.hpp>
#include <polyplan/roadmaps/rrt_star_planner.hpp>
#include <polyplan/roadmaps/trapezoid_planner.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/roadmaps/voronoi_planner.hpp>

namespace polyplan {

// Every planner of polygon worlds, one line each, in the order `polyplan planners` lists them.
template <>
const PlannerRegistry<TranslatingRobot>& planners<TranslatingRobot>() {
  static const PlannerRegistry<TranslatingRobot> registry{
      visibility_planner_entry(VisibilityKind::reduced),
      visibility_planner_entry(VisibilityKind::full),
      raster_planner_entry(),
      trapezoid_planner_entry(),
      voronoi_planner_entry(),
      gvd_grid_planner_entry(),
      prm_planner_entry<TranslatingRobot>(polygon_sampling_space),
      lazy_prm_planner_entry<TranslatingRobot>(polygon_sampling_space),
      rrt_planner_entry<TranslatingRobot>(polygon_sampling_space),
      rrt_star_planner_entry<TranslatingRobot>(polygon_sampling_space),
      rrt_connect_planner_entry<TranslatingRobot>(polygon_sampling_space),
  };
  return registry;
}

// Every planner of rotating polygon robots.
template <>
const PlannerRegistry<RotatingRobot>& planners<RotatingRobot>() {
  static const PlannerRegistry<RotatingRobot> registry{
      rotation_planner_entry(),
  };
  return registry;
}

}  // namespace polyplan
