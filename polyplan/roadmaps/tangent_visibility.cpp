#include <polyplan/roadmaps/tangent_visibility.hpp>

#include <polyplan/geometry/round_query.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_trace.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/plan/query_tally.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/roadmaps/detail/certified_length.hpp>
#include <polyplan/roadmaps/detail/tangent_arcs.hpp>
#include <polyplan/roadmaps/detail/tangent_prefilter.hpp>
#include <polyplan/search/roadmap.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

namespace polyplan {
namespace {

using tangent::Arc;
using tangent::Circle;
using AP = AlgebraicPoint;
using Rules = round_rules::RoundRules<Algebraic>;

using tangent::length_lower;
using tangent::length_upper;

// A checked straight motion between two touching points; `from_owner` and `to_owner` are circle
// indices, or circles.size() for the query's start and + 1 for its goal.
struct Chord {
  std::size_t from_owner = 0, to_owner = 0;
  AP from, to;
};

// An edge of a query's graph: a chord, or the arc of a circle counter-clockwise from node `u` to
// node `v` (the edge's own order).
struct Link {
  double length = 0;
  std::optional<std::size_t> circle;  // an arc's
  std::size_t u = 0, v = 0;
};

AP direction(const AP& from, const AP& to) { return to - from; }
FactPoint approximate(const AP& p) { return {p.x.doubleValue(), p.y.doubleValue()}; }
ExactPoint nearest_rational(const AP& p) {
  const FactPoint d = approximate(p);
  return {Rational(d[0]), Rational(d[1])};
}

double arc_length_estimate(const Arc& arc) {
  const FactPoint c = approximate(arc.circle->centre), a = approximate(arc.from), b = approximate(arc.to);
  const double ax = a[0] - c[0], ay = a[1] - c[1], bx = b[0] - c[0], by = b[1] - c[1];
  double theta = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (theta < 0) theta += 2 * M_PI;
  return arc.circle->radius.doubleValue() * theta;
}

}  // namespace

struct TangentVisibilityGraph::Impl {
  const RoundWorld& world;
  Rules rules;
  tangent::Prefilter prefilter;
  std::vector<Circle> circles;
  std::vector<Chord> chords;  // between the world's circles
  SearchOptions search;
  double build_seconds = 0;

  Impl(const RoundWorld& w, SearchOptions s)
      : world(w), rules(w.cspace(), [](const Rational& q) { return algebraic(q); }), prefilter(rules),
        circles(tangent::circles_of(w.cspace())), search(s) {
    const Stopwatch building;
    for (std::size_t i = 0; i < circles.size(); ++i)
      for (std::size_t j = i + 1; j < circles.size(); ++j) add_chords(circles[i], i, circles[j], j, chords);
    build_seconds = building.seconds();
  }

  // Whether the straight motion a→b is valid, ends included (a point: whether it is free).
  bool usable(const AP& a, const AP& b) const {
    if (a == b) return !rules.blocked_at(a, std::nullopt, std::nullopt);
    if (prefilter.clearly_blocked(a, b)) return false;
    return !rules.blocked_at(a, std::nullopt, direction(a, b)) && !rules.blocked_at(b, direction(b, a), std::nullopt) &&
           !rules.segment_blocked(a, b);
  }

  void add_chords(const Circle& a, std::size_t ia, const Circle& b, std::size_t ib, std::vector<Chord>& out) const {
    for (const tangent::Tangent& t : tangent::common_tangents(a, b))
      if (usable(t.from, t.to)) out.push_back({ia, ib, t.from, t.to});
  }

  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options);
};

namespace {

// A query's graph: its nodes (touching points; a corner of radius 0 or the start or goal has one
// node per class of directions a path may pass it by), and its links.
class QueryGraph {
 public:
  QueryGraph(const Rules& rules, const std::vector<Circle>& circles, const std::vector<Chord>& chords)
      : rules_(rules), circles_(circles) {
    for (std::size_t k = 0; k < chords.size(); ++k) {
      ports_[chords[k].from_owner].push_back({k, true, chords[k].from, direction(chords[k].from, chords[k].to)});
      ports_[chords[k].to_owner].push_back({k, false, chords[k].to, direction(chords[k].to, chords[k].from)});
    }
    chord_ends_.resize(chords.size());
    for (auto& [owner, ports] : ports_) add_nodes(owner, ports);
    for (std::size_t k = 0; k < chords.size(); ++k) {
      // A chord along a wall joins its ends' nodes on one face of it: the left of its from port is
      // the right of its to port (turned back).
      const FactPoint a = approximate(chords[k].from), b = approximate(chords[k].to);
      for (const auto& [u, face_u] : chord_ends_[k].first)
        for (const auto& [v, face_v] : chord_ends_[k].second)
          if (face_u == 0 || face_v == 0 || face_u == -face_v)
            add_link({std::hypot(a[0] - b[0], a[1] - b[1]), std::nullopt, u, v});
    }
    for (const auto& [owner, ports] : ports_)
      if (owner < circles.size() && sign_of_radius(owner) > 0) add_arcs(owner);
  }

