#include <polyplan/rotation/rotation_planner.hpp>

#include <polyplan/free_space/detail/free_space_triangulation.hpp>
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/turn_enclosure.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/query_tally.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/rotation/rotation_facts.hpp>
#include <polyplan/search/graph_search.hpp>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace polyplan {
namespace {

using detail::FreeSpaceTriangulation;
using detail::to_point;

constexpr std::size_t kOffLayer = static_cast<std::size_t>(-1);  // a query pose between layers
constexpr std::size_t kNoNode = static_cast<std::size_t>(-1);

struct PoseNode {
  std::size_t layer = kOffLayer;
  ExactPoint position;
  detail::Point point;  // the position in CGAL's kernel, made once: visibility tests take it by the thousand
  double x = 0, y = 0;
};
struct Motion {
  double cost = 0;
};
using PoseGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, PoseNode, Motion>;
using NodeId = boost::graph_traits<PoseGraph>::vertex_descriptor;
using PointKey = std::pair<Rational, Rational>;

// One layer's share of the roadmap.
struct LayerRoadmap {
  std::unique_ptr<FreeSpaceTriangulation> triangulation;
  std::map<PointKey, NodeId> node_at;            // every vertex of the layer, by position
  std::vector<NodeId> corner_of;                 // triangulation vertex → its node when a convex corner
  std::set<PointKey> pinches;                    // where the free space has zero width: no vertex goes there
  std::vector<std::vector<NodeId>> turn_points;  // per turn layer beside it: its corners here
};

// A query's start or goal: its pose and the layers it enters or leaves by, with the turn onto
// each (certified by `turns`, the exact C-spaces of its turn enclosures).
struct QueryEnd {
  Pose pose;
  std::size_t on_layer = kOffLayer;
  std::vector<std::size_t> entry_layers;       // off a layer: the nearest layers it can turn onto
  std::vector<double> entry_turns;             // degrees, pose → layer
  std::vector<std::unique_ptr<CSpace>> turns;  // the turn enclosures' C-spaces, by entry
};

// One query's ends in the roadmap: the poses resolved, and the vertices of the poses themselves.
struct QueryNodes {
  QueryEnd start, goal;
  NodeId from = kNoNode, to = kNoNode;
};

// What the walk along a found path measures while it certifies each motion.
struct WalkedPath {
  std::vector<Pose> poses;
  double turned = 0, translated = 0;  // degrees; length
  std::size_t turns_used = 0;
  std::vector<std::size_t> layers_used;
};

}  // namespace

struct RotationPlanner::Impl {
  RotationOptions options;
  double weight;
  RotationLayers layers;
  std::vector<LayerRoadmap> roadmaps;
  PoseGraph graph;
  // Vertices of the query being answered (start and goal in each layer), reused.
  std::vector<NodeId> query_pool;
  std::size_t query_vertices_used = 0;
  SearchWorkspace<NodeId> workspace;
  double build_seconds = 0;
  double max_error_radians = 0;

  Impl(const World& world, const RotationOptions& o)
      : options(o), weight(o.weight < 0 ? robot_radius(world.robot) : o.weight),
        layers(world, OrientationSet(o.orientations)) {
    for (const RotationLayer& layer : layers.layers()) {
      const double error = std::abs(std::remainder(degrees_of(layer.rotation) - layer.degrees, 360.0)) * pi / 180;
      max_error_radians = std::max(max_error_radians, error);
    }
    roadmaps.resize(layers.layers().size());
    for (std::size_t k = 0; k < roadmaps.size(); ++k) add_corners(k);
    for (std::size_t t = 0; t < layers.turns().size(); ++t) add_turn(t);
    for (std::size_t k = 0; k < roadmaps.size(); ++k) join_turn_points(k);
  }

  const World& world() const { return layers.world(); }
  const RotationLayer& layer(std::size_t k) const { return layers.layers()[k]; }

  double turn_cost(double degrees) const { return weight * std::abs(degrees) * pi / 180; }

  NodeId node(std::size_t k, const ExactPoint& p) {
    auto [at, added] = roadmaps[k].node_at.emplace(PointKey{p.x, p.y}, 0);
    if (added) {
      at->second = boost::add_vertex(graph);
      graph[at->second] = PoseNode{k, p, to_point(p), to_double(p.x), to_double(p.y)};
    }
    return at->second;
  }

  void add_translation(NodeId u, NodeId v) {
    boost::add_edge(u, v, Motion{std::hypot(graph[u].x - graph[v].x, graph[u].y - graph[v].y)}, graph);
  }

