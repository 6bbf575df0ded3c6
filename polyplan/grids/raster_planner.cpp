#include <polyplan/grids/raster_planner.hpp>

#include <polyplan/geometry/round_rasterize.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/raster_grid.hpp>
#include <polyplan/plan/grid_options.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/graph_search.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {

template <class Space>
struct BasicRasterPlanner<Space>::Impl {
  const typename Space::Problem* world;
  RasterOptions options;
  Raster raster;
  GridGraph graph;
  std::size_t free_cells = 0, moves = 0;
  double build_seconds = 0;
  std::shared_ptr<const CellGrid> picture;  // made for the first query that records

  Impl(const typename Space::Problem& w, const RasterOptions& o)
      : world(&w), options(o), raster(rasterize(w, o.resolution)), graph(raster_graph(raster, o.conventions())),
        free_cells(raster.blocked.size() - raster.blocked_count()), moves(move_count(graph)) {}

  std::shared_ptr<const CellGrid> cells() {
    if (!picture) picture = std::make_shared<const CellGrid>(raster_cell_grid(raster));
    return picture;
  }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, "raster");
    facts.set(RoadmapFacts::vertices, free_cells);
    facts.set(RoadmapFacts::edges, moves);
    facts.set(RoadmapFacts::seconds, build_seconds);
    facts.set(RasterFacts::cells_per_axis, raster.cells_per_axis);
    facts.set(RasterFacts::blocked_cells, raster.blocked_count());
    record_grid_conventions(facts, options.conventions());
    facts.set(SearchFacts::algorithm, to_string(options.search.algorithm));
  }
};

template <class Space>
BasicRasterPlanner<Space>::BasicRasterPlanner(const typename Space::Problem& world, RasterOptions options)
    : impl_(build_timed<Impl>(world, options)) {}

template <class Space>
BasicRasterPlanner<Space>::~BasicRasterPlanner() = default;

template <class Space>
const Raster& BasicRasterPlanner<Space>::raster() const {
  return impl_->raster;
}

template <class Space>
const GridGraph& BasicRasterPlanner<Space>::graph() const {
  return impl_->graph;
}

template <class Space>
std::optional<std::pair<std::size_t, std::size_t>> BasicRasterPlanner<Space>::nearest_free_cell(
    const ExactPoint& p) const {
  return polyplan::nearest_free_cell(impl_->raster, p);
}

template <class Space>
PlanReport<ExactPoint> BasicRasterPlanner<Space>::plan(const Query& query, const QueryOptions& options) {
  Impl& r = *impl_;
  return grid_query(r.raster, [&](PlanReport<ExactPoint>& report, SearchResult<GridCell>& search) {
    r.record_facts(report.facts);
    if (options.record) report.recording.cells = r.cells();

    const auto snapped = snap_query(*r.world, r.raster, query, report);
    if (!snapped) return;
    const auto [from, to] = *snapped;
    const GridGraph& g = r.graph;
    SearchOptions searching = r.options.search;
    searching.record_expanded = options.record;
    searching.record_trace = options.trace;
    search = shortest_path(g, from, to, searching, GridDistanceTo(g, to, raster_metric(r.raster, g)), GridMoveCost{&g});
    if (!search.found) {
      const std::string n = std::to_string(r.raster.cells_per_axis);
      report.fail(PlanStatus::not_found, "no path on the " + n + " x " + n + " grid from cell " +
                                             cell_text(r.raster, from) + " to cell " + cell_text(r.raster, to));
      return;
    }
    report.facts.set(RasterFacts::grid_cost, search.cost);

    return_if_valid(*r.world, polyline_through_turns(r.raster, query.start, search.path, query.goal),
                    "the grid path joined to start and goal", report);
  });
}

template <class Space>
PlannerEntry<Space> raster_planner_entry() {
  OptionTable<RasterOptions> table;
  table.add("resolution", &RasterOptions::resolution, "cells per side of the bounds (n x n cells)",
            in_range(1, static_cast<double>(max_cells_per_axis)));
  add_grid_options(
      table, [](auto& o) -> auto& { return o.connectivity; }, [](auto& o) -> auto& { return o.corner_cutting; },
      [](auto& o) -> auto& { return o.diagonal_cost; });
  add_search_options(table, &RasterOptions::search);
  return make_planner_entry<Space, RasterOptions>(
      "raster",
      "the course's graph-search homework's occupancy grid: the bounds cut into n x n exact cells, searched "
      "8-connected",
      std::move(table), [](const typename Space::Problem& world, const RasterOptions& o) {
        return std::make_unique<BasicRasterPlanner<Space>>(world, o);
      });
}

template class BasicRasterPlanner<TranslatingRobot>;
template class BasicRasterPlanner<RoundRobot>;
template PlannerEntry<TranslatingRobot> raster_planner_entry<TranslatingRobot>();
template PlannerEntry<RoundRobot> raster_planner_entry<RoundRobot>();

}  // namespace polyplan
