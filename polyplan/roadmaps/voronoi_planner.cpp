#include <polyplan/roadmaps/voronoi_planner.hpp>

#include <polyplan/free_space/query_frame.hpp>
#include <polyplan/geometry/clearance.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/shared_component.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_trace.hpp>
#include <polyplan/plan/query_tally.hpp>
#include <polyplan/roadmaps/roadmap_facts.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace polyplan {
namespace {

constexpr double kClearanceTolerance = 1e-7;  // how far a sampled arc may come below r*

// A piece of the graph searched for one query: a diagram edge between two parameters, or the
// straight move from a query point to where it meets the diagram.
struct Piece {
  std::size_t u = 0, v = 0;         // graph vertices
  std::optional<std::size_t> edge;  // the diagram edge it runs along; none for a straight move
  std::optional<Vec2> via;          // a straight move's corner: where it stepped off the boundary
  double t_u = 0, t_v = 0;
  double clearance = 0, length = 0;
  bool joins_a_query = false;
};

// The pieces at least as clear as the bottleneck as a roadmap, and which piece joins two vertices.
struct PieceGraph {
  Roadmap roadmap;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> piece_between;
};

}  // namespace

struct VoronoiPlanner::Impl {
  const CSpace* cspace;
  VoronoiOptions options;
  VoronoiDiagram diagram;
  double build_seconds = 0;
  std::size_t parabolic_edges = 0;
  std::shared_ptr<const PlanGraph<ExactPoint>> picture;
  std::unique_ptr<VisibilityGraph> exact_shortest;  // built when a passage is too narrow for doubles

  VisibilityGraph& exact_planner() {
    if (!exact_shortest) exact_shortest = std::make_unique<VisibilityGraph>(*cspace);
    return *exact_shortest;
  }