  std::size_t node_of(std::size_t owner) const { return owner_nodes_.at(owner).front(); }
  const std::vector<AP>& points() const { return points_; }
  const std::vector<std::size_t>& owners() const { return node_owner_; }
  const std::map<std::pair<std::size_t, std::size_t>, Link>& links() const { return links_; }

  Roadmap roadmap() const {
    Roadmap graph;
    for (const AP& p : points_) add_vertex(graph, nearest_rational(p));
    for (const auto& [key, link] : links_) boost::add_edge(key.first, key.second, RoadmapEdge{link.length}, graph);
    return graph;
  }

 private:
  struct Port {
    std::size_t chord;
    bool from_end;
    AP at, out;  // where the chord touches, and its direction away from there
  };

  int sign_of_radius(std::size_t owner) const { return round_rules::sign_of(circles_[owner].radius); }

  std::size_t new_node(std::size_t owner, const AP& at) {
    points_.push_back(at);
    node_owner_.push_back(owner);
    owner_nodes_[owner].push_back(points_.size() - 1);
    return points_.size() - 1;
  }

  // `face`: the side of the port's direction the node's ways lie on where the port runs along a
  // wall (1 the left, -1 the right), 0 elsewhere.
  void attach(const Port& port, std::size_t node, int face = 0) {
    auto& [u, v] = chord_ends_[port.chord];
    (port.from_end ? u : v).push_back({node, face});
  }

  // A circle's touching points are nodes each. At a point, a node is a sector of the directions a
  // motion may turn through (between walls and obstacles): a port into a sector belongs to its
  // node; a port along a wall borders two sectors, its left and its right, and belongs to the node
  // of each, marked with that face (a robot sliding along a wall is on one of its faces). Ports,
  // and the faces of ports along walls, join one sector where a motion turns freely from one to
  // the other (round_rules' turn test at the point).
  void add_nodes(std::size_t owner, const std::vector<Port>& ports) {
    if (owner < circles_.size() && sign_of_radius(owner) > 0) {
      for (const Port& port : ports) attach(port, new_node(owner, port.at));
      return;
    }
    const round_rules::Contact<Algebraic> contact = rules_.contact(ports.front().at);
    const std::size_t n = ports.size();
    // A chord of length 0 (the point lies on a circle) leaves along no direction: any sector takes it.
    const auto still = [&](std::size_t i) { return round_rules::sign_of(round_rules::squared(ports[i].out)) == 0; };
    const auto along_wall = [&](std::size_t i) {
      return !still(i) && round_rules::is_separator(contact, ports[i].out);
    };
    const auto ccw_free = [&](const AP& from, const AP& to) {  // turning counter-clockwise from one to the other
      return round_rules::turns_freely(contact, round_rules::turning_directions(contact, from, to), from, to);
    };
    // Elements: 2i the port i (a port along a wall: its left face), 2i + 1 a wall port's right face.
    std::vector<std::size_t> leader(2 * n);
    std::iota(leader.begin(), leader.end(), 0);
    const auto find = [&](std::size_t e) {
      while (leader[e] != e) e = leader[e] = leader[leader[e]];
      return e;
    };
    const auto join = [&](std::size_t a, std::size_t b) { leader[find(b)] = find(a); };
    const bool one_side = contact.separators.empty() && contact.blocked.size() <= 1;
    for (std::size_t i = 0; i < n; ++i) {
      if (still(i)) continue;
      if (along_wall(i) && ccw_free(ports[i].out, ports[i].out)) join(2 * i, 2 * i + 1);  // round a wall's end
      for (std::size_t k = i + 1; k < n; ++k) {
        if (still(k)) continue;
        if (one_side) {
          join(2 * i, 2 * k);
          continue;
        }
        // The face of i that a counter-clockwise turn from i to k leaves by (its left), the face
        // of k it comes to (its right); and the same turning from k to i.
        const std::size_t i_left = 2 * i, i_right = along_wall(i) ? 2 * i + 1 : 2 * i;
        const std::size_t k_left = 2 * k, k_right = along_wall(k) ? 2 * k + 1 : 2 * k;
        if (ccw_free(ports[i].out, ports[k].out)) join(i_left, k_right);
        if (ccw_free(ports[k].out, ports[i].out)) join(k_left, i_right);
      }
    }
    std::map<std::size_t, std::size_t> node_of_sector;
    const auto sector_node = [&](std::size_t e) {
      auto [it, added] = node_of_sector.try_emplace(find(e), 0);
      if (added) it->second = new_node(owner, ports.front().at);
      return it->second;
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (still(i)) continue;
      if (!along_wall(i)) {
        attach(ports[i], sector_node(2 * i));
      } else if (find(2 * i) == find(2 * i + 1)) {
        attach(ports[i], sector_node(2 * i));
      } else {
        attach(ports[i], sector_node(2 * i), 1);
        attach(ports[i], sector_node(2 * i + 1), -1);
      }
    }
    for (std::size_t i = 0; i < n; ++i)
      if (still(i)) {
        if (node_of_sector.empty()) attach(ports[i], new_node(owner, ports[i].at));
        for (const auto& [sector, node] : node_of_sector) attach(ports[i], node);
      }
  }

