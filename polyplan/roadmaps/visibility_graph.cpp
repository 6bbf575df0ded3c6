#include <polyplan/roadmaps/visibility_graph.hpp>

#include <polyplan/free_space/detail/free_space_triangulation.hpp>
#include <polyplan/free_space/query_frame.hpp>
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_trace.hpp>
#include <polyplan/plan/query_tally.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/search/exact_shortest_path.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

using namespace detail;
using Direction = VertexWedges::Direction;

constexpr std::size_t kNotANode = static_cast<std::size_t>(-1);

}  // namespace

struct VisibilityGraph::Impl {
  const CSpace* cspace;
  VisibilityKind kind;
  SearchOptions search;
  FreeSpaceTriangulation triangulation;
  // node_of[v][k]: the roadmap vertex of free wedge k at free-space vertex v, or kNotANode.
  std::vector<std::vector<std::size_t>> node_of;
  Roadmap roadmap;
  std::size_t corners = 0;
  RoadmapVertexId start_slot = 0, goal_slot = 0;
  SearchWorkspace<RoadmapVertexId> workspace;
  double build_seconds = 0;
  std::shared_ptr<const PlanGraph<ExactPoint>> picture;           // made for the first query that records
  std::vector<std::pair<std::size_t, std::size_t>> corner_edges;  // the edges between corners,
  std::vector<std::string> edge_kinds;                            // and what each is

  // Without bounds the triangulation's frame holds `inside` (geometry/detail/free_space_frame.hpp).
  Impl(const CSpace& c, VisibilityKind k, SearchOptions s, const std::vector<ExactPoint>& inside)
      : cspace(&c), kind(k), search(s), triangulation(CSpaceAccess::impl(c), inside) {}

  const char* kind_name() const { return kind == VisibilityKind::reduced ? "visibility" : "visibility-full"; }

  bool is_node_wedge(const VertexWedges& w, std::size_t k) const {
    return w.is_free(k) && (kind == VisibilityKind::full || w.is_reflex(k));
  }

  // The node a sight line from `from` ends at when it reaches vertex v, or kNotANode: the corner
  // of the wedge it arrives in, and (reduced graph) only if the line is tangent there, i.e. its
  // continuation past v stays in the same wedge.
  std::size_t arrival_node(std::size_t v, const Point& from) const {
    const VertexWedges& w = triangulation.wedges(v);
    const Point& at = triangulation.point(v);
    const auto wedge = w.wedge(Direction(from - at));
    if (!wedge) return kNotANode;
    const std::size_t node = node_of[v][*wedge];
    if (node == kNotANode) return kNotANode;
    if (kind == VisibilityKind::reduced && w.wedge(Direction(at - from)) != wedge) return kNotANode;
    return node;
  }

  // Which side of the directed line a→b the obstacle at corner v (outside its free wedge k) lies
  // on: +1 left, −1 right, 0 both (the line is not tangent to it there).
  int obstacle_side(std::size_t v, std::size_t k, const Point& a, const Point& b) const {
    const VertexWedges& w = triangulation.wedges(v);
    const int s1 = CGAL::orientation(a, b, w.far(k)), s2 = CGAL::orientation(a, b, w.far((k + 1) % w.size()));
    if (s1 >= 0 && s2 >= 0 && s1 + s2 > 0) return 1;
    if (s1 <= 0 && s2 <= 0 && s1 + s2 < 0) return -1;
    return 0;
  }

  // The sight line from corner v (free wedge k) to vertex c: a supporting bitangent when both
  // obstacles lie on one side of it, separating when on either side, else other.
  std::string edge_kind(std::size_t v, std::size_t k, std::size_t c) const {
    const Point &a = triangulation.point(v), &b = triangulation.point(c);
    const auto at_c = triangulation.wedges(c).wedge(Direction(a - b));
    const int here = obstacle_side(v, k, a, b), there = at_c ? obstacle_side(c, *at_c, a, b) : 0;
    if (here == 0 || there == 0) return "other";
    return here == there ? "supporting" : "separating";
  }

