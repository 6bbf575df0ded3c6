#include <polyplan/roadmaps/raster_planner.hpp>

#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/roadmaps/stopwatch.hpp>
#include <polyplan/search/graph_search.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

Rational cell_width(const Raster& r) { return (r.bounds.xmax - r.bounds.xmin) / Rational(mpz_class(r.cells_per_axis)); }
Rational cell_height(const Raster& r) { return (r.bounds.ymax - r.bounds.ymin) / Rational(mpz_class(r.cells_per_axis)); }

// Steps in world units, so that search costs are lengths (a non-square cell's diagonal included).
std::vector<GridAxis> axes_of(const Raster& r) {
  const auto n = static_cast<std::int64_t>(r.cells_per_axis);
  return {{n, AxisKind::bounded, to_double(cell_width(r))}, {n, AxisKind::bounded, to_double(cell_height(r))}};
}

std::vector<std::uint8_t> free_cells_of(const Raster& r) {
  std::vector<std::uint8_t> free(r.blocked.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = r.blocked[i] ? 0 : 1;
  return free;
}

// The tightest admissible heuristic: octile is exact on an empty 8-connected grid of square cells
// but overestimates when cells are not square (a diagonal then costs less than max + 0.414 min),
// where the Euclidean distance is the safe choice; 4-connected paths cost the sum of the axes.
GridMetric metric_for(const Raster& r, Connectivity connectivity) {
  if (connectivity == Connectivity::axis_aligned) return GridMetric::sum_of_axes;
  return cell_width(r) == cell_height(r) ? GridMetric::octile : GridMetric::euclidean;
}

// Appends p unless it repeats the last point (a start that is its cell's centre): a zero-length
// segment says nothing.
void append(std::vector<ExactPoint>& path, const ExactPoint& p) {
  if (path.empty() || !(path.back() == p)) path.push_back(p);
}


// Moves of the grid graph between free cells, each counted once (the graph is undirected).
std::size_t move_count(const GridGraph& g) {
  std::size_t twice = 0;
  for (GridCell c = 0; c < g.cell_count(); ++c)
    if (g.is_free(c))
      for (auto [e, end] = out_edges(c, g); e != end; ++e) ++twice;
  return twice / 2;
}

std::string cell_text(std::size_t x, std::size_t y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

}  // namespace

struct RasterPlanner::Impl {
  const CSpace* cspace;
  RasterOptions options;
  Raster raster;
  GridGraph graph;
  std::size_t free_cells = 0, moves = 0;
  double build_seconds = 0;
  std::shared_ptr<const CellGrid> picture;  // made for the first query that records

  Impl(const CSpace& c, const RasterOptions& o)
      : cspace(&c),
        options(o),
        raster(rasterize(c, o.resolution)),
        graph(axes_of(raster), o.connectivity, StepCost::euclidean, free_cells_of(raster)),
        free_cells(raster.blocked.size() - raster.blocked_count()),
        moves(move_count(graph)) {}

  std::shared_ptr<const CellGrid> cells() {
    if (picture) return picture;
    auto grid = std::make_shared<CellGrid>();
    grid->columns = grid->rows = raster.cells_per_axis;
    grid->x0 = to_double(raster.bounds.xmin);
    grid->y0 = to_double(raster.bounds.ymin);
    grid->cell_width = to_double(cell_width(raster));
    grid->cell_height = to_double(cell_height(raster));
    grid->states.resize(raster.blocked.size());
    for (std::size_t i = 0; i < raster.blocked.size(); ++i)
      grid->states[i] = raster.blocked[i] ? CellGrid::blocked : CellGrid::free;
    picture = std::move(grid);
    return picture;
  }

  void record_facts(Facts& facts) const {
    facts.set("roadmap.kind", "raster");
    facts.set("roadmap.vertices", free_cells);
    facts.set("roadmap.edges", moves);
    facts.set("roadmap.seconds", build_seconds);
    facts.set("raster.cells_per_axis", raster.cells_per_axis);
    facts.set("raster.blocked_cells", raster.blocked_count());
    facts.set("search.algorithm", to_string(options.search.algorithm));
  }
};

RasterPlanner::RasterPlanner(const CSpace& cspace, RasterOptions options) {
  const Stopwatch building;
  impl_ = std::make_unique<Impl>(cspace, options);
  impl_->build_seconds = building.seconds();
}

RasterPlanner::~RasterPlanner() = default;

const Raster& RasterPlanner::raster() const { return impl_->raster; }
const GridGraph& RasterPlanner::graph() const { return impl_->graph; }

// An exact search in square rings of cells around p's cell (clamped into the grid), rather than a
// KD-tree in doubles: the distances are compared exactly, so ties — frequent, since starts are
// often round numbers halfway between centres — are broken by the documented rule and not by
// rounding, and the grid's arithmetic gives the neighbourhood with no index to build. A cell in
// ring r has a centre at least (r - 1/2) cell sides from p along one axis, which stops the search.
std::optional<std::pair<std::size_t, std::size_t>> RasterPlanner::nearest_free_cell(const ExactPoint& p) const {
  const Raster& r = impl_->raster;
  const long n = static_cast<long>(r.cells_per_axis);
  const Rational w = cell_width(r), h = cell_height(r);
  const Rational u = (p.x - r.bounds.xmin) / w, v = (p.y - r.bounds.ymin) / h;  // grid coordinates
  auto cell_of = [n](const Rational& t) -> long {
    if (t < 0) return 0;
    if (t >= n) return n - 1;
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), t.get_num_mpz_t(), t.get_den_mpz_t());
    return f.get_si();
  };
  const long i0 = cell_of(u), j0 = cell_of(v);
  const Rational shorter_side_squared = std::min(w, h) * std::min(w, h);
  const Rational half(1, 2);

  std::optional<std::pair<long, long>> best;
  Rational best_distance2;
  auto consider = [&](long i, long j) {
    if (i < 0 || j < 0 || i >= n || j >= n || r.is_blocked(i, j)) return;
    const Rational du = (i + half - u) * w, dv = (j + half - v) * h;
    const Rational d2 = du * du + dv * dv;
    const bool lower_index = best && (j < best->second || (j == best->second && i < best->first));
    if (!best || d2 < best_distance2 || (d2 == best_distance2 && lower_index)) {
      best = {i, j};
      best_distance2 = d2;
    }
  };
  for (long ring = 0; ring < n; ++ring) {
    if (best && ring >= 1) {
      const Rational reach = ring - half;
      if (reach * reach * shorter_side_squared > best_distance2) break;
    }
    for (long j = j0 - ring; j <= j0 + ring; ++j) {
      if (j == j0 - ring || j == j0 + ring) {
        for (long i = i0 - ring; i <= i0 + ring; ++i) consider(i, j);
      } else {
        consider(i0 - ring, j);
        consider(i0 + ring, j);
      }
    }
  }
  if (!best) return std::nullopt;
  return std::pair<std::size_t, std::size_t>(best->first, best->second);
}

