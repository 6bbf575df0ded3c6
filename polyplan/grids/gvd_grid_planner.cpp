#include <polyplan/grids/gvd_grid_planner.hpp>

#include <polyplan/geometry/clearance.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/round_rasterize.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/raster_grid.hpp>
#include <polyplan/plan/grid_options.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/graph_search.hpp>

#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

namespace polyplan {

namespace {

// The conventions of the search along the GVD, which 4 neighbours could split.
GridConventions along_gvd(const GridConventions& grid) {
  if (grid.connectivity == Connectivity::axis_aligned)
    throw InputError(
        "gvd-grid: connectivity 4: the GVD is joined by 8-connected moves (corner-cutting and "
        "diagonal-cost apply)");
  return grid;
}

}  // namespace

template <class Space>
struct BasicGvdGridPlanner<Space>::Impl {
  const typename Space::Problem* world;
  GvdGridOptions options;
  Raster raster;
  Brushfire field;
  GridGraph free_graph;  // every move between free cells: what the climbs take
  GridGraph gvd_graph;   // the same moves between GVD cells only: what the search takes
  std::size_t gvd_moves = 0;
  double build_seconds = 0;
  std::shared_ptr<const CellGrid> picture;  // made for the first query that records

  Impl(const typename Space::Problem& w, const GvdGridOptions& o)
      : world(&w), options(o), raster(rasterize(w, o.resolution)),
        field(polyplan::brushfire(raster.cells_per_axis, raster.cells_per_axis, raster.blocked, raster.walls)),
        free_graph(raster_axes(raster), Connectivity::full, StepCost::euclidean, raster_free_cells(raster)),
        gvd_graph(raster_graph(raster, along_gvd(o.grid))) {
    // The bitmap keeps the corner rule of the free cells (a diagonal move between GVD cells may
    // pass free cells off the GVD, never a blocked one); the test keeps the moves on the GVD.
    gvd_graph.set_move_test([gvd = &field.gvd](GridCell from, GridCell to) { return (*gvd)[from] && (*gvd)[to]; });
    gvd_moves = move_count(gvd_graph);
  }

  std::shared_ptr<const CellGrid> cells() {
    if (picture) return picture;
    auto grid = std::make_shared<CellGrid>(raster_cell_grid(raster));
    grid->values.assign(field.distance.begin(), field.distance.end());
    grid->value_name = "brushfire distance to the nearest obstacle (cells)";
    for (std::size_t i = 0; i < field.gvd.size(); ++i)
      if (field.gvd[i]) grid->states[i] = CellGrid::ridge;
    picture = std::move(grid);
    return picture;
  }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, "gvd-grid");
    facts.set(RoadmapFacts::vertices, field.gvd_cells);
    facts.set(RoadmapFacts::edges, gvd_moves);
    facts.set(RoadmapFacts::seconds, build_seconds);
    facts.set(RasterFacts::cells_per_axis, raster.cells_per_axis);
    record_grid_conventions(facts, options.grid);
    facts.set(GvdFacts::cells, field.gvd_cells);
    facts.set(GvdFacts::max_distance, field.max_distance);
    facts.set(SearchFacts::algorithm, to_string(options.search.algorithm));
  }

  // A lower bound on the distance from the centre of a cell at brushfire distance d to the
  // C-obstacles and walls: every cell nearer than d is free (brushfire.hpp).
  double clearance_of(std::uint32_t d) const {
    return (static_cast<double>(d) - 0.5) * std::min(to_double(raster.cell_width()), to_double(raster.cell_height()));
  }
};

template <class Space>
BasicGvdGridPlanner<Space>::BasicGvdGridPlanner(const typename Space::Problem& world, GvdGridOptions options)
    : impl_(build_timed<Impl>(world, options)) {}

template <class Space>
BasicGvdGridPlanner<Space>::~BasicGvdGridPlanner() = default;

template <class Space>
const Raster& BasicGvdGridPlanner<Space>::raster() const {
  return impl_->raster;
}

template <class Space>
const Brushfire& BasicGvdGridPlanner<Space>::brushfire() const {
  return impl_->field;
}

template <class Space>
const GridGraph& BasicGvdGridPlanner<Space>::gvd_graph() const {
  return impl_->gvd_graph;
}

template <class Space>
std::vector<GridCell> BasicGvdGridPlanner<Space>::climb(GridCell cell) const {
  const Brushfire& f = impl_->field;
  std::vector<GridCell> cells{cell};
  while (!f.gvd[cell]) {
    // The best neighbour: on the GVD first, then of largest distance, then of lowest index.
    const auto better = [&](GridCell a, GridCell b) {
      if (f.gvd[a] != f.gvd[b]) return f.gvd[a] > f.gvd[b];
      if (f.distance[a] != f.distance[b]) return f.distance[a] > f.distance[b];
      return a < b;
    };
    GridCell best = cell;
    for (auto [e, end] = out_edges(cell, impl_->free_graph); e != end; ++e)
      if (const GridCell next = (*e).target; best == cell || better(next, best)) best = next;
    if (best == cell || (!f.gvd[best] && f.distance[best] <= f.distance[cell])) break;
    cells.push_back(cell = best);
  }
  return cells;
}

