#include <polyplan/roadmaps/trapezoid_planner.hpp>

#include <polyplan/free_space/channel_funnel.hpp>
#include <polyplan/free_space/query_frame.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_trace.hpp>
#include <polyplan/plan/query_tally.hpp>
#include <polyplan/roadmaps/roadmap_facts.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <algorithm>
#include <stdexcept>

namespace polyplan {
namespace {

ExactPoint midpoint(const ExactPoint& a, const ExactPoint& b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

bool share_a_cell(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  return std::any_of(a.begin(), a.end(), [&](std::size_t c) { return std::find(b.begin(), b.end(), c) != b.end(); });
}

}  // namespace

struct TrapezoidPlanner::Impl {
  const CSpace* cspace;
  TrapezoidOptions options;
  TrapezoidalDecomposition decomposition;
  Roadmap roadmap;
  RoadmapVertexId start_slot = 0, goal_slot = 0;
  SearchWorkspace<RoadmapVertexId> workspace;
  double build_seconds = 0;
  std::shared_ptr<const PlanGraph<ExactPoint>> graph_picture;  // made for the first query that records
  std::shared_ptr<const PlanDecomposition<ExactPoint>> cells_picture;

  Impl(const CSpace& c, const TrapezoidOptions& o, const std::vector<ExactPoint>& inside)
      : cspace(&c), options(o), decomposition(c, inside) {
    for (const ExactPoint& p : decomposition.centroids()) add_vertex(roadmap, p);
    for (std::size_t w = 0; w < decomposition.walls().size(); ++w) {
      const TrapezoidWall& wall = decomposition.walls()[w];
      const RoadmapVertexId middle = add_vertex(roadmap, midpoint(wall.lower, wall.upper));
      add_edge(roadmap, wall.left, middle);
      add_edge(roadmap, middle, wall.right);
    }
    start_slot = add_vertex(roadmap, {0, 0});
    goal_slot = add_vertex(roadmap, {0, 0});
  }

  std::size_t cell_count() const { return decomposition.cells().size(); }
  // A query slot at p: its edges' lengths and the search's heuristic read the position.
  void place(RoadmapVertexId slot, const ExactPoint& p) {
    roadmap[slot] = RoadmapVertex{p, to_double(p.x), to_double(p.y)};
  }
  bool is_wall_node(RoadmapVertexId v) const { return v >= cell_count() && v < start_slot; }
  const TrapezoidWall& wall_of(RoadmapVertexId v) const { return decomposition.walls()[v - cell_count()]; }

  // The roadmap searched from the query's start, joined to the cells `from` around it, to its
  // goal, joined to the cells `to`; the expanded vertices and the trace added to `report` when
  // `recording` asks for them.
  SearchResult<RoadmapVertexId> search(const Query& query, const std::vector<std::size_t>& from,
                                       const std::vector<std::size_t>& to, const QueryOptions& recording,
                                       PlanReport<ExactPoint>& report) {
    place(start_slot, query.start);
    place(goal_slot, query.goal);
    for (std::size_t c : from) add_edge(roadmap, start_slot, c);
    for (std::size_t c : to) add_edge(roadmap, c, goal_slot);
    SearchOptions searching = options.search;
    searching.record_expanded = recording.record;
    searching.record_trace = recording.trace;
    auto result = shortest_path(roadmap, start_slot, goal_slot, searching, workspace);
    boost::clear_vertex(start_slot, roadmap);
    boost::clear_vertex(goal_slot, roadmap);
    for (RoadmapVertexId v : result.expanded_order) report.recording.expanded.push_back(roadmap[v].exact);
    report.recording.trace =
        plan_trace<ExactPoint>(result.trace, [this](RoadmapVertexId v) { return roadmap[v].exact; });
    return result;
  }

  // The search's path start, centroid, wall midpoint, centroid, ..., goal, as the walls it
  // crosses, each seen from the side the path comes from.
  std::vector<Portal> portals_along(const std::vector<RoadmapVertexId>& nodes) const {
    std::vector<Portal> portals;
    for (std::size_t i = 1; i + 1 < nodes.size(); ++i) {
      if (!is_wall_node(nodes[i])) continue;
      const TrapezoidWall& wall = wall_of(nodes[i]);
      const bool rightwards = nodes[i - 1] == wall.left;  // from the wall's left cell to its right one
      portals.push_back(rightwards ? Portal{wall.upper, wall.lower} : Portal{wall.lower, wall.upper});
    }
    return portals;
  }

  std::shared_ptr<const PlanGraph<ExactPoint>> graph() {
    if (graph_picture) return graph_picture;
    auto g = std::make_shared<PlanGraph<ExactPoint>>();
    g->kind = "roadmap";
    for (RoadmapVertexId v = 0; v < start_slot; ++v) g->vertices.push_back(roadmap[v].exact);
    for (auto [e, end] = boost::edges(roadmap); e != end; ++e) {
      const auto u = boost::source(*e, roadmap), v = boost::target(*e, roadmap);
      if (u < start_slot && v < start_slot) g->edges.emplace_back(u, v);
    }
    graph_picture = std::move(g);
    return graph_picture;
  }