  // The layer's convex corners (a free wedge wider than 180°, not at a pinch point) and the
  // translations between those that see each other.
  void add_corners(std::size_t k) {
    LayerRoadmap& r = roadmaps[k];
    r.triangulation =
        std::make_unique<FreeSpaceTriangulation>(detail::CSpaceAccess::impl(*layer(k).cspace), query_points(world()));
    const FreeSpaceTriangulation& t = *r.triangulation;
    r.corner_of.assign(t.vertex_count(), kNoNode);
    std::vector<std::size_t> wedge_of(t.vertex_count(), 0);
    for (std::size_t v = 0; v < t.vertex_count(); ++v) {
      const auto& w = t.wedges(v);
      if (w.is_pinch()) {
        const ExactPoint p = detail::to_exact(t.point(v));
        r.pinches.emplace(p.x, p.y);
      }
      if (w.free_wedges() != 1) continue;
      for (std::size_t i = 0; i < w.size(); ++i)
        if (w.is_free(i) && w.is_reflex(i)) {
          r.corner_of[v] = node(k, detail::to_exact(t.point(v)));
          wedge_of[v] = i;
        }
    }
    std::vector<std::size_t> seen;
    for (std::size_t v = 0; v < t.vertex_count(); ++v) {
      if (r.corner_of[v] == kNoNode) continue;
      seen.clear();
      t.visible_from_corner(v, wedge_of[v], seen);
      for (std::size_t u : seen)
        if (u > v && r.corner_of[u] != kNoNode) add_translation(r.corner_of[v], r.corner_of[u]);
    }
  }

  // A turn layer's corners, in both layers it joins, and the turns between them. Not at a pinch
  // point of either layer: a vertex there would join the free wedges that meet at it, which no
  // motion may pass between (a turn on the spot is fine; leaving into the other wedge is not).
  void add_turn(std::size_t t) {
    const TurnLayer& turn = layers.turns()[t];
    std::vector<NodeId> from_nodes, to_nodes;
    for (const ExactPoint& p : turn.corners) {
      if (roadmaps[turn.from].pinches.count({p.x, p.y}) || roadmaps[turn.to].pinches.count({p.x, p.y})) continue;
      const NodeId a = node(turn.from, p), b = node(turn.to, p);
      from_nodes.push_back(a);
      to_nodes.push_back(b);
      boost::add_edge(a, b, Motion{turn_cost(turn.turn_degrees)}, graph);
    }
    roadmaps[turn.from].turn_points.push_back(std::move(from_nodes));
    roadmaps[turn.to].turn_points.push_back(std::move(to_nodes));
  }

  // Translations in layer k from `p` to the corners it sees, and to each of `others` it sees
  // (exact segment walks).
  void join(std::size_t k, NodeId p, const std::vector<NodeId>& others) {
    LayerRoadmap& r = roadmaps[k];
    const detail::Point& at = graph[p].point;
    std::vector<std::size_t> seen;
    r.triangulation->visible_from_point(at, seen);
    for (std::size_t v : seen)
      if (r.corner_of[v] != kNoNode && r.corner_of[v] != p) add_translation(p, r.corner_of[v]);
    for (NodeId q : others)
      if (q != p && !r.triangulation->why_blocked(at, graph[q].point)) add_translation(p, q);
  }

  // The turn points of a layer: to the corners they see, and to the turn points of the turn
  // layer on its other side (a path arrives by one turn and leaves by the next).
  void join_turn_points(std::size_t k) {
    LayerRoadmap& r = roadmaps[k];
    std::set<NodeId> corners;
    for (NodeId c : r.corner_of)
      if (c != kNoNode) corners.insert(c);
    for (std::size_t side = 0; side < r.turn_points.size(); ++side) {
      std::vector<NodeId> across;  // the turn points of the sides after this one (each pair once)
      for (std::size_t other = side + 1; other < r.turn_points.size(); ++other)
        across.insert(across.end(), r.turn_points[other].begin(), r.turn_points[other].end());
      for (NodeId p : r.turn_points[side])
        if (!corners.count(p)) join(k, p, across);  // a corner is joined as a corner already
    }
  }

  // Every vertex of layer k that is not a corner: what a query vertex tries to reach directly.
  std::vector<NodeId> turn_points_of(std::size_t k) const {
    std::vector<NodeId> all;
    for (const auto& side : roadmaps[k].turn_points) all.insert(all.end(), side.begin(), side.end());
    return all;
  }

