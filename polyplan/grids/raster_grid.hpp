#pragma once
// What the grid planners (`raster`, `gvd-grid`; of polygon worlds and of round ones) share about a Raster
// (geometry/rasterize.hpp) searched as an implicit grid graph (search/grid_graph.hpp): the axes
// in world units, the free cells as a bitmap, the tightest admissible heuristic, the polyline
// through the cells where a grid path turns, the exact check that decides whether that polyline
// is returned, and the picture of the cells. Cell indices are the raster's, x + y·n, which are
// also the grid graph's (axis 0 varies fastest).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace polyplan {

// Two axes of n cells, each step the cell's side in world units, so that search costs are
// lengths (a non-square cell's diagonal included).
std::vector<GridAxis> raster_axes(const Raster& raster);

// The grid graph of the raster's free cells with the conventions' moves. Throws InputError for a
// diagonal cost given as a number on cells that are not square.
GridGraph raster_graph(const Raster& raster, const GridConventions& conventions);

// The conventions as facts (RasterFacts::connectivity, corner_cutting, diagonal_cost).
void record_grid_conventions(Facts& facts, const GridConventions& conventions);

// 1 for each free cell of the raster, 0 for each blocked one: the grid graph's bitmap.
std::vector<std::uint8_t> raster_free_cells(const Raster& raster);

// The tightest admissible heuristic for the moves of `graph` (its connectivity and diagonals) over
// the raster's cells.
GridMetric raster_metric(const Raster& raster, const GridGraph& graph);

// The moves of the graph between free cells that it allows, each counted once (every move has
// its reverse).
std::size_t move_count(const GridGraph& graph);

// "(x, y)": how messages name a cell.
std::string cell_text(std::size_t x, std::size_t y);
std::string cell_text(const Raster& raster, GridCell cell);
// The same cells as a fact's (column, row).
FactCell cell_fact(std::size_t x, std::size_t y);
FactCell cell_fact(const Raster& raster, GridCell cell);

// The counts of a grid search as the facts every planner reports (search.expanded, ...), and the
// centres of the cells it expanded (for the picture) and its trace (when recorded).
void report_search(const Raster& raster, const SearchResult<GridCell>& search, PlanReport<ExactPoint>& report);

// A grid planner's query: `answer(report, search)` plans (and may return early with why_not
// set); then the search's counts are reported (report_search) and the query's time as
// query_seconds, whatever the answer.
template <class Answer>
PlanReport<ExactPoint> grid_query(const Raster& raster, Answer&& answer) {
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  SearchResult<GridCell> search;
  answer(report, search);
  report_search(raster, search, report);
  report.facts.set(QueryFacts::seconds, querying.seconds());
  return report;
}

// The first step of a grid planner's query: a start or goal that is not free
// (CSpace::query_not_free, or RoundWorld::config_not_free of each), or a raster without a free
// cell, is an answer — nullopt, why_not set. Otherwise the cells that start and goal snap to
// (nearest_free_cell), also reported as the facts raster.start_cell and raster.goal_cell.
std::optional<std::pair<GridCell, GridCell>> snap_query(const CSpace& cspace, const Raster& raster, const Query& query,
                                                        PlanReport<ExactPoint>& report);
std::optional<std::pair<GridCell, GridCell>> snap_query(const RoundWorld& world, const Raster& raster,
                                                        const Query& query, PlanReport<ExactPoint>& report);

// start → the centres of the cells where the grid path turns → goal (a repeated point once).
std::vector<ExactPoint> polyline_through_turns(const Raster& raster, const ExactPoint& start,
                                               std::span<const GridCell> cells, const ExactPoint& goal);

// The exact check of a polyline in either space (geometry/path_check.hpp's check_path, or
// RoundWorld::check_path), and what a certificate calls it: one name for the grid planners that
// are templates over the space.
PathCheck check_exactly(const CSpace& cspace, const std::vector<ExactPoint>& path);
PathCheck check_exactly(const RoundWorld& world, const std::vector<ExactPoint>& path);
std::string_view exact_check_name(const CSpace& cspace);
std::string_view exact_check_name(const RoundWorld& world);

// Returns `path` in `report` (found, length, certificate) when it passes the exact check_path
// (geometry/path_check.hpp's, or RoundWorld::check_path); otherwise found stays false and why_not
// says "`what` is not a valid motion: " and the check's reason. A grid path's joins to the exact
// start and goal can cross a corner that the cells did not see, so the whole polyline is checked,
// never the cells only.
void return_if_valid(const CSpace& cspace, std::vector<ExactPoint> path, std::string_view what,
                     PlanReport<ExactPoint>& report);
void return_if_valid(const RoundWorld& world, std::vector<ExactPoint> path, std::string_view what,
                     PlanReport<ExactPoint>& report);

// The raster's cells as a picture shows them: free or blocked, no values.
CellGrid raster_cell_grid(const Raster& raster);

}  // namespace polyplan
