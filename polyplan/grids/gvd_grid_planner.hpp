#pragma once
// The brushfire GVD planner on an occupancy grid (the course's GVD exercise): the world
// rasterised as `raster` does it (geometry/rasterize.hpp, n × n exact cells), the brushfire of
// that grid (search/brushfire.hpp) giving every free cell its distance to the nearest obstacle
// and the generalized Voronoi diagram where two wavefronts meet — of two obstacles, or of one
// obstacle from two places along it (the two jambs of a door, the two sides of a pocket, the
// bounds from two sides; thinned to what joins pieces and ends climbs), told apart by the
// obstacle cells the fronts came from. The cells where the robot would leave the bounds are
// part of the outside, the bounds' one obstacle, so a wall touching the bounds keeps its own
// id. A query snaps start and goal to their nearest free cells (as `raster` does), climbs from each up the distance
// field to the GVD, searches along GVD cells between the two places where the climbs arrive, and joins start → the
// centres where that cell path turns → goal. Registered as `gvd-grid`.
//
// The climb is a steepest ascent over the moves of the 8-connected grid without corner cutting:
// from a cell off the GVD it steps onto a GVD neighbour when there is one (the one of largest
// distance, then lowest index), otherwise to the neighbour of largest distance, strictly larger
// than its own (then lowest index). Within a free component of the grid the GVD is one piece and
// every climb reaches it (brushfire.hpp; tested on random grids, not proven), so start and goal
// whose cells share a free component are joined; cells in two components are answered found =
// false with the reason ("the GVD does not connect ..."), as would be a climb ending off the GVD
// (the guard of the unproven property).
//
// The path keeps away from obstacles rather than being short. Like `raster`'s, its joins to the
// exact start and goal are not protected by the cells, so the whole polyline is checked exactly
// (geometry/path_check.hpp) and a polyline that fails is not returned (found = false, why_not
// quotes the check).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/brushfire.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace polyplan {

struct GvdGridOptions {
  std::size_t resolution = 100;  // cells per side of the bounds (n)
  SearchOptions search{};        // along the GVD
  // The moves of the search along the GVD: corner cutting and diagonal cost (connectivity 4 is
  // refused, InputError: the GVD is joined by 8-connected moves, and the climbs stay so).
  GridConventions grid{};
};

// Space: TranslatingRobot (its problem a CSpace) or RoundRobot (a RoundWorld, rasterised by
// geometry/round_rasterize.hpp; no clearance or bottleneck is measured there).
template <class Space>
class BasicGvdGridPlanner final : public Planner<Space> {
 public:
  // Rasterises the world of `world` (which must outlive the planner) and runs the brushfire once.
  // Throws InputError naming the world's file when it has no bounds, std::invalid_argument for a
  // resolution of 0 or above max_cells_per_axis.
  explicit BasicGvdGridPlanner(const typename Space::Problem& world, GvdGridOptions options = {});
  ~BasicGvdGridPlanner() override;

  // Facts: roadmap.kind "gvd-grid", roadmap.vertices (GVD cells), roadmap.edges (moves between
  // them), roadmap.seconds (rasterising, brushfire and graph), raster.cells_per_axis, gvd.cells,
  // gvd.max_distance (the largest brushfire distance, in cells), raster.start_cell and
  // raster.goal_cell (the snapped cells), gvd.start_cell and gvd.goal_cell (where their climbs
  // reach the GVD), search.* (along the GVD), query_seconds, and for a path found `clearance` and
  // `bottleneck` {x, y} (the path's smallest distance to the C-obstacles and walls and where,
  // measured on it: geometry/clearance.hpp) and gvd.clearance_bound: (d - 1/2) × the shorter cell
  // side, d the smallest brushfire distance of the path's cells — what the grid alone promises for
  // the path's cell centres (not for the joins to the exact start and goal). With QueryOptions::record,
  // `cells` holds the raster, the GVD as ridge cells and the distance field as values.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

  // The cells of the climb from `cell` (a free cell) by the rule above: `cell` first; the last is
  // on the GVD unless the climb stopped at a cell off it with no larger neighbour.
  std::vector<GridCell> climb(GridCell cell) const;

  const Raster& raster() const;
  const Brushfire& brushfire() const;
  // The grid graph the search runs on: moves of the 8-connected grid without corner cutting
  // between GVD cells only.
  const GridGraph& gvd_graph() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using GvdGridPlanner = BasicGvdGridPlanner<TranslatingRobot>;
using RoundGvdGridPlanner = BasicGvdGridPlanner<RoundRobot>;

// The registries' `gvd-grid` (TranslatingRobot, RoundRobot): options resolution (100), search, weight.
template <class Space>
PlannerEntry<Space> gvd_grid_planner_entry();

}  // namespace polyplan