template <class Space>
PlanReport<ExactPoint> BasicGvdGridPlanner<Space>::plan(const Query& query, const QueryOptions& options) {
  Impl& r = *impl_;
  return grid_query(r.raster, [&](PlanReport<ExactPoint>& report, SearchResult<GridCell>& search) {
    r.record_facts(report.facts);
    if (options.record) report.recording.cells = r.cells();

    const auto snapped = snap_query(*r.world, r.raster, query, report);
    if (!snapped) return;
    const std::vector<GridCell> up = climb(snapped->first), down = climb(snapped->second);
    for (const auto& [climbed, what] : {std::pair{&up, "start"}, std::pair{&down, "goal"}}) {
      if (r.field.gvd[climbed->back()]) continue;
      report.fail(PlanStatus::not_found,
                  std::string("the climb from the ") + what + "'s cell " + cell_text(r.raster, climbed->front()) +
                      " up the distance field stops at cell " + cell_text(r.raster, climbed->back()) +
                      ", a local maximum off the GVD (the brushfire's GVD failed to reach it: a bug to report)");
      return;
    }
    report.facts.set(GvdFacts::start_cell, cell_fact(r.raster, up.back()));
    report.facts.set(GvdFacts::goal_cell, cell_fact(r.raster, down.back()));

    const auto search_between = [&](const GridGraph& g, const SearchOptions& searching) {
      return shortest_path(g, up.back(), down.back(), searching,
                           GridDistanceTo(g, down.back(), raster_metric(r.raster, g)), GridMoveCost{&g});
    };
    SearchOptions searching = r.options.search;
    searching.record_expanded = options.record;
    searching.record_trace = options.trace;
    search = search_between(r.gvd_graph, searching);
    if (!search.found) {
      // Expected only between two free components of the grid; a second search over all free
      // cells tells that from a GVD that failed to join one component (brushfire.hpp).
      const bool apart = !search_between(r.free_graph, SearchOptions{Search::bfs}).found;
      report.fail(PlanStatus::not_found,
                  "the GVD does not connect cell " + cell_text(r.raster, up.back()) +
                      ", where the start's climb reaches it, to cell " + cell_text(r.raster, down.back()) +
                      ", where the goal's does" +
                      (apart ? ": they lie in different free components of the grid"
                             : ", though free cells do (the brushfire's GVD failed to join them: a bug to report)"));
      return;
    }

    // Up from the start, along the GVD, down to the goal (the goal's climb reversed).
    std::vector<GridCell> cells = up;
    cells.insert(cells.end(), search.path.begin() + 1, search.path.end());
    cells.insert(cells.end(), down.rbegin() + 1, down.rend());
    std::uint32_t nearest = std::numeric_limits<std::uint32_t>::max();
    for (const GridCell c : cells) nearest = std::min(nearest, r.field.distance[c]);

    return_if_valid(*r.world, polyline_through_turns(r.raster, query.start, cells, query.goal),
                    "the GVD path joined to start and goal", report);
    if (report.found) {
      report.facts.set(GvdFacts::clearance_bound, r.clearance_of(nearest));
      // The shared word means the same for every planner: measured on the returned path (among
      // polygons only: geometry/clearance.hpp measures a C-space).
      if constexpr (std::is_same_v<Space, TranslatingRobot>) {
        const PathBottleneck narrowest = path_bottleneck(*r.world, report.path);
        report.bottleneck = Bottleneck{narrowest.at.x, narrowest.at.y, narrowest.clearance};
      }
    }
  });
}

template <class Space>
PlannerEntry<Space> gvd_grid_planner_entry() {
  OptionTable<GvdGridOptions> table;
  table.add("resolution", &GvdGridOptions::resolution, "cells per side of the bounds (n x n cells)",
            in_range(1, static_cast<double>(max_cells_per_axis)));
  add_search_options(table, &GvdGridOptions::search);
  add_grid_conventions(
      table, [](auto& o) -> auto& { return o.grid; });
  return make_planner_entry<Space, GvdGridOptions>(
      "gvd-grid", "brushfire GVD on the n x n occupancy grid: climb the distance field, follow the GVD, descend",
      std::move(table), [](const typename Space::Problem& world, const GvdGridOptions& o) {
        return std::make_unique<BasicGvdGridPlanner<Space>>(world, o);
      });
}

template class BasicGvdGridPlanner<TranslatingRobot>;
template class BasicGvdGridPlanner<RoundRobot>;
template PlannerEntry<TranslatingRobot> gvd_grid_planner_entry<TranslatingRobot>();
template PlannerEntry<RoundRobot> gvd_grid_planner_entry<RoundRobot>();

}  // namespace polyplan
