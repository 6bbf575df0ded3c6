#pragma once
// Planning on a rasterised world (geometry/rasterize.hpp), as seed 000's search_start_goal does:
// start and goal snap to the nearest free cell centre, the implicit grid graph
// (search/grid_graph.hpp) is searched between those cells, and the path is
// start → the cells' centres → goal.
//
// The grid part of such a path never enters a C-obstacle: it runs through free open squares and
// across sides and corners shared by free cells (diagonal moves never cut a corner). The joins
// from the start to its cell centre and from the goal's centre to the goal are not so protected —
// at a coarse resolution the nearest free centre can lie behind an obstacle corner. So the whole
// polyline is checked exactly (geometry/path_check.hpp) and the verdict is reported, never hidden:
// `found` says the grid search succeeded, `checked_free` whether the polyline is a valid motion.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {

struct RasterPlan {
  bool found = false;
  // Why found is false: the start or goal is not free (it says what it hits), or no grid path
  // joins the two snapped cells. Empty when found.
  std::string why_not_found;
  // start, the centres of the grid path's cells, goal; exact. Centres in the middle of a straight
  // run of equal moves are left out (the same polyline); search.path keeps every cell. A start or
  // goal that is its cell's centre appears once.
  std::vector<ExactPoint> path;
  double length = 0;             // Euclidean length of `path` (double)
  bool checked_free = false;     // check_path found `path` a valid motion
  std::string why_not_free;      // check_path's reason when not (e.g. a join crossing an obstacle)
  std::size_t start_cell_x = 0, start_cell_y = 0, goal_cell_x = 0, goal_cell_y = 0;  // the snapped cells
  SearchResult<GridCell> search;  // cells of the grid path, cost (in world units) and counts
};

// The raster's grid graph (free cells, world-unit step costs), built once for many queries.
class RasterPlanner {
 public:
  // `raster` must have been made from `cspace` (same world): std::invalid_argument when the
  // bounds differ. Connectivity::full is 8-connected without corner cutting, axis_aligned 4-connected.
  // Both are kept by reference: they must outlive the planner.
  RasterPlanner(const Raster& raster, const CSpace& cspace, Connectivity connectivity = Connectivity::full);

  // A start or goal that is not free (inside a C-obstacle or outside the bounds; contact is free)
  // gives found == false with the reason, not an exception: callers that want bad queries
  // rejected as input errors call CSpace::require_free_queries first, as the programs do.
  RasterPlan plan(const Query& query, const SearchOptions& options = {}) const;

  // The free cell whose centre is nearest to p (exact Euclidean distance; among equally near
  // cells the one of lowest index x + y·n); nullopt when every cell is blocked.
  std::optional<std::pair<std::size_t, std::size_t>> nearest_free_cell(const ExactPoint& p) const;

  const GridGraph& graph() const { return graph_; }

 private:
  const Raster* raster_;
  const CSpace* cspace_;
  GridGraph graph_;
};

// One query: RasterPlanner(raster, cspace, connectivity).plan(query, options).
RasterPlan plan_on_raster(const Raster& raster, const CSpace& cspace, const Query& query,
                          const SearchOptions& options = {}, Connectivity connectivity = Connectivity::full);

}  // namespace polyplan