  // The query's start or goal resolved: on a layer, or off it with certified turns onto the
  // nearest layers; a reason when it is not free or cannot reach any layer.
  std::optional<std::string> resolve(const ExactPoint& position, const std::optional<double>& theta, const char* what,
                                     QueryEnd& end) const {
    const OrientationSet& set = layers.orientations();
    const double asked = theta.value_or(0);
    const auto angle = set.normalized(asked);
    const std::string pose_text = to_string(Pose{position, {}, asked});
    if (!angle)
      return std::string("the ") + what + " " + pose_text + " is outside the orientations [" +
             angle_text(set.degrees(0)) + ", " + angle_text(set.degrees(set.size() - 1)) + "]";
    if (!roadmaps[0].triangulation->in_frame(position))
      return std::string("the ") + what + " " + pose_text +
             " is beyond the frame the planner triangulated around this world without bounds (give the world bounds)";
    if (const auto k = set.layer_at(*angle)) {
      end.on_layer = *k;
      end.pose = Pose{position, layer(*k).rotation, *angle};
      if (auto why = layer(*k).cspace->collision_at(position))
        return std::string("the ") + what + " " + pose_text + " is not free: " + *why;
      return std::nullopt;
    }
    end.pose = Pose{position, exact_rotation(*angle), *angle};
    const World own = world_with_robot(world(), rotated(world().robot, end.pose.rotation));
    if (auto why = CSpace(own).collision_at(position))
      return std::string("the ") + what + " " + pose_text + " is not free: " + *why;
    std::string refused;
    for (std::size_t k : set.nearest(*angle)) {
      auto turn = std::make_unique<CSpace>(  // a C-space keeps its own copy of the world
          world_with_robot(world(), turn_enclosure(world().robot, end.pose.rotation, layer(k).rotation)));
      if (auto why = turn->collision_at(position)) {
        refused += (refused.empty() ? "" : "; ") + std::string("turning to ") + angle_text(layer(k).degrees) +
                   ", what it sweeps is blocked: " + *why;
        continue;
      }
      end.entry_layers.push_back(k);
      end.entry_turns.push_back(polyplan::turn_degrees(end.pose.rotation, layer(k).rotation));
      end.turns.push_back(std::move(turn));
    }
    if (end.entry_layers.empty())
      return std::string("the ") + what + " " + pose_text + " cannot turn onto the nearest layer: " + refused;
    return std::nullopt;
  }

  // A vertex for this query only, from a pool that grows to the largest query and is reused.
  NodeId query_vertex(std::size_t k, const ExactPoint& p) {
    if (query_vertices_used == query_pool.size()) query_pool.push_back(boost::add_vertex(graph));
    const NodeId n = query_pool[query_vertices_used++];
    graph[n] = PoseNode{k, p, to_point(p), to_double(p.x), to_double(p.y)};
    return n;
  }

  void release_query_vertices() {
    for (std::size_t i = 0; i < query_vertices_used; ++i) {
      boost::clear_vertex(query_pool[i], graph);
      graph[query_pool[i]] = PoseNode{};
    }
    query_vertices_used = 0;
  }

  // A query's start or goal in the roadmap: a vertex at its position in every layer where the
  // robot is free there (not at a pinch point, which a path must not pass through), turns on the
  // spot between neighbouring layers where the turn layer is free there, and, for a pose between
  // layers, its own vertex with its certified turns onto the nearest layers. Returns the vertex of
  // the pose itself; `at_layer` gets the vertex in each layer (or kNoNode).
  NodeId enter(const QueryEnd& end, std::vector<NodeId>& at_layer) {
    const ExactPoint& p = end.pose.position;
    at_layer.assign(roadmaps.size(), kNoNode);
    for (std::size_t k = 0; k < roadmaps.size(); ++k)
      if (k == end.on_layer ||
          (layer(k).cspace->locate(p).kind != Location::Kind::blocked && !roadmaps[k].pinches.count({p.x, p.y})))
        at_layer[k] = query_vertex(k, p);
    for (const TurnLayer& t : layers.turns())
      if (at_layer[t.from] != kNoNode && at_layer[t.to] != kNoNode &&
          t.cspace->locate(p).kind != Location::Kind::blocked)
        boost::add_edge(at_layer[t.from], at_layer[t.to], Motion{turn_cost(t.turn_degrees)}, graph);
    if (end.on_layer != kOffLayer) return at_layer[end.on_layer];
    const NodeId pose = query_vertex(kOffLayer, p);
    for (std::size_t i = 0; i < end.entry_layers.size(); ++i)
      boost::add_edge(pose, at_layer[end.entry_layers[i]], Motion{turn_cost(end.entry_turns[i])}, graph);
    return pose;
  }