  // The arcs between consecutive touching points round the circle, those that keep clear.
  void add_arcs(std::size_t owner) {
    std::vector<std::size_t> around = owner_nodes_[owner];
    if (around.size() < 2) return;
    const AP& c = circles_[owner].centre;
    const AP east{Algebraic(1), Algebraic(0)};
    std::sort(around.begin(), around.end(), [&](std::size_t a, std::size_t b) {
      return tangent::turns_before(east, points_[a] - c, points_[b] - c);
    });
    for (std::size_t k = 0; k < around.size(); ++k) {
      const std::size_t u = around[k], v = around[(k + 1) % around.size()];
      const Arc arc{&circles_[owner], points_[u], points_[v]};
      if (!tangent::arc_blocked(rules_, arc)) add_link({arc_length_estimate(arc), owner, u, v});
    }
  }

  // Parallel links (two arcs between the same two nodes, one each way round): the shorter, which
  // is the one a search would take.
  void add_link(const Link& link) {
    const auto key = std::minmax(link.u, link.v);
    auto [it, added] = links_.try_emplace(key, link);
    if (!added && link.length < it->second.length) it->second = link;
  }

  const Rules& rules_;
  const std::vector<Circle>& circles_;
  std::map<std::size_t, std::vector<Port>> ports_;
  using Ends = std::vector<std::pair<std::size_t, int>>;  // each end's nodes, with the face they lie on
  std::vector<std::pair<Ends, Ends>> chord_ends_;
  std::vector<AP> points_;
  std::vector<std::size_t> node_owner_;
  std::map<std::size_t, std::vector<std::size_t>> owner_nodes_;
  std::map<std::pair<std::size_t, std::size_t>, Link> links_;
};

// A found path as pieces: segments, and arcs with their circle and turn; zero-length pieces left
// out, consecutive arcs of one circle turning the same way merged.
struct Piece : tangent::CirclePiece {
  std::size_t from_owner = 0, to_owner = 0;  // the circles (or the start or goal) its ends touch
};

std::vector<Piece> pieces_of(const QueryGraph& graph, const std::vector<RoadmapVertexId>& nodes) {
  std::vector<Piece> out;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const std::size_t u = nodes[k], v = nodes[k + 1];
    const Link& link = graph.links().at(std::minmax(u, v));
    const AP &a = graph.points()[u], &b = graph.points()[v];
    if (a == b) continue;
    const Piece piece{{a, b, link.circle, !link.circle || link.u == u}, graph.owners()[u], graph.owners()[v]};
    if (piece.circle && !out.empty() && out.back().circle == piece.circle &&
        out.back().counter_clockwise == piece.counter_clockwise) {
      out.back().to = b;
      out.back().to_owner = piece.to_owner;
    } else out.push_back(piece);
  }
  return out;
}

}  // namespace

