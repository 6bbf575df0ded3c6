#include <polyplan/roadmaps/visibility_graph.hpp>

#include <polyplan/internal/cspace_impl.hpp>
#include <polyplan/roadmaps/detail/free_space_triangulation.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <chrono>
#include <stdexcept>

namespace polyplan {
namespace {

using namespace detail;
using Clock = std::chrono::steady_clock;
using Direction = VertexWedges::Direction;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

constexpr std::size_t kNotANode = static_cast<std::size_t>(-1);

// A path that runs straight through a corner (grazing it) lists that corner; the same motion
// without it reads better and is what DESIGN.md calls the path ("if start sees goal, the path is
// the segment"). Exact: the middle point is dropped only if collinear and between its neighbours.
std::vector<ExactPoint> without_straight_corners(const std::vector<ExactPoint>& path) {
  std::vector<ExactPoint> kept;
  for (const ExactPoint& p : path) {
    while (kept.size() >= 2) {
      const ExactPoint &a = kept[kept.size() - 2], &b = kept.back();
      const bool collinear = (b.x - a.x) * (p.y - a.y) == (p.x - a.x) * (b.y - a.y);
      const bool between = (b.x - a.x) * (p.x - b.x) + (b.y - a.y) * (p.y - b.y) > 0;
      if (!(collinear && between)) break;
      kept.pop_back();
    }
    kept.push_back(p);
  }
  return kept;
}

}  // namespace

struct VisibilityGraph::Impl {
  VisibilityKind kind;
  FreeSpaceTriangulation triangulation;
  // node_of[v][k]: the roadmap vertex of free wedge k at free-space vertex v, or kNotANode.
  std::vector<std::vector<std::size_t>> node_of;
  Roadmap roadmap;
  std::size_t corners = 0;
  RoadmapVertexId start_slot = 0, goal_slot = 0;
  SearchWorkspace<RoadmapVertexId> workspace;
  double build_seconds = 0;

  Impl(const CSpace& c, VisibilityKind k) : kind(k), triangulation(CSpaceAccess::impl(c)) {}

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
};

VisibilityGraph::VisibilityGraph(const CSpace& cspace, VisibilityKind kind)
    : impl_(std::make_unique<Impl>(cspace, kind)) {
  const auto started = Clock::now();
  impl_->build();
  impl_->build_seconds = seconds_since(started);
}
VisibilityGraph::~VisibilityGraph() = default;
VisibilityGraph::VisibilityGraph(VisibilityGraph&&) noexcept = default;
VisibilityGraph& VisibilityGraph::operator=(VisibilityGraph&&) noexcept = default;

const Roadmap& VisibilityGraph::roadmap() const { return impl_->roadmap; }

RoadmapFacts VisibilityGraph::facts() const {
  const Impl& g = *impl_;
  // The query slots' edges are cleared after every query: all edges are the corners'.
  return {g.kind == VisibilityKind::reduced ? "visibility" : "visibility-full", g.corners, boost::num_edges(g.roadmap),
          g.build_seconds};
}

Plan VisibilityGraph::plan(const ExactPoint& start, const ExactPoint& goal, const SearchOptions& options) {
  Impl& g = *impl_;
  const auto started = Clock::now();
  Plan plan;
  plan.roadmap = facts();
  plan.algorithm = options.algorithm;

  const Point from_point = to_point(start), to_point_ = to_point(goal);
  const std::vector<int> from = g.triangulation.components_at(from_point), to = g.triangulation.components_at(to_point_);
  bool shared_component = false;
  for (int c : from)
    shared_component |= std::find(to.begin(), to.end(), c) != to.end();
  if (!shared_component) {  // blocked, or in different components: nothing to search
    plan.query_seconds = seconds_since(started);
    return plan;
  }

  if (!g.triangulation.why_blocked(from_point, to_point_)) {  // start sees goal: the segment
    plan.found = true;
    plan.path = {start, goal};
    plan.length = std::hypot(to_double(start.x) - to_double(goal.x), to_double(start.y) - to_double(goal.y));
  } else {
    g.connect(g.start_slot, start);
    g.connect(g.goal_slot, goal);
    const auto result = shortest_path(g.roadmap, g.start_slot, g.goal_slot, options, g.workspace);
    for (RoadmapVertexId v : result.expanded_order) plan.expanded_points.push_back(g.roadmap[v].exact);
    boost::clear_vertex(g.start_slot, g.roadmap);
    boost::clear_vertex(g.goal_slot, g.roadmap);
    plan.expanded = result.expanded;
    plan.generated = result.generated;
    plan.search_seconds = result.seconds;
    if (result.found) {
      for (RoadmapVertexId v : result.path) plan.path.push_back(g.roadmap[v].exact);
      plan.path = without_straight_corners(plan.path);
      plan.found = true;
      plan.length = result.cost;
      // Every reported path is checked exactly (by a walk through the triangulation, not by the
      // visibility cones that found it; the straight segment above was that walk already); a
      // failure here is a bug, never a tolerance call.
      std::vector<Point> points;
      for (const ExactPoint& p : plan.path) points.push_back(to_point(p));
      if (auto why = g.triangulation.why_path_blocked(points))
        throw std::logic_error("visibility graph produced an invalid path: " + *why);
    }
  }
  plan.query_seconds = seconds_since(started);
  return plan;
}

}  // namespace polyplan