  std::shared_ptr<const PlanDecomposition<ExactPoint>> cells() {
    if (cells_picture) return cells_picture;
    auto d = std::make_shared<PlanDecomposition<ExactPoint>>();
    d->kind = "trapezoids";
    d->cells = decomposition.cells();
    for (const TrapezoidWall& w : decomposition.walls()) d->walls.emplace_back(w.lower, w.upper);
    cells_picture = std::move(d);
    return cells_picture;
  }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, "trapezoid");
    facts.set(RoadmapFacts::vertices, start_slot);
    facts.set(RoadmapFacts::edges, 2 * decomposition.walls().size());
    facts.set(RoadmapFacts::seconds, build_seconds);
    facts.set(TrapezoidFacts::cells, cell_count());
    facts.set(TrapezoidFacts::walls, decomposition.walls().size());
    const SweepCounts& sweep = decomposition.sweep();
    facts.set(TrapezoidFacts::sweep_insertions, sweep.insertions);
    facts.set(TrapezoidFacts::sweep_deletions, sweep.deletions);
    facts.set(TrapezoidFacts::sweep_events, sweep.events());
    facts.set(TrapezoidFacts::sweep_most_crossed, sweep.most_crossed);
    facts.set(SearchFacts::algorithm, to_string(options.search.algorithm));
  }
};

TrapezoidPlanner::TrapezoidPlanner(const CSpace& cspace, TrapezoidOptions options) {
  impl_ = build_timed<Impl>(cspace, options, query_points(cspace.world()));
}

TrapezoidPlanner::~TrapezoidPlanner() = default;

const TrapezoidalDecomposition& TrapezoidPlanner::decomposition() const { return impl_->decomposition; }
const Roadmap& TrapezoidPlanner::roadmap() const { return impl_->roadmap; }

PlanReport<ExactPoint> TrapezoidPlanner::plan(const Query& query, const QueryOptions& options) {
  if (auto inside = points_to_reframe(impl_->decomposition, impl_->cspace->world(), query))
    impl_ = build_timed<Impl>(*impl_->cspace, impl_->options, *inside);
  Impl& g = *impl_;
  return tallied_query<ExactPoint>([&](PlanReport<ExactPoint>& report, QueryTally& tally) {
    g.record_facts(report.facts);
    if (options.record) {
      report.recording.graph = g.graph();
      report.recording.decomposition = g.cells();
    }
    const std::vector<std::size_t> from = g.decomposition.cells_at(query.start),
                                   to = g.decomposition.cells_at(query.goal);
    if (from.empty() || to.empty())
      return report.fail(PlanStatus::invalid_query,
                         g.cspace->query_not_free(query).value_or("the start or goal is in no trapezoid"));

    std::vector<ExactPoint> zigzag, funnel;
    std::size_t channel_cells = 1;
    if (share_a_cell(from, to)) {  // one convex cell holds both: the segment
      zigzag = funnel = {query.start, query.goal};
    } else {
      const auto result = g.search(query, from, to, options, report);
      tally.count(result);
      if (!result.found)  // the cells of a free component are joined by walls: another component
        return report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
      zigzag.push_back(query.start);
      for (std::size_t i = 1; i + 1 < result.path.size(); ++i) zigzag.push_back(g.roadmap[result.path[i]].exact);
      zigzag.push_back(query.goal);
      funnel = funnel_path(query.start, g.portals_along(result.path), query.goal);
      channel_cells = (result.path.size() - 1) / 2;
    }
    report.path = without_straight_corners(g.options.path == ChannelPath::funnel ? funnel : zigzag);
    if (report.path.size() == 1) report.path.push_back(query.goal);  // start == goal: still a segment
    // Every reported path is checked exactly; a failure is a bug of the decomposition or the
    // funnel, never a tolerance call.
    const PathCheck check = check_path(*g.cspace, report.path);
    if (!check.valid) throw std::logic_error("trapezoid planner produced an invalid path: " + check.reason);
    report.succeed();
    report.length = euclidean_length(report.path);
    report.certificate = {true, "exact path check (geometry/path_check)"};
    report.facts.set(SearchFacts::path_edges, report.path.size() - 1);
    report.facts.set(TrapezoidFacts::channel_cells, channel_cells);
    report.facts.set(TrapezoidFacts::zigzag_length, euclidean_length(zigzag));
    report.facts.set(TrapezoidFacts::funnel_length, euclidean_length(funnel));
  });
}

PlannerEntry<TranslatingRobot> trapezoid_planner_entry() {
  OptionTable<TrapezoidOptions> table;
  table.add(
      "path", &TrapezoidOptions::path,
      "funnel: the shortest path within the channel of trapezoids found; zigzag: through centroids and wall midpoints",
      std::vector<std::pair<std::string, ChannelPath>>{{"funnel", ChannelPath::funnel},
                                                       {"zigzag", ChannelPath::zigzag}});
  add_search_options(table, &TrapezoidOptions::search);
  return make_planner_entry<TranslatingRobot, TrapezoidOptions>(
      "trapezoid", "vertical (trapezoidal) decomposition of the free space: centroids and wall midpoints as a roadmap",
      std::move(table),
      [](const CSpace& cspace, const TrapezoidOptions& o) { return std::make_unique<TrapezoidPlanner>(cspace, o); });
}

}  // namespace polyplan