PlanReport<ExactPoint> TangentVisibilityGraph::Impl::plan(const Query& query, const QueryOptions& options) {
  return tallied_query<ExactPoint>([&](PlanReport<ExactPoint>& report, QueryTally& tally) {
    report.facts.set(RoadmapFacts::kind, "tangent-visibility");
    report.facts.set(RoadmapFacts::seconds, build_seconds);
    report.facts.set(SearchFacts::algorithm, to_string(search.algorithm));
    if (auto why = query_not_free(world, query)) return report.fail(PlanStatus::invalid_query, *why);
    const AP start = algebraic(query.start), goal = algebraic(query.goal);
    const std::size_t start_owner = circles.size(), goal_owner = circles.size() + 1;
    std::vector<Circle> ends = circles;  // what a node touches: a circle, or the start or the goal
    ends.push_back({start, Algebraic(0), query.start, 0, "the start"});
    ends.push_back({goal, Algebraic(0), query.goal, 0, "the goal"});
    std::vector<Chord> all = chords;
    if (usable(start, goal)) all = {{start_owner, goal_owner, start, goal}};  // nothing is shorter
    else
      for (std::size_t i = 0; i < circles.size(); ++i) {
        add_chords(ends[start_owner], start_owner, circles[i], i, all);
        add_chords(ends[goal_owner], goal_owner, circles[i], i, all);
      }
    const QueryGraph graph(rules, circles, all);
    report.facts.set(RoadmapFacts::vertices, graph.points().size());
    report.facts.set(RoadmapFacts::edges, graph.links().size());
    const Roadmap roadmap = graph.roadmap();
    if (options.record) {
      auto picture = std::make_shared<PlanGraph<ExactPoint>>();
      picture->kind = "roadmap";
      for (const AP& p : graph.points()) picture->vertices.push_back(nearest_rational(p));
      for (const auto& [key, link] : graph.links())
        if (!link.circle) picture->edges.emplace_back(key.first, key.second);
      report.recording.graph = std::move(picture);
    }
    const auto owned = [&](std::size_t owner) {
      return std::count(graph.owners().begin(), graph.owners().end(), owner);
    };
    if (owned(start_owner) == 0 || owned(goal_owner) == 0)
      return report.fail(PlanStatus::no_path, std::string(owned(start_owner) == 0 ? "the start" : "the goal") +
                                                  " sees no circle it could leave along: no path");
    SearchOptions s = search;
    s.record_expanded = options.record;
    s.record_trace = options.trace;
    const auto result = shortest_path(roadmap, graph.node_of(start_owner), graph.node_of(goal_owner), s);
    tally.count(result);
    report.recording.trace = plan_trace<ExactPoint>(result.trace, [&](RoadmapVertexId v) { return roadmap[v].exact; });
    if (!result.found)
      return report.fail(PlanStatus::no_path, "start and goal are not joined by tangents and arcs: no path");
    const std::vector<Piece> pieces = pieces_of(graph, result.path);
    report.path = {query.start};
    if (!pieces.empty()) {
      // The whole path checked again, piece by piece and at every joint, independently of how
      // the graph found it: a bug, never a tolerance call.
      if (auto why =
              tangent::path_blocked(rules, std::vector<tangent::CirclePiece>(pieces.begin(), pieces.end()), circles))
        throw std::logic_error("tangent visibility graph produced an invalid path: " + *why);
      tangent::LengthBounds total;
      for (const Piece& piece : pieces) {
        const auto bounds = tangent::length_bounds(piece, circles);
        total = total + bounds;
        const ExactPoint to = tangent::printed_point(piece.to, ends[piece.to_owner]);
        report.pieces.push_back(tangent::path_piece(
            piece, circles, tangent::printed_point(piece.from, ends[piece.from_owner]), to, bounds));
        report.path.push_back(to);
      }
      total.lower = std::max(0.0, total.lower);
      report.length = (total.lower + total.upper) / 2;
      report.facts.set(length_lower, total.lower);
      report.facts.set(length_upper, total.upper);
    }
    if (pieces.empty()) report.path.push_back(query.goal);  // a start that is its goal
    else report.path.back() = query.goal;                   // exactly
    report.succeed();
    report.certificate = {true,
                          "exact tangent and arc checks in real algebraic numbers (CORE), lengths bounded outward"};
  });
}

TangentVisibilityGraph::TangentVisibilityGraph(const RoundWorld& world, SearchOptions search)
    : impl_(std::make_unique<Impl>(world, search)) {}
TangentVisibilityGraph::~TangentVisibilityGraph() = default;
TangentVisibilityGraph::TangentVisibilityGraph(TangentVisibilityGraph&&) noexcept = default;
TangentVisibilityGraph& TangentVisibilityGraph::operator=(TangentVisibilityGraph&&) noexcept = default;

PlanReport<ExactPoint> TangentVisibilityGraph::plan(const Query& query, const QueryOptions& options) {
  return impl_->plan(query, options);
}

PlannerEntry<RoundRobot> tangent_visibility_planner_entry() {
  struct Options {
    SearchOptions search;
  };
  OptionTable<Options> table;
  add_search_options(table, &Options::search);
  return make_planner_entry<RoundRobot, Options>(
      "visibility", "exact shortest paths of a point or disc robot: tangents to circles and arcs along them",
      std::move(table), [](const RoundWorld& world, const Options& o) {
        return std::make_unique<TangentVisibilityGraph>(world, o.search);
      });
}

}  // namespace polyplan