  void build() {
    const std::size_t n = triangulation.vertex_count();
    node_of.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
      const VertexWedges& w = triangulation.wedges(v);
      node_of[v].assign(w.size(), kNotANode);
      for (std::size_t k = 0; k < w.size(); ++k)
        if (is_node_wedge(w, k)) node_of[v][k] = add_vertex(roadmap, to_exact(w.point()));
    }
    corners = boost::num_vertices(roadmap);
    std::vector<std::size_t> visible;
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < node_of[v].size(); ++k) {
        const std::size_t u = node_of[v][k];
        if (u == kNotANode) continue;
        visible.clear();
        triangulation.visible_from_corner(v, k, visible);
        for (std::size_t c : visible) {
          const std::size_t target = arrival_node(c, triangulation.point(v));
          if (target == kNotANode || target <= u) continue;  // each pair once: visibility is symmetric
          if (kind == VisibilityKind::reduced && arrival_node(v, triangulation.point(c)) != u) continue;
          add_edge(roadmap, u, target);
          corner_edges.emplace_back(u, target);
          edge_kinds.push_back(edge_kind(v, k, c));
        }
      }
    start_slot = add_vertex(roadmap, ExactPoint{});
    goal_slot = add_vertex(roadmap, ExactPoint{});
  }

  // Joins a query point to the corners it sees; false when it is blocked.
  bool connect(RoadmapVertexId slot, const ExactPoint& p) {
    roadmap[slot] = RoadmapVertex{p, to_double(p.x), to_double(p.y)};
    const Point at = to_point(p);
    std::vector<std::size_t> visible;
    if (!triangulation.visible_from_point(at, visible)) return false;
    for (std::size_t c : visible) {
      const std::size_t node = arrival_node(c, at);
      if (node != kNotANode) add_edge(roadmap, slot, node);
    }
    return true;
  }

  // The corners and the edges between them (the query slots' edges are cleared after each query).
  std::shared_ptr<const PlanGraph<ExactPoint>> graph_picture() {
    if (picture) return picture;
    auto g = std::make_shared<PlanGraph<ExactPoint>>();
    g->kind = "roadmap";
    for (std::size_t v = 0; v < corners; ++v) g->vertices.push_back(roadmap[v].exact);
    g->edges = corner_edges;
    g->edge_kinds = edge_kinds;
    picture = std::move(g);
    return picture;
  }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, kind_name());
    facts.set(RoadmapFacts::vertices, corners);
    facts.set(RoadmapFacts::edges, boost::num_edges(roadmap));
    facts.set(RoadmapFacts::seconds, build_seconds);
    const auto count = [&](const char* kind) { return std::count(edge_kinds.begin(), edge_kinds.end(), kind); };
    facts.set(RoadmapFacts::supporting_edges, count("supporting"));
    facts.set(RoadmapFacts::separating_edges, count("separating"));
    if (kind == VisibilityKind::full) facts.set(RoadmapFacts::other_edges, count("other"));
  }

  // Whether start and goal lie in one component of the free space (a blocked end lies in none).
  bool share_a_component(const Query& query) const {
    const std::vector<int> from = triangulation.components_at(to_point(query.start)),
                           to = triangulation.components_at(to_point(query.goal));
    return std::any_of(from.begin(), from.end(), [&](int c) { return std::find(to.begin(), to.end(), c) != to.end(); });
  }

  // The corners searched from the query's start to its goal, each joined to the corners it sees;
  // the expanded vertices added to `expanded` when the search records them.
  SearchResult<RoadmapVertexId> search_corners(const Query& query, const SearchOptions& searching,
                                               std::vector<ExactPoint>& expanded) {
    connect(start_slot, query.start);
    connect(goal_slot, query.goal);
    auto result = shortest_path(roadmap, start_slot, goal_slot, searching, workspace);
    // A* and Dijkstra call their path shortest: the exact pass makes it so where doubles tie.
    if (result.found && (searching.algorithm == Search::astar || searching.algorithm == Search::dijkstra))
      result.path = exactly_shortest_path(roadmap, result.path);
    for (RoadmapVertexId v : result.expanded_order) expanded.push_back(roadmap[v].exact);
    boost::clear_vertex(start_slot, roadmap);
    boost::clear_vertex(goal_slot, roadmap);
    return result;
  }

  // Why there is no path: a blocked end (what it hits), or ends in different components.
  void refuse_unconnected(const Query& query, PlanReport<ExactPoint>& report) const {
    if (auto blocked = cspace->query_not_free(query)) report.fail(PlanStatus::invalid_query, *blocked);
    else report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
  }
};

