#pragma once
// Planning on a rasterised world (geometry/rasterize.hpp), as the course's graph-search homework's search_start_goal
// does: the world's bounds cut into n × n cells, a cell blocked when it meets a C-obstacle's interior; start and goal
// snap to the nearest free cell centre, the implicit grid graph (search/grid_graph.hpp) is searched between those
// cells, and the path is start → the centres where the grid path turns → goal. Registered as `raster` for both
// spaces whose configurations are exact points: a polygon world's C-space (RasterPlanner) and a world with discs and
// walls for a point or disc robot (RoundRasterPlanner, rasterised by geometry/round_rasterize.hpp; its disc bounds
// give the grid the square round them). The same search, facts and answers in both.
//
// The grid part of such a path never enters a C-obstacle: it runs through free open squares and
// across sides and corners shared by free cells (diagonal moves never cut a corner). The joins
// from the start to its cell centre and from the goal's centre to the goal are not so protected —
// at a coarse resolution the nearest free centre can lie behind an obstacle corner. So the whole
// polyline is checked exactly (geometry/path_check.hpp, RoundWorld::check_path): a path that fails
// is not returned (found = false, why_not quotes the check), never hidden and never accepted.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <utility>

namespace polyplan {

struct RasterOptions {
  std::size_t resolution = 100;                    // cells per side of the bounds (n)
  Connectivity connectivity = Connectivity::full;  // full: 8-connected without corner cutting; axis_aligned: 4
  SearchOptions search{};
  bool corner_cutting = false;   // a diagonal move may pass a blocked cell's corner
  DiagonalCost diagonal_cost{};  // √2; a number only on square cells (InputError otherwise)
  GridConventions conventions() const { return {connectivity, corner_cutting, diagonal_cost}; }
};

// Space: TranslatingRobot (its problem a CSpace) or RoundRobot (a RoundWorld).
template <class Space>
class BasicRasterPlanner final : public Planner<Space> {
 public:
  // Rasterises the world of `world` (which must outlive the planner) once. Throws InputError
  // naming the world's file when it has no bounds, or for a resolution of 0 or above
  // max_cells_per_axis.
  explicit BasicRasterPlanner(const typename Space::Problem& world, RasterOptions options = {});
  ~BasicRasterPlanner() override;

  // Facts: roadmap.kind "raster", roadmap.vertices (free cells), roadmap.edges (moves between
  // them), roadmap.seconds (rasterising and the graph), raster.cells_per_axis,
  // raster.blocked_cells, raster.start_cell and raster.goal_cell ("(x, y)", the snapped cells),
  // raster.grid_cost (the grid path's length), raster.connectivity, raster.corner_cutting,
  // raster.diagonal_cost, search.*, query_seconds. A start or goal that is
  // not free (invalid_query), unconnected cells, and a polyline that fails the exact check
  // (not_found) are answers (found = false) with the reason.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

  // Where a start or goal snaps: polyplan::nearest_free_cell (geometry/rasterize.hpp) on the raster.
  std::optional<std::pair<std::size_t, std::size_t>> nearest_free_cell(const ExactPoint& p) const;

  const Raster& raster() const;
  const GridGraph& graph() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using RasterPlanner = BasicRasterPlanner<TranslatingRobot>;
using RoundRasterPlanner = BasicRasterPlanner<RoundRobot>;

// The registries' `raster` (TranslatingRobot, RoundRobot): options resolution (100),
// connectivity (8), corner-cutting (false), diagonal-cost (sqrt2), search, weight, reopen.
template <class Space>
PlannerEntry<Space> raster_planner_entry();

}  // namespace polyplan
