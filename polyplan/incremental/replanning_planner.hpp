#pragma once
// The replanning planners of polygon worlds, registered as `dstar-lite`, `lpastar` and
// `repeated-astar`: a robot drives the world's raster (the cells of grids/raster_planner.hpp: the
// bounds cut into n × n cells, a cell blocked when it meets a C-obstacle's interior) from the
// start's cell to the goal's with incremental/discovering_robot.hpp, while the world changes as
// its file's "changes" say — after k moves an obstacle appears, or one disappears. The robot
// senses the cells within `sensor` cells of its own (0: the whole raster, so it learns of a
// change as it happens) and replans with the planner's algorithm on what it knows.
//
// Each world the changes make is rasterised anew from its own exact C-space. The path returned is
// the start, the centres of the cells where the drive turns, and the goal; each stretch driven
// between two changes is checked exactly against the C-space of the world as it was while the
// robot drove it, and a drive that fails the check (or ends with an obstacle on the robot) is not
// returned. Costs are the grid's (1 and √2 per move, in cells): with non-square cells (bounds that
// are not square) the drive is shortest in moves, not in length.
#include <polyplan/geometry/cspace.hpp>
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
};

class ReplanningPlanner final : public Planner<TranslatingRobot> {
 public:
  // Builds and rasterises the world of `cspace` (which must outlive the planner) and every world
  // its changes make. Throws InputError naming the file when the world has no bounds,
  // std::invalid_argument for a resolution of 0 or too large, or a sensor radius that is neither 0
  // nor a finite number of at least √2.
  ReplanningPlanner(const CSpace& cspace, ReplanAlgorithm algorithm, ReplanningOptions options = {});
  ~ReplanningPlanner() override;

  // Facts: roadmap.kind (the planner's name), raster.cells_per_axis, raster.blocked_cells (at the
  // start), raster.start_cell, raster.goal_cell, replan.algorithm, replan.sensor_cells (0: all),
  // replan.moves, replan.replans, replan.changes_made (those the drive lived to see),
  // replan.grid_cost (the moves' cost in cells), search.expanded, search.generated,
  // search.heap_operations, query_seconds. The picture shows the world and its raster as they
  // were at the drive's end (PlanReport::world_at_end).
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The registry's entry for one algorithm: `dstar-lite`, `lpastar` or `repeated-astar`, with the
// options resolution (100), sensor (0) and max-moves (0).
PlannerEntry<TranslatingRobot> replanning_planner_entry(ReplanAlgorithm algorithm);

}  // namespace polyplan