  Impl(const CSpace& c, const VoronoiOptions& o, const std::vector<ExactPoint>& inside)
      : cspace(&c), options(o), diagram(c, inside) {
    for (std::size_t e = 0; e < diagram.edges().size(); ++e) parabolic_edges += diagram.is_parabolic(e);
  }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, "voronoi");
    facts.set(RoadmapFacts::vertices, diagram.vertices().size());
    facts.set(RoadmapFacts::edges, diagram.edges().size());
    facts.set(RoadmapFacts::seconds, build_seconds);
    facts.set(VoronoiFacts::sites, diagram.sites().size());
    facts.set(VoronoiFacts::parabolic_edges, parabolic_edges);
    facts.set(SearchFacts::algorithm, to_string(options.search.algorithm));
  }

  // The diagram, its parabolic arcs as the quadratic Bézier curves they are.
  std::shared_ptr<const PlanGraph<ExactPoint>> graph() {
    if (picture) return picture;
    auto g = std::make_shared<PlanGraph<ExactPoint>>();
    g->kind = "Voronoi diagram";
    for (const DiagramVertex& v : diagram.vertices()) g->vertices.push_back(exactly(v.at));
    for (std::size_t e = 0; e < diagram.edges().size(); ++e) {
      g->edges.emplace_back(diagram.edges()[e].from, diagram.edges()[e].to);
      g->bends.push_back(diagram.is_parabolic(e) ? std::optional<ExactPoint>(exactly(diagram.bezier_control(
                                                       e, diagram.parameter_from(e), diagram.parameter_to(e))))
                                                 : std::nullopt);
    }
    picture = std::move(g);
    return picture;
  }

  // The pieces of the search graph: the diagram's edges, and for each query point the straight
  // move onto the diagram and the two parts of the edge it lands on (and the part between the two
  // landing points when both land on one edge).
  std::vector<Piece> pieces_for(const ExactPoint& start, const VoronoiDiagram::Retraction& from_start,
                                const ExactPoint& goal, const VoronoiDiagram::Retraction& from_goal) const {
    const CurvePoint from = from_start.on, to = from_goal.on;
    const std::size_t n = diagram.vertices().size(), s = n, g = n + 1, rs = n + 2, rg = n + 3;
    std::vector<Piece> pieces;
    for (std::size_t e = 0; e < diagram.edges().size(); ++e) {
      const DiagramEdge& edge = diagram.edges()[e];
      pieces.push_back({edge.from, edge.to, e, std::nullopt, diagram.parameter_from(e), diagram.parameter_to(e),
                        edge.clearance, edge.length, false});
    }
    auto land = [&](std::size_t query, std::size_t landing, const ExactPoint& p, const VoronoiDiagram::Retraction& r) {
      const CurvePoint on = r.on;
      const Vec2 at = approximate(p), there = diagram.point(on.edge, on.parameter),
                 corner = r.off_boundary.value_or(at);
      pieces.push_back(
          {query, landing, std::nullopt, r.off_boundary, 0, 0, r.clearance,
           std::hypot(at.x - corner.x, at.y - corner.y) + std::hypot(corner.x - there.x, corner.y - there.y), true});
      const DiagramEdge& edge = diagram.edges()[on.edge];
      for (const auto& [end, t] :
           {std::pair{edge.from, diagram.parameter_from(on.edge)}, std::pair{edge.to, diagram.parameter_to(on.edge)}})
        pieces.push_back({landing, end, on.edge, std::nullopt, on.parameter, t,
                          diagram.clearance_between(on.edge, on.parameter, t),
                          diagram.length_between(on.edge, on.parameter, t), true});
    };
    land(s, rs, start, from_start);
    land(g, rg, goal, from_goal);
    if (from.edge == to.edge)
      pieces.push_back({rs, rg, from.edge, std::nullopt, from.parameter, to.parameter,
                        diagram.clearance_between(from.edge, from.parameter, to.parameter),
                        diagram.length_between(from.edge, from.parameter, to.parameter), true});
    return pieces;
  }

  // Chords along a piece from its t_u end to its t_v end (the t_u end not included), fine enough
  // to stay within the tolerance of the bottleneck.
  void sample(const Piece& piece, double t1, double t2, double bottleneck, std::vector<Vec2>& out,
              int depth = 0) const {
    const std::size_t e = *piece.edge;
    if (diagram.is_parabolic(e) && depth < 60) {
      const double arc = diagram.clearance_between(e, t1, t2);
      const double floor = std::max(bottleneck - kClearanceTolerance, std::min(bottleneck, arc) / 2);
      if (arc - diagram.sagitta(e, t1, t2) < floor) {
        const double middle = (t1 + t2) / 2;
        sample(piece, t1, middle, bottleneck, out, depth + 1);
        sample(piece, middle, t2, bottleneck, out, depth + 1);
        return;
      }
    }
    out.push_back(diagram.point(e, t2));
  }

  // The search graph's vertices: the diagram's, then the query's start and goal and the two
  // points where they land on the diagram (pieces_for's numbering).
  std::size_t start_vertex() const { return diagram.vertices().size(); }
  std::size_t goal_vertex() const { return diagram.vertices().size() + 1; }
  std::size_t search_vertices() const { return diagram.vertices().size() + 4; }

  // The bottleneck r*: the pieces joined in order of falling clearance until start and goal
  // meet; nullopt when they never do. Pieces of the diagram with no clearance (through a pinch
  // point, into a corner) never join anything.
  std::optional<double> bottleneck_of(const std::vector<Piece>& pieces) const {
    std::vector<std::size_t> order(pieces.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return pieces[a].clearance > pieces[b].clearance; });
    std::vector<std::size_t> rank(search_vertices()), parent(search_vertices());
    boost::disjoint_sets<std::size_t*, std::size_t*> components(rank.data(), parent.data());
    for (std::size_t v = 0; v < search_vertices(); ++v) components.make_set(v);
    for (std::size_t i : order) {
      const Piece& piece = pieces[i];
      if (piece.clearance <= 0 && !piece.joins_a_query) break;
      components.union_set(piece.u, piece.v);
      if (components.find_set(start_vertex()) == components.find_set(goal_vertex())) return piece.clearance;
    }
    return std::nullopt;
  }

  // The graph of the pieces at least `bottleneck` clear, each pair of vertices joined by its
  // shortest such piece.
  PieceGraph pieces_at_least(const std::vector<Piece>& pieces, double bottleneck, const Query& query,
                             const VoronoiDiagram::Retraction& from, const VoronoiDiagram::Retraction& to) const {
    PieceGraph clear;
    for (const DiagramVertex& v : diagram.vertices()) add_vertex(clear.roadmap, exactly(v.at));
    add_vertex(clear.roadmap, query.start);
    add_vertex(clear.roadmap, query.goal);
    add_vertex(clear.roadmap, exactly(diagram.point(from.on.edge, from.on.parameter)));
    add_vertex(clear.roadmap, exactly(diagram.point(to.on.edge, to.on.parameter)));
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& piece = pieces[i];
      if (piece.clearance < bottleneck || (piece.clearance <= 0 && !piece.joins_a_query)) continue;
      boost::add_edge(piece.u, piece.v, RoadmapEdge{piece.length}, clear.roadmap);
      for (const auto& key : {std::pair{piece.u, piece.v}, std::pair{piece.v, piece.u}}) {
        auto [it, inserted] = clear.piece_between.emplace(key, i);
        if (!inserted && pieces[it->second].length > piece.length) it->second = i;
      }
    }
    return clear;
  }

  // The searched vertices as a path from the query's start to its goal: straight moves onto and
  // off the diagram, its arcs as chords fine enough for the bottleneck.
  std::vector<ExactPoint> path_along(const std::vector<RoadmapVertexId>& nodes, const std::vector<Piece>& pieces,
                                     const PieceGraph& clear, double bottleneck, const Query& query) const {
    std::vector<Vec2> points;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      const std::size_t u = nodes[i], v = nodes[i + 1];
      const Piece& piece = pieces[clear.piece_between.at({u, v})];
      if (!piece.edge) {  // a query point's move onto the diagram, or back from it
        if (piece.via) points.push_back(*piece.via);
        points.push_back(approximate(clear.roadmap[v].exact));
        continue;
      }
      const bool forward = piece.u == u;
      sample(piece, forward ? piece.t_u : piece.t_v, forward ? piece.t_v : piece.t_u, bottleneck, points);
    }
    std::vector<ExactPoint> path{query.start};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) path.push_back(exactly(points[i]));
    path.push_back(query.goal);
    path = without_straight_corners(path);
    if (path.size() == 1) path.push_back(query.goal);
    return path;
  }

  // A path is returned only after the exact check; its clearance is measured on it.
  void certify(PlanReport<ExactPoint>& report) const {
    const PathCheck check = check_path(*cspace, report.path);
    if (!check.valid) {
      report.path.clear();
      return report.fail(PlanStatus::not_found,
                         "the maximum-clearance path failed the exact check (the diagram's doubles rounded across the "
                         "boundary): " +
                             check.reason);
    }
    report.succeed();
    report.length = euclidean_length(report.path);
    report.certificate = {true, "exact path check (geometry/path_check)"};
    const PathBottleneck narrowest = path_bottleneck(*cspace, report.path);
    report.bottleneck = Bottleneck{narrowest.at.x, narrowest.at.y, narrowest.clearance};
    report.facts.set(SearchFacts::path_edges, report.path.size() - 1);
  }
};

