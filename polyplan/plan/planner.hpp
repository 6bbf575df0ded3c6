#pragma once
// The one interface every planner implements. A planner is built once from a problem (the exact
// C-space of a polygon world, an arm and its surroundings) and its options, then answers queries
// with a PlanReport (plan/plan_report.hpp). Planners are found by name in a registry
// (registry/registry.hpp), which gives each one its command-line name, its options, the JSON
// writer, the picture and the conformance test; docs/architecture.md says how to add one.
//
// A configuration space is a small traits struct: what a configuration is, what a planner is
// built from, and what a query is. Planners of one space share everything above them.
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/geometry/world.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <string_view>

namespace polyplan {

// A polygon robot (or a point) translating among polygon obstacles: configurations are the
// reference point's exact positions. `polyplan plan` answers these.
struct TranslatingRobot {
  using Configuration = ExactPoint;
  using Problem = CSpace;
  using Query = polyplan::Query;
  static constexpr std::string_view description = "a polygon robot translating in a polygon world";
};

// A point, disc or translating polygon robot among discs, walls of zero thickness and polygons, in
// box or disc bounds (World::round_features): configurations are exact positions of the reference
// point, motions straight segments checked exactly in rationals against the C-space of
// geometry/round_cspace.hpp (geometry/round_world_check.hpp). Its planners are the tangent
// visibility graph, the sampling planners, the grid planners over its exact raster (raster,
// gvd-grid, and the replanning planners dstar-lite, lpastar, repeated-astar) and the reactive
// planners.
struct RoundRobot {
  using Configuration = ExactPoint;
  using Problem = RoundWorld;
  using Query = polyplan::Query;
  static constexpr std::string_view description = "a robot (point, disc or polygon) among discs, walls and polygons";
};

// A polygon robot that translates and turns about its reference point among polygon obstacles:
// configurations are poses (exact position, exact rotation). A path's consecutive poses differ
// either in position only (a straight translation) or in rotation only (a turn on the spot, the
// short way, by turn_degrees). The problem is the world itself: the planner builds the exact
// C-space of each orientation it uses. `polyplan plan --planner rotation` answers these.
struct RotatingRobot {
  using Configuration = Pose;
  using Problem = World;
  using Query = polyplan::Query;
  static constexpr std::string_view description = "a polygon robot translating and turning in a polygon world";
};

// A planar n-link arm among obstacle polygons and points: configurations are relative joint
// angles (radians). `polyplan arm` answers these.
struct PlanarArm {
  using Configuration = JointAngles;
  using Problem = ArmProblem;
  using Query = ArmQuery;
  static constexpr std::string_view description = "a planar n-link arm";
};

// A car among polygon obstacles (the world's robot has `car`: its turning radius, and whether it
// may reverse): configurations are poses (doubles: the reference point and the heading) with the
// segment that drove there (geometry/car_pose.hpp); a path is one segment from each entry to the
// next, an arc at full lock or a straight, certified free (car/car_collision.hpp). The problem is
// the world itself. `polyplan plan` answers these when the world's robot is a car.
struct SteeredCar {
  using Configuration = CarState;
  using Problem = World;
  using Query = polyplan::Query;
  static constexpr std::string_view description = "a car steering among polygon obstacles";
};

// What a query asks beyond its start and goal.
struct QueryOptions {
  // Keep what a picture shows: the roadmap or tree, the expanded configurations, the cells.
  bool record = false;
  // Keep every expansion of the graph search with its g, h, f, backpointer and open-list size
  // (PlanReport::trace): the planners that search a graph (roadmaps, grids) do.
  bool trace = false;
};

template <class Space>
class Planner {
 public:
  using Configuration = typename Space::Configuration;
  using Query = typename Space::Query;

  virtual ~Planner() = default;

  // The answer to one query. A start or goal that is not free, or that the planner cannot reach,
  // is an answer (found = false, why_not says so), not an exception. A found path begins exactly
  // at the query's start, ends exactly at its goal, and is certified free along every motion.
  // Planners keep per-query scratch space: one planner serves one thread.
  virtual PlanReport<Configuration> plan(const Query& query, const QueryOptions& options = {}) = 0;
};

}  // namespace polyplan