  // Joins the query's vertices in each layer to what they see there (and the start's to the goal's).
  void join_query(const std::vector<NodeId>& start_at, const std::vector<NodeId>& goal_at) {
    for (std::size_t k = 0; k < roadmaps.size(); ++k) {
      std::vector<NodeId> others = turn_points_of(k);
      if (goal_at[k] != kNoNode) others.push_back(goal_at[k]);
      if (start_at[k] != kNoNode) join(k, start_at[k], others);
      others.resize(others.size() - (goal_at[k] != kNoNode));
      if (goal_at[k] != kNoNode) join(k, goal_at[k], others);
    }
  }

  std::size_t fixed_vertices() const { return boost::num_vertices(graph) - query_pool.size(); }

  void record_facts(Facts& facts) const {
    facts.set(RoadmapFacts::kind, "rotation-layers");
    facts.set(RoadmapFacts::vertices, fixed_vertices());
    facts.set(RoadmapFacts::edges, boost::num_edges(graph));
    facts.set(RoadmapFacts::seconds, build_seconds);
    facts.set(RotationFacts::layers_count, layers.layers().size());
    facts.set(RotationFacts::layers_step, layers.orientations().step());
    facts.set(RotationFacts::layers_max_error_radians, max_error_radians);
    facts.set(RotationFacts::turn_layers_built, layers.turns().size());
    facts.set(RotationFacts::rotation_weight, weight);
    facts.set(SearchFacts::algorithm, to_string(options.search.algorithm));
  }

  // The pose angle of a node: its layer's, or a query end's own.
  double angle_of(NodeId n, const QueryNodes& q) const {
    if (graph[n].layer != kOffLayer) return layer(graph[n].layer).degrees;
    return n == q.from ? q.start.pose.degrees : q.goal.pose.degrees;
  }

  Pose pose_of(NodeId n, const QueryNodes& q) const {
    const PoseNode& v = graph[n];
    if (v.layer == kOffLayer) return n == q.from ? q.start.pose : q.goal.pose;
    return Pose{v.position, layer(v.layer).rotation, layer(v.layer).degrees};
  }

  // The search from the query's start to its goal. The heuristic's rotation part is shrunk by a
  // millionth: the costs use the exact rotations' angles, within 1e-10 rad of the nominal ones.
  SearchResult<NodeId> search(const QueryNodes& q) {
    const OrientationSet& set = layers.orientations();
    const auto heuristic = [&](NodeId n) {
      const PoseNode& v = graph[n];
      return std::hypot(v.x - graph[q.to].x, v.y - graph[q.to].y) +
             (1 - 1e-6) * turn_cost(set.distance(angle_of(n, q), q.goal.pose.degrees));
    };
    const auto cost = [&](const auto& e) { return graph[e].cost; };
    SearchOptions searching = options.search;
    searching.record_expanded = false;
    return shortest_path(graph, q.from, q.to, searching, heuristic, cost, workspace);
  }

  // The C-space that certifies the turn between two consecutive nodes of the path.
  const CSpace& turn_cspace(NodeId a, NodeId b, const QueryNodes& q) const {
    const std::size_t la = graph[a].layer, lb = graph[b].layer;
    for (const auto& [end, pose] : {std::pair{&q.start, q.from}, std::pair{&q.goal, q.to}})
      if (a == pose || b == pose)
        for (std::size_t i = 0; i < end->entry_layers.size(); ++i)
          if (end->entry_layers[i] == (a == pose ? lb : la)) return *end->turns[i];
    for (const TurnLayer& t : layers.turns())
      if ((t.from == la && t.to == lb) || (t.from == lb && t.to == la)) return *t.cspace;
    throw std::logic_error("rotation planner: a turn between layers that are not neighbours");
  }