VoronoiPlanner::VoronoiPlanner(const CSpace& cspace, VoronoiOptions options) {
  impl_ = build_timed<Impl>(cspace, options, query_points(cspace.world()));
}

VoronoiPlanner::~VoronoiPlanner() = default;

const VoronoiDiagram& VoronoiPlanner::diagram() const { return impl_->diagram; }

PlanReport<ExactPoint> VoronoiPlanner::plan(const Query& query, const QueryOptions& options) {
  if (auto inside = points_to_reframe(impl_->diagram, impl_->cspace->world(), query))
    impl_ = build_timed<Impl>(*impl_->cspace, impl_->options, *inside);
  Impl& g = *impl_;
  return tallied_query<ExactPoint>([&](PlanReport<ExactPoint>& report, QueryTally& tally) {
    g.record_facts(report.facts);
    if (options.record) report.recording.graph = g.graph();
    if (auto blocked = g.cspace->query_not_free(query)) return report.fail(PlanStatus::invalid_query, *blocked);
    const auto from = g.diagram.retract(query.start), to = g.diagram.retract(query.goal);
    if (!from || !to)
      return report.fail(PlanStatus::not_found,
                         std::string("the ") + (from ? "goal" : "start") + " meets no edge of the Voronoi diagram");

    const std::vector<Piece> pieces = g.pieces_for(query.start, *from, query.goal, *to);
    const std::optional<double> bottleneck = g.bottleneck_of(pieces);
    if (!bottleneck) {
      if (!share_a_component(*g.cspace, query.start, query.goal))
        return report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space");
      // The exact free space joins them through a passage narrower than the diagram's doubles
      // resolve (decimal.json's gap of 1e-17): the best clearance is below that resolution, and the
      // exact shortest path through the passage is as clear as any.
      report.path = g.exact_planner().plan(query).path;
      report.facts.set(VoronoiFacts::narrows, true);
      return g.certify(report);
    }

    // The shortest path over the pieces at least as clear as the bottleneck.
    const PieceGraph clear = g.pieces_at_least(pieces, *bottleneck, query, *from, *to);
    SearchOptions searching = g.options.search;
    searching.record_expanded = options.record;
    searching.record_trace = options.trace;
    const auto result = shortest_path(clear.roadmap, g.start_vertex(), g.goal_vertex(), searching);
    for (RoadmapVertexId v : result.expanded_order) report.recording.expanded.push_back(clear.roadmap[v].exact);
    report.recording.trace =
        plan_trace<ExactPoint>(result.trace, [&clear](RoadmapVertexId v) { return clear.roadmap[v].exact; });
    tally.count(result);
    if (!result.found)  // cannot happen: the bottleneck joined them
      return report.fail(PlanStatus::not_found, "no path on the Voronoi diagram at the bottleneck clearance");
    report.path = g.path_along(result.path, pieces, clear, *bottleneck, query);
    report.facts.set(VoronoiFacts::bottleneck, *bottleneck);
    g.certify(report);
  });
}

PlannerEntry<TranslatingRobot> voronoi_planner_entry() {
  OptionTable<VoronoiOptions> table;
  add_search_options(table, &VoronoiOptions::search);
  return make_planner_entry<TranslatingRobot, VoronoiOptions>(
      "voronoi", "maximum clearance on the generalized Voronoi diagram of the free space (CGAL segment Delaunay graph)",
      std::move(table),
      [](const CSpace& cspace, const VoronoiOptions& o) { return std::make_unique<VoronoiPlanner>(cspace, o); });
}

}  // namespace polyplan
