#pragma once
// The replanning planners, registered as `dstar-lite`, `lpastar` and `repeated-astar` for polygon
// worlds (TranslatingRobot, the raster of grids/raster_planner.hpp: a cell blocked when it meets a
// C-obstacle's interior) and for worlds with discs, walls, disc bounds and a point or disc robot
// (RoundRobot, the raster of geometry/round_rasterize.hpp): a robot drives the world's raster, the
// bounds cut into n × n cells, from the start's cell to the goal's with
// incremental/discovering_robot.hpp, while the world changes as its file's "changes" say — after k
// moves an obstacle polygon appears, or one disappears. The robot senses the cells within `sensor`
// cells of its own (0: the whole raster, so it learns of a change as it happens) and replans with
// the planner's algorithm on what it knows.
//
// Each world the changes make is rasterised anew from its own exact problem (a polygon world's
// raster decides again only the cells near the changed obstacles; a round world's is rasterised
// whole). The path returned is the start, the centres of the cells where the drive turns, and the
// goal; each stretch driven between two changes is checked exactly (check_path, or
// RoundWorld::check_path) against the world as it was while the robot drove it, and a drive that
// fails the check (or ends with an obstacle on the robot) is not returned. Costs are the grid's (1
// and √2 per move, in cells): with non-square cells (bounds that are not square) the drive is
// shortest in moves, not in length.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>

namespace polyplan {

struct ReplanningOptions {
  std::size_t resolution = 100;  // cells per side of the bounds
  double sensor = 0;             // the sensing radius in cells (at least √2), or 0: the whole raster
  std::size_t max_moves = 0;     // 0: 4 × the raster's cells; then status limit
  double time = 300;             // seconds per query before the drive stops with status limit
  GridConventions grid{};        // connectivity, corner cutting, diagonal cost (sensor >= 1 with 4 or cutting)
  bool known_map = false;        // the robot starts knowing the raster as it is at the start
};

// Space: TranslatingRobot (its problem a CSpace) or RoundRobot (a RoundWorld).
template <class Space>
class BasicReplanningPlanner final : public Planner<Space> {
 public:
  // Builds and rasterises the world of `world` (which must outlive the planner) and every world
  // its changes make. Throws InputError naming the file when the world has no bounds (box or
  // disc), std::invalid_argument for a resolution of 0 or too large, or a sensor radius that is
  // neither 0 nor a finite number of at least √2.
  BasicReplanningPlanner(const typename Space::Problem& world, ReplanAlgorithm algorithm,
                         ReplanningOptions options = {});
  ~BasicReplanningPlanner() override;

  // Facts: roadmap.kind (the planner's name), raster.cells_per_axis, raster.blocked_cells (at the
  // start), raster.start_cell, raster.goal_cell, raster.connectivity, raster.corner_cutting,
  // raster.diagonal_cost, replan.algorithm, replan.sensor_cells (0: all), replan.known_map,
  // replan.moves, replan.replans, replan.changes_made (those the drive lived to see),
  // replan.grid_cost (the moves' cost in cells), search.expanded, search.generated,
  // search.heap_operations, query_seconds. The picture shows the raster as it was at the drive's
  // end, and a polygon world's C-space likewise (PlanReport::world_at_end; a round world's picture
  // draws the file's world, PlanRecording holding a C-space only).
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using ReplanningPlanner = BasicReplanningPlanner<TranslatingRobot>;
using RoundReplanningPlanner = BasicReplanningPlanner<RoundRobot>;

// The registries' entry for one algorithm (TranslatingRobot, RoundRobot): `dstar-lite`, `lpastar`
// or `repeated-astar`, with the options resolution (100), sensor (0), max-moves (0) and time.
template <class Space>
PlannerEntry<Space> replanning_planner_entry(ReplanAlgorithm algorithm);

}  // namespace polyplan