PlanReport<ExactPoint> RasterPlanner::plan(const Query& query, const QueryOptions& options) {
  Impl& r = *impl_;
  const Stopwatch querying;
  PlanReport<ExactPoint> report;
  r.record_facts(report.facts);
  if (options.record) report.cells = r.cells();
  SearchResult<GridCell> search;
  const auto finish = [&]() {
    report.facts.set("search.expanded", search.expanded);
    report.facts.set("search.generated", search.generated);
    report.facts.set("search.path_edges", search.path_edges());
    report.facts.set("search.seconds", search.seconds);
    report.facts.set("query_seconds", querying.seconds());
    return report;
  };

  if (auto why = r.cspace->query_not_free(query)) {
    report.why_not = *why;
    return finish();
  }
  const auto start_cell = nearest_free_cell(query.start), goal_cell = nearest_free_cell(query.goal);
  if (!start_cell || !goal_cell) {
    report.why_not = "every cell of the raster is blocked";
    return finish();
  }
  report.facts.set("raster.start_cell", cell_text(start_cell->first, start_cell->second));
  report.facts.set("raster.goal_cell", cell_text(goal_cell->first, goal_cell->second));

  const GridGraph& g = r.graph;
  auto cell_id = [&](std::pair<std::size_t, std::size_t> cell) {
    return g.cell({static_cast<GridCoordinate>(cell.first), static_cast<GridCoordinate>(cell.second)});
  };
  const GridCell from = cell_id(*start_cell), to = cell_id(*goal_cell);
  SearchOptions searching = r.options.search;
  searching.record_expanded = options.record;
  search = shortest_path(g, from, to, searching, GridDistanceTo(g, to, metric_for(r.raster, g.connectivity())), GridMoveCost{&g});
  for (const GridCell c : search.expanded_order) {
    const auto at = g.coordinates(c);
    report.expanded.push_back(r.raster.cell_center(static_cast<std::size_t>(at[0]), static_cast<std::size_t>(at[1])));
  }
  if (!search.found) {
    const std::string n = std::to_string(r.raster.cells_per_axis);
    report.why_not = "no path on the " + n + " x " + n + " grid from cell " +
                     cell_text(start_cell->first, start_cell->second) + " to cell " +
                     cell_text(goal_cell->first, goal_cell->second);
    return finish();
  }
  report.facts.set("raster.grid_cost", search.cost);

  // A cell is a corner of the polyline only where the move direction changes.
  std::vector<ExactPoint> path;
  std::vector<std::vector<GridCoordinate>> cells;
  for (const GridCell c : search.path) cells.push_back(g.coordinates(c));
  append(path, query.start);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const bool straight_through = k > 0 && k + 1 < cells.size() && cells[k][0] - cells[k - 1][0] == cells[k + 1][0] - cells[k][0] &&
                                  cells[k][1] - cells[k - 1][1] == cells[k + 1][1] - cells[k][1];
    if (!straight_through)
      append(path, r.raster.cell_center(static_cast<std::size_t>(cells[k][0]), static_cast<std::size_t>(cells[k][1])));
  }
  append(path, query.goal);

  const PathCheck check = check_path(*r.cspace, path);
  if (!check.valid) {
    report.why_not = "the grid path joined to start and goal is not a valid motion: " + check.reason;
    return finish();
  }
  report.found = true;
  report.path = std::move(path);
  report.length = euclidean_length(report.path);
  report.certificate = {true, "exact path check (arrangement zone walk)"};
  return finish();
}

PlannerEntry<TranslatingRobot> raster_planner_entry() {
  OptionTable<RasterOptions> table;
  table.add("resolution", &RasterOptions::resolution, "cells per side of the bounds (n x n cells)");
  table.add("connectivity", &RasterOptions::connectivity, "8: moves to all 8 neighbours without cutting corners; 4: axis moves only",
            std::vector<std::pair<std::string, Connectivity>>{{"8", Connectivity::full}, {"4", Connectivity::axis_aligned}});
  add_search_options(table, &RasterOptions::search);
  return make_planner_entry<TranslatingRobot, RasterOptions>(
      "raster", "seed 000's occupancy grid: the bounds cut into n x n exact cells, searched 8-connected",
      std::move(table), [](const CSpace& cspace, const RasterOptions& o) {
        return std::make_unique<RasterPlanner>(cspace, o);
      });
}

}  // namespace polyplan