VisibilityGraph::VisibilityGraph(const CSpace& cspace, VisibilityKind kind, SearchOptions search) {
  build(cspace, kind, search, query_points(cspace.world()));
}

void VisibilityGraph::build(const CSpace& cspace, VisibilityKind kind, SearchOptions search,
                            const std::vector<ExactPoint>& inside) {
  const Stopwatch building;
  impl_ = std::make_unique<Impl>(cspace, kind, search, inside);
  impl_->build();
  impl_->build_seconds = building.seconds();
}
VisibilityGraph::~VisibilityGraph() = default;
VisibilityGraph::VisibilityGraph(VisibilityGraph&&) noexcept = default;
VisibilityGraph& VisibilityGraph::operator=(VisibilityGraph&&) noexcept = default;

const Roadmap& VisibilityGraph::roadmap() const { return impl_->roadmap; }
std::size_t VisibilityGraph::corner_count() const { return impl_->corners; }

PlanReport<ExactPoint> VisibilityGraph::plan(const Query& query, const QueryOptions& options) {
  return plan(query, impl_->search, options);
}

// `search` by value: a query beyond the frame rebuilds impl_, impl_->search with it.
PlanReport<ExactPoint> VisibilityGraph::plan(const Query& query, SearchOptions search, const QueryOptions& options) {
  if (auto inside = points_to_reframe(impl_->triangulation, impl_->cspace->world(), query))
    build(*impl_->cspace, impl_->kind, impl_->search, *inside);
  Impl& g = *impl_;
  PlanReport<ExactPoint> answer = tallied_query<ExactPoint>([&](PlanReport<ExactPoint>& report, QueryTally& tally) {
    g.record_facts(report.facts);
    report.facts.set(SearchFacts::algorithm, to_string(search.algorithm));
    if (options.record) report.recording.graph = g.graph_picture();
    if (!g.share_a_component(query)) return g.refuse_unconnected(query, report);  // nothing to search

    if (!g.triangulation.why_blocked(to_point(query.start), to_point(query.goal))) {  // start sees goal: the segment
      report.path = {query.start, query.goal};
    } else {
      search.record_expanded = options.record;
      search.record_trace = options.trace;
      const auto result = g.search_corners(query, search, report.recording.expanded);
      report.recording.trace =
          plan_trace<ExactPoint>(result.trace, [&g](RoadmapVertexId v) { return g.roadmap[v].exact; });
      tally.count(result);
      if (!result.found)  // cannot happen: one component means one path through its corners
        return report.fail(PlanStatus::no_path, "no path in the visibility graph between start and goal");
      for (RoadmapVertexId v : result.path) report.path.push_back(g.roadmap[v].exact);
      report.path = without_straight_corners(report.path);
      // Every reported path is checked exactly (by a walk through the triangulation, not by the
      // visibility cones that found it; the straight segment above was that walk already); a
      // failure here is a bug, never a tolerance call.
      std::vector<Point> points;
      for (const ExactPoint& p : report.path) points.push_back(to_point(p));
      if (auto why = g.triangulation.why_path_blocked(points))
        throw std::logic_error("visibility graph produced an invalid path: " + *why);
    }
    report.succeed();
    report.length = euclidean_length(report.path);
    report.certificate = {true, "exact path check (walk through the triangulated free space)"};
  });
  answer.facts.set(SearchFacts::path_edges, answer.path.empty() ? 0 : answer.path.size() - 1);
  return answer;
}

PlannerEntry<TranslatingRobot> visibility_planner_entry(VisibilityKind kind) {
  struct Options {
    SearchOptions search;
  };
  OptionTable<Options> table;
  add_search_options(table, &Options::search);
  const bool reduced = kind == VisibilityKind::reduced;
  return make_planner_entry<TranslatingRobot, Options>(
      reduced ? "visibility" : "visibility-full",
      reduced ? "exact shortest paths on the reduced visibility graph (bitangents between convex corners)"
              : "every visible pair of free corners, as a course draws the visibility graph",
      std::move(table), [kind](const CSpace& cspace, const Options& o) {
        return std::make_unique<VisibilityGraph>(cspace, kind, o.search);
      });
}

}  // namespace polyplan
