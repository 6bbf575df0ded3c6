#include <polyplan/grids/raster_grid.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/round_query.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_trace.hpp>

#include <utility>

namespace polyplan {
namespace {

std::pair<std::size_t, std::size_t> xy_of(const Raster& r, GridCell c) {
  return {static_cast<std::size_t>(c % r.cells_per_axis), static_cast<std::size_t>(c / r.cells_per_axis)};
}

// Appends p unless it repeats the last point (a start that is its cell's centre): a zero-length
// segment says nothing.
void append(std::vector<ExactPoint>& path, const ExactPoint& p) {
  if (path.empty() || !(path.back() == p)) path.push_back(p);
}

}  // namespace

std::vector<GridAxis> raster_axes(const Raster& r) {
  const auto n = static_cast<std::int64_t>(r.cells_per_axis);
  return {{n, AxisKind::bounded, to_double(r.cell_width())}, {n, AxisKind::bounded, to_double(r.cell_height())}};
}

GridGraph raster_graph(const Raster& r, const GridConventions& conventions) {
  if (!conventions.diagonal_cost.is_sqrt2() && r.cell_width() != r.cell_height())
    throw InputError("diagonal-cost " + conventions.diagonal_cost.text() +
                     ": a number needs square cells, and these are not (the bounds are not square): use sqrt2");
  GridGraph graph(raster_axes(r), conventions.connectivity, StepCost::euclidean, raster_free_cells(r));
  set_diagonals(graph, conventions);
  return graph;
}

void record_grid_conventions(Facts& facts, const GridConventions& conventions) {
  facts.set(RasterFacts::connectivity, conventions.connectivity == Connectivity::full ? 8 : 4);
  facts.set(RasterFacts::corner_cutting, conventions.corner_cutting);
  facts.set(RasterFacts::diagonal_cost, conventions.diagonal_cost.text());
}

std::vector<std::uint8_t> raster_free_cells(const Raster& r) {
  std::vector<std::uint8_t> free(r.blocked.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = r.blocked[i] ? 0 : 1;
  return free;
}

// Octile is exact on an empty 8-connected grid of square cells but overestimates when cells are
// not square (a diagonal then costs less than max + 0.414 min), where the Euclidean distance is
// the safe choice (such cells keep the Euclidean diagonal); 4-connected paths, and paths whose
// diagonals cost 2 or more, cost the sum of the axes.
GridMetric raster_metric(const Raster& r, const GridGraph& graph) {
  if (r.cell_width() != r.cell_height() && graph.connectivity() == Connectivity::full) return GridMetric::euclidean;
  return square_grid_metric(graph);
}

std::size_t move_count(const GridGraph& g) {
  std::size_t twice = 0;
  for (GridCell c = 0; c < g.cell_count(); ++c)
    if (g.is_free(c))
      for (auto [e, end] = out_edges(c, g); e != end; ++e) ++twice;
  return twice / 2;
}

std::string cell_text(std::size_t x, std::size_t y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

std::string cell_text(const Raster& r, GridCell c) {
  const auto [x, y] = xy_of(r, c);
  return cell_text(x, y);
}

FactCell cell_fact(std::size_t x, std::size_t y) { return {std::int64_t(x), std::int64_t(y)}; }

FactCell cell_fact(const Raster& r, GridCell c) {
  const auto [x, y] = xy_of(r, c);
  return cell_fact(x, y);
}

namespace {

// What both snap_query overloads do once the exact world has said whether start and goal are free.
std::optional<std::pair<GridCell, GridCell>> snap_free_query(const std::optional<std::string>& not_free,
                                                             const Raster& r, const Query& query,
                                                             PlanReport<ExactPoint>& report) {
  if (not_free) {
    report.fail(PlanStatus::invalid_query, *not_free);
    return std::nullopt;
  }
  const auto start_cell = nearest_free_cell(r, query.start), goal_cell = nearest_free_cell(r, query.goal);
  if (!start_cell || !goal_cell) {
    report.fail(PlanStatus::not_found, "every cell of the raster is blocked");
    return std::nullopt;
  }
  report.facts.set(RasterFacts::start_cell, cell_fact(start_cell->first, start_cell->second));
  report.facts.set(RasterFacts::goal_cell, cell_fact(goal_cell->first, goal_cell->second));
  const auto index = [&](std::pair<std::size_t, std::size_t> c) {
    return GridCell{c.first + c.second * r.cells_per_axis};
  };
  return std::pair<GridCell, GridCell>(index(*start_cell), index(*goal_cell));
}

// What both return_if_valid overloads do with the exact check's answer.
void return_checked(const PathCheck& check, std::vector<ExactPoint> path, std::string_view what,
                    std::string_view certified_by, PlanReport<ExactPoint>& report) {
  if (!check.valid) {
    report.fail(PlanStatus::not_found, std::string(what) + " is not a valid motion: " + check.reason);
    return;
  }
  report.succeed();
  report.path = std::move(path);
  report.length = euclidean_length(report.path);
  report.certificate = {true, std::string(certified_by)};
}

}  // namespace

std::optional<std::pair<GridCell, GridCell>> snap_query(const CSpace& cspace, const Raster& r, const Query& query,
                                                        PlanReport<ExactPoint>& report) {
  return snap_free_query(cspace.query_not_free(query), r, query, report);
}

std::optional<std::pair<GridCell, GridCell>> snap_query(const RoundWorld& world, const Raster& r, const Query& query,
                                                        PlanReport<ExactPoint>& report) {
  return snap_free_query(query_not_free(world, query), r, query, report);
}

// A cell is a corner of the polyline only where the move direction changes.
std::vector<ExactPoint> polyline_through_turns(const Raster& r, const ExactPoint& start,
                                               std::span<const GridCell> cells, const ExactPoint& goal) {
  const auto move = [&](std::size_t k) {  // from cells[k - 1] to cells[k]
    const auto [x0, y0] = xy_of(r, cells[k - 1]);
    const auto [x1, y1] = xy_of(r, cells[k]);
    return std::pair<long, long>(static_cast<long>(x1) - static_cast<long>(x0),
                                 static_cast<long>(y1) - static_cast<long>(y0));
  };
  std::vector<ExactPoint> path;
  append(path, start);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const bool straight_through = k > 0 && k + 1 < cells.size() && move(k) == move(k + 1);
    if (!straight_through) {
      const auto [x, y] = xy_of(r, cells[k]);
      append(path, r.cell_center(x, y));
    }
  }
  append(path, goal);
  return path;
}

PathCheck check_exactly(const CSpace& cspace, const std::vector<ExactPoint>& path) { return check_path(cspace, path); }

PathCheck check_exactly(const RoundWorld& world, const std::vector<ExactPoint>& path) { return world.check_path(path); }

std::string_view exact_check_name(const CSpace&) { return "exact path check (arrangement zone walk)"; }

std::string_view exact_check_name(const RoundWorld&) {
  return "exact rational path check among discs, walls and polygons";
}

void return_if_valid(const CSpace& cspace, std::vector<ExactPoint> path, std::string_view what,
                     PlanReport<ExactPoint>& report) {
  const PathCheck check = check_exactly(cspace, path);
  return_checked(check, std::move(path), what, exact_check_name(cspace), report);
}

void return_if_valid(const RoundWorld& world, std::vector<ExactPoint> path, std::string_view what,
                     PlanReport<ExactPoint>& report) {
  const PathCheck check = check_exactly(world, path);
  return_checked(check, std::move(path), what, exact_check_name(world), report);
}

void report_search(const Raster& r, const SearchResult<GridCell>& search, PlanReport<ExactPoint>& report) {
  report.facts.set(SearchFacts::expanded, search.expanded);
  report.facts.set(SearchFacts::generated, search.generated);
  report.facts.set(SearchFacts::path_edges, search.path_edges());
  report.facts.set(SearchFacts::seconds, search.seconds);
  const auto centre = [&r](GridCell c) {
    const auto [x, y] = xy_of(r, c);
    return r.cell_center(x, y);
  };
  for (const GridCell c : search.expanded_order) report.recording.expanded.push_back(centre(c));
  report.recording.trace = plan_trace<ExactPoint>(search.trace, centre);
}

CellGrid raster_cell_grid(const Raster& r) {
  CellGrid grid;
  grid.columns = grid.rows = r.cells_per_axis;
  grid.x0 = to_double(r.bounds.xmin);
  grid.y0 = to_double(r.bounds.ymin);
  grid.cell_width = to_double(r.cell_width());
  grid.cell_height = to_double(r.cell_height());
  grid.states.resize(r.blocked.size());
  for (std::size_t i = 0; i < r.blocked.size(); ++i) grid.states[i] = r.blocked[i] ? CellGrid::blocked : CellGrid::free;
  return grid;
}

}  // namespace polyplan