  // The poses along the searched nodes, every motion certified again, exactly, before anything is
  // returned: a run of translations in one layer as one polyline (check_path also holds the pinch
  // rule at its bends), each turn on the spot by its turn layer.
  WalkedPath walk(const std::vector<NodeId>& nodes, const QueryNodes& q) const {
    WalkedPath walked;
    std::vector<ExactPoint> run;
    std::size_t run_layer = kOffLayer;
    const auto check_run = [&]() {
      if (run.size() >= 2) {
        const PathCheck check = check_path(*layer(run_layer).cspace, run);
        if (!check.valid)
          throw std::logic_error("rotation planner: translations in layer " + std::to_string(run_layer) +
                                 " fail the exact check: " + check.reason);
      }
      run.clear();
    };
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const NodeId n = nodes[i];
      const Pose pose = pose_of(n, q);
      if (i > 0) {
        const Pose& last = walked.poses.back();
        const NodeId previous = nodes[i - 1];
        if (last.rotation == pose.rotation) {  // a translation in one layer
          if (last.position == pose.position) continue;
          if (run.empty()) run.push_back(last.position);
          run_layer = graph[n].layer != kOffLayer ? graph[n].layer : graph[previous].layer;
          run.push_back(pose.position);
          walked.translated += std::hypot(to_double(last.position.x) - to_double(pose.position.x),
                                          to_double(last.position.y) - to_double(pose.position.y));
        } else {  // a turn on the spot, certified by its turn layer
          check_run();
          if (!(last.position == pose.position))
            throw std::logic_error("rotation planner: a motion that turns and translates");
          if (turn_cspace(previous, n, q).locate(pose.position).kind == Location::Kind::blocked)
            throw std::logic_error("rotation planner: a turn at " + to_string(pose.position) +
                                   " is not free in its turn layer");
          walked.turned += std::abs(turn_degrees(last.rotation, pose.rotation));
          ++walked.turns_used;
        }
      }
      walked.poses.push_back(pose);
      if (graph[n].layer != kOffLayer &&
          std::find(walked.layers_used.begin(), walked.layers_used.end(), graph[n].layer) == walked.layers_used.end())
        walked.layers_used.push_back(graph[n].layer);
    }
    check_run();
    const Pose& goal = q.goal.pose;
    if (walked.poses.size() == 1 || !(walked.poses.back().position == goal.position) ||
        !(walked.poses.back().rotation == goal.rotation))
      walked.poses.push_back(goal);  // start == goal: the path is that pose, begun and ended
    return walked;
  }

  std::string no_motion() const {
    const OrientationSet& set = layers.orientations();
    if (set.size() == 1)
      return "no motion joins start and goal at the one orientation " + angle_text(set.degrees(0)) + " (no turns)";
    return "no certified motion joins start and goal over " + std::to_string(set.size()) + " orientations " +
           angle_text(set.step()) + " apart (a turn is allowed only where its whole sweep is free)";
  }

  void record_walk(WalkedPath& walked, Facts& facts) const {
    facts.set(RotationFacts::rotation, walked.turned);
    facts.set(RotationFacts::translation_length, walked.translated);
    facts.set(RotationFacts::layers_used, walked.layers_used.size());
    // The actual angle of each layer the path uses (its exact rotation's), beside the nominal one.
    std::string actual;
    std::sort(walked.layers_used.begin(), walked.layers_used.end());
    for (std::size_t k : walked.layers_used)
      actual += (actual.empty() ? "" : ", ") + angle_text(layer(k).degrees) + " is " +
                angle_text(layer(k).degrees + std::remainder(degrees_of(layer(k).rotation) - layer(k).degrees, 360.0));
    facts.set(RotationFacts::layers_actual, actual);
    facts.set(RotationFacts::turn_layers_used, walked.turns_used);
  }
};

namespace {

// Angles unwrapped along the path, from the start's theta as the query gives it: consecutive
// poses differ by the turn between them, the short way (a turn from the layer at 355° to the one
// at 0° reads 355 → 360), so whoever interpolates between them follows the motion.
std::vector<Pose> unwrapped(std::vector<Pose> path, double start_theta) {
  double nominal = path.front().degrees;
  path.front().degrees = start_theta;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double next = path[i].degrees;
    path[i].degrees = path[i - 1].degrees + std::remainder(next - nominal, 360.0);
    nominal = next;
  }
  return path;
}

}  // namespace

RotationPlanner::RotationPlanner(const World& world, RotationOptions options)
    : impl_(build_timed<Impl>(world, options)) {}
RotationPlanner::~RotationPlanner() = default;
RotationPlanner::RotationPlanner(RotationPlanner&&) noexcept = default;
RotationPlanner& RotationPlanner::operator=(RotationPlanner&&) noexcept = default;

const RotationLayers& RotationPlanner::layers() const { return impl_->layers; }
double RotationPlanner::rotation_weight() const { return impl_->weight; }

// Nothing to record for a picture beyond the path: the strobe of poses is drawn from it.
PlanReport<Pose> RotationPlanner::plan(const Query& query, const QueryOptions&) {
  Impl& g = *impl_;
  return tallied_query<Pose>([&](PlanReport<Pose>& report, QueryTally& tally) {
    g.record_facts(report.facts);
    QueryNodes q;
    if (auto why = g.resolve(query.start, query.start_theta, "start", q.start))
      return report.fail(PlanStatus::invalid_query, *why);
    if (auto why = g.resolve(query.goal, query.goal_theta, "goal", q.goal))
      return report.fail(PlanStatus::invalid_query, *why);
    std::vector<NodeId> start_at, goal_at;
    q.from = g.enter(q.start, start_at);
    q.to = g.enter(q.goal, goal_at);
    g.join_query(start_at, goal_at);
    const auto result = g.search(q);
    tally.count(result);
    WalkedPath walked;
    if (result.found) {
      walked = g.walk(result.path, q);
      report.path = unwrapped(walked.poses, query.start_theta.value_or(0));
      report.succeed();
      report.length = walked.translated + g.turn_cost(walked.turned);
      report.certificate = {
          true, "exact path check in each layer; turns by their turn layers' exact C-spaces (swept-area enclosure)"};
    } else {
      report.fail(PlanStatus::not_found, g.no_motion());
    }
    g.release_query_vertices();
    g.record_walk(walked, report.facts);
  });
}

PlannerEntry<RotatingRobot> rotation_planner_entry() {
  OptionTable<RotationOptions> table;
  table.add(
      "rotation-step", "degrees between neighbouring orientations (layers)", std::string("number > 0"),
      [](const RotationOptions& o) { return detail::show_number(o.orientations.step); },
      [](RotationOptions& o, std::string_view text) -> std::optional<std::string> {
        const auto step = detail::parse_real_number(text);
        if (!step || *step <= 0) return "expected a number of degrees > 0";
        o.orientations.step = *step;
        return std::nullopt;
      },
      above(0));
  table.add(
      "rotation-count", "number of orientations (0: one every rotation-step)", std::string("whole number >= 0"),
      [](const RotationOptions& o) { return std::to_string(o.orientations.count); },
      [](RotationOptions& o, std::string_view text) -> std::optional<std::string> {
        const auto count = detail::parse_whole_number(text);
        if (!count || *count < 0) return "expected a whole number >= 0";
        o.orientations.count = static_cast<std::size_t>(*count);
        return std::nullopt;
      },
      at_least(0));
  table.add(
      "rotation-from", "first orientation, degrees", std::string("number"),
      [](const RotationOptions& o) { return detail::show_number(o.orientations.from); },
      [](RotationOptions& o, std::string_view text) -> std::optional<std::string> {
        const auto degrees = detail::parse_real_number(text);
        if (!degrees) return "expected a number of degrees";
        o.orientations.from = *degrees;
        return std::nullopt;
      },
      OptionRange{});
  table.add(
      "rotation-to", "last orientation, degrees (default and from + 360: the whole circle)", std::string("number"),
      [](const RotationOptions& o) {
        return o.orientations.to ? detail::show_number(*o.orientations.to) : std::string("from+360");
      },
      [](RotationOptions& o, std::string_view text) -> std::optional<std::string> {
        const auto degrees = detail::parse_real_number(text);
        if (!degrees) return "expected a number of degrees";
        o.orientations.to = *degrees;
        return std::nullopt;
      },
      OptionRange{});
  table.add(
      "rotation-weight", "cost of turning per radian (default: the robot's radius)",
      std::string("number >= 0 or radius"),
      [](const RotationOptions& o) { return o.weight < 0 ? std::string("radius") : detail::show_number(o.weight); },
      [](RotationOptions& o, std::string_view text) -> std::optional<std::string> {
        if (text == "radius") {
          o.weight = -1;
          return std::nullopt;
        }
        const auto weight = detail::parse_real_number(text);
        if (!weight || *weight < 0) return "expected a number >= 0 or radius";
        o.weight = *weight;
        return std::nullopt;
      },
      at_least(0));
  add_search_options(table, &RotationOptions::search);
  return make_planner_entry<RotatingRobot, RotationOptions>(
      "rotation", "translations and certified turns over exact rotation layers (discretized rotation)",
      std::move(table),
      [](const World& world, const RotationOptions& o) { return std::make_unique<RotationPlanner>(world, o); });
}

}  // namespace polyplan
