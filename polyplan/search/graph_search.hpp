#pragma once
// shortest_path on any Boost Graph IncidenceGraph: the roadmap, an implicit grid decided lazily,
// a lattice. Every algorithm is a BGL algorithm run without its O(V) initialisation:
//   astar, wastar, dijkstra, greedy  boost::astar_search_no_init (4-ary mutable heap)
//   bfs                              boost::breadth_first_visit (FIFO)
//   dfs                              boost::depth_first_visit (non-recursive, with a terminator)
// The per-vertex state lives in a SearchWorkspace reused across queries; a visitor counts what a
// course compares and stops the search at the goal by throwing (the BGL idiom), and on request
// records the search's trace for watching it (SearchOptions::record_trace, search/search_trace.hpp)
// and breaks ties of f as the course's graph-search homework's queue does (SearchOptions::ties_first_discovered).
//
// Requirements on the graph: boost::graph_traits<Graph> describes an IncidenceGraph (out_edges,
// source, target) whose vertex_descriptor is copyable, equality-comparable and hashable by the
// workspace's Hash. A VertexListGraph is not needed: nothing iterates over all vertices.
//
// Heavy include (the BGL algorithms): include it where a search is instantiated, not in headers
// that merely name search types (those want search/search_result.hpp and search/search_workspace.hpp).
#include <polyplan/search/search_result.hpp>
#include <polyplan/search/search_workspace.hpp>

#include <boost/graph/astar_search.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace polyplan {

namespace detail {

struct WorkspaceAccess {
  template <class W>
  static auto& hashed(W& ws) {
    return ws.hashed_;
  }
  template <class W>
  static auto& dense(W& ws) {
    return ws.dense_;
  }
  template <class W>
  static auto& fifo(W& ws) {
    return ws.fifo_;
  }
  template <class W>
  static void set_used_dense(W& ws, bool dense) {
    ws.used_dense_ = dense;
  }
};

// ---- property maps over a workspace table: absent records read as the BGL initial values ----

struct DistanceField {
  template <class Vertex>
  using value_type = double;
  template <class R>
  static double read(const R& r) {
    return r.distance;
  }
  template <class R>
  static void write(R& r, double x) {
    r.distance = x;
  }
  template <class Vertex>
  static double absent(const Vertex&) {
    return unreached;
  }
};

struct RankField {
  template <class Vertex>
  using value_type = double;
  template <class R>
  static double read(const R& r) {
    return r.rank;
  }
  template <class R>
  static void write(R& r, double x) {
    r.rank = x;
  }
  template <class Vertex>
  static double absent(const Vertex&) {
    return unreached;
  }
};

struct PredecessorField {
  template <class Vertex>
  using value_type = Vertex;
  template <class R>
  static auto read(const R& r) {
    return r.predecessor;
  }
  template <class R, class Vertex>
  static void write(R& r, const Vertex& x) {
    r.predecessor = x;
  }
  template <class Vertex>
  static Vertex absent(const Vertex& v) {
    return v;
  }
};

struct ColorField {
  template <class Vertex>
  using value_type = boost::default_color_type;
  template <class R>
  static boost::default_color_type read(const R& r) {
    return static_cast<boost::default_color_type>(r.color);
  }
  template <class R>
  static void write(R& r, boost::default_color_type x) {
    r.color = static_cast<std::uint8_t>(x);
  }
  template <class Vertex>
  static boost::default_color_type absent(const Vertex&) {
    return boost::white_color;
  }
};

template <class Table, class Vertex, class Field>
class RecordMap {
 public:
  using key_type = Vertex;
  using value_type = typename Field::template value_type<Vertex>;
  using reference = value_type;
  using category = boost::read_write_property_map_tag;

  explicit RecordMap(Table& table) : table_(&table) {}

  friend value_type get(const RecordMap& m, const key_type& v) {
    if (const auto* r = m.table_->find(v)) return Field::read(*r);
    return Field::absent(v);
  }
  friend void put(const RecordMap& m, const key_type& v, const value_type& x) { Field::write(m.table_->touch(v), x); }

 private:
  Table* table_;
};

// The vertex index astar_search_no_init gives its heap (a vector_property_map over it): the order in
// which this query first touched each vertex, so that vector grows with the vertices touched, not
// with the largest vertex id.
template <class Table, class Vertex>
class SlotMap {
 public:
  using key_type = Vertex;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;

  explicit SlotMap(Table& table) : table_(&table) {}
  friend std::size_t get(const SlotMap& m, const key_type& v) { return m.table_->touch(v).slot; }

 private:
  Table* table_;
};

// The open-list key with ties_first_discovered: the rank, then the order of first touch, which for
// a best-first search is the order in which vertices entered the open list (a vertex is first
// touched when its distance is first set).
struct RankThenSlot {
  double rank = 0;
  std::uint32_t slot = 0;
  RankThenSlot() = default;
  // Implicit: Boost keeps its zero (a plain 0.0) as a value of the rank map's type.
  RankThenSlot(double r, std::uint32_t s = 0) : rank(r), slot(s) {}
};

struct RankThenSlotLess {
  // Distances (relax) are compared as plain numbers; a weight with Boost's zero (the negative-weight
  // check) as RankThenSlot of slot 0, which is the same.
  bool operator()(double a, double b) const { return a < b; }
  bool operator()(const RankThenSlot& a, const RankThenSlot& b) const {
    return a.rank < b.rank || (a.rank == b.rank && a.slot < b.slot);
  }
};

// The rank map the heap reads as RankThenSlot; Boost writes plain ranks into it.
template <class Table, class Vertex>
class RankThenSlotMap {
 public:
  using key_type = Vertex;
  using value_type = RankThenSlot;
  using reference = RankThenSlot;
  using category = boost::read_write_property_map_tag;

  explicit RankThenSlotMap(Table& table) : table_(&table) {}
  friend RankThenSlot get(const RankThenSlotMap& m, const key_type& v) {
    if (const auto* r = m.table_->find(v)) return {r->rank, r->slot};
    return {unreached, static_cast<std::uint32_t>(-1)};
  }
  friend void put(const RankThenSlotMap& m, const key_type& v, double rank) { m.table_->touch(v).rank = rank; }

 private:
  Table* table_;
};

template <class Edge, class WeightFn>
class FunctionWeightMap {
 public:
  using key_type = Edge;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;

  explicit FunctionWeightMap(const WeightFn& fn) : fn_(fn) {}
  friend double get(const FunctionWeightMap& m, const key_type& e) { return m.fn_(e); }

 private:
  WeightFn fn_;
};

// The textbook's weighted A* (SearchOptions::reopen false): an edge into a closed (black) vertex
// weighs infinity, so Boost's relax lowers no closed vertex's distance and never re-opens it, and
// the weight function is not even asked for those edges. Boost offers no other hook: its visitor
// hears of a re-opening only after it happened.
template <class Graph, class WeightMap, class ColorMap>
class ClosedTargetsOutOfReach {
 public:
  using key_type = typename WeightMap::key_type;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;

  ClosedTargetsOutOfReach(const Graph& g, const WeightMap& weights, const ColorMap& color)
      : g_(&g), weights_(weights), color_(color) {}
  friend double get(const ClosedTargetsOutOfReach& m, const key_type& e) {
    return get(m.color_, target(e, *m.g_)) == boost::black_color ? unreached : get(m.weights_, e);
  }

 private:
  const Graph* g_;
  WeightMap weights_;
  ColorMap color_;
};

// Greedy best-first is A* on these: g stays 0, so f = h.
template <class Edge>
struct ZeroWeightMap {
  using key_type = Edge;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;
  friend double get(const ZeroWeightMap&, const key_type&) { return 0.0; }
};

struct ZeroHeuristic {
  template <class Vertex>
  double operator()(const Vertex&) const {
    return 0.0;
  }
};

template <class Heuristic>
struct ScaledHeuristic {
  Heuristic h;
  double weight;
  template <class Vertex>
  double operator()(const Vertex& v) const {
    return weight * h(v);
  }
};

// ---- visitors: count, record tree edges, stop at the goal ----

struct FoundGoal {};  // thrown through the BGL algorithm; never leaves shortest_path

// Which vertices end the search: one goal, or any of several (shortest_path_to_any). The first one
// the search takes out of its open list (DFS: discovers) is recorded in `reached`.
template <class Vertex>
class GoalTest {
 public:
  GoalTest(const Vertex* goals, std::size_t count, Vertex& reached)
      : goals_(goals), count_(count), reached_(&reached) {}
  void stop_if_goal(const Vertex& u) const {
    for (std::size_t i = 0; i < count_; ++i)
      if (u == goals_[i]) {
        *reached_ = u;
        throw FoundGoal{};
      }
  }

 private:
  const Vertex* goals_;
  std::size_t count_;
  Vertex* reached_;
};

struct SearchCounts {
  std::size_t expanded = 0, generated = 0;
  std::size_t reopened = 0;  // closed vertices given a shorter distance (weighted A* with reopen, inconsistent h)
};

// Records SearchOptions::record_trace (search/search_trace.hpp) from the visitors' events. It keeps
// its own g and backpointer per vertex, summed with the real weights, so that greedy (searched on
// zero weights), bfs and dfs report the cost of their backpointer paths too; for astar, wastar and
// dijkstra its g is Boost's distance, summed in the same order.
template <class Vertex, class Hash, class Heuristic, class WeightFn, class PredecessorMap>
class TraceRecorder {
 public:
  TraceRecorder(SearchTrace<Vertex>& out, const SearchOptions& options, const Heuristic& heuristic,
                const WeightFn& weight, PredecessorMap predecessor)
      : out_(&out), algorithm_(options.algorithm), weighting_(options.weight), heuristic_(&heuristic), weight_(&weight),
        predecessor_(predecessor) {}

  // A vertex enters the open list. Only the start arrives without a tree edge labelling it first.
  void discovered(const Vertex& v) {
    if (!labels_.count(v)) set_label(v, 0.0, std::nullopt);
    ++open_;
  }
  // A closed vertex given a shorter distance goes back into the open list (weighted A* with reopen).
  void reopened() { ++open_; }
  // A vertex taken out of the open list (best-first searches, bfs).
  void examined(const Vertex& u) {
    --open_;
    expand(u);
  }
  // DFS expands a vertex as it discovers it; its "open list" is the stack of unfinished vertices.
  void discovered_depth_first(const Vertex& u) {
    if (!labels_.count(u)) set_label(u, 0.0, std::nullopt);
    expand(u);
    ++open_;
  }
  void finished_depth_first() { --open_; }
  // Boost's relax lowered a distance. On an undirected graph it may have lowered the edge's source
  // from its target: the predecessor map says which end moved.
  template <class Edge, class Graph>
  void relaxed(const Edge& e, const Graph& g) {
    const Vertex s = source(e, g), t = target(e, g);
    if (get(predecessor_, t) == s) label_through(t, s, e);
    else if (get(predecessor_, s) == t) label_through(s, t, e);
  }
  // bfs and dfs: the edge that discovered its target.
  template <class Edge, class Graph>
  void tree_edge(const Edge& e, const Graph& g) {
    label_through(target(e, g), source(e, g), e);
  }

 private:
  struct Label {
    double g;
    std::optional<Vertex> backpointer;
  };
  template <class Edge>
  void label_through(const Vertex& v, const Vertex& from, const Edge& e) {
    set_label(v, labels_.at(from).g + static_cast<double>((*weight_)(e)), from);
  }
  void set_label(const Vertex& v, double g, std::optional<Vertex> backpointer) {
    const bool discovered = labels_.insert_or_assign(v, Label{g, backpointer}).second;
    const double h = static_cast<double>((*heuristic_)(v));
    out_->labels.push_back({out_->expansions.size(), v, g, h, key(g, h), backpointer, discovered});
  }
  double key(double g, double h) const {
    switch (algorithm_) {
      case Search::wastar: return g + weighting_ * h;
      case Search::dijkstra: return g;
      case Search::greedy: return h;
      default: return g + h;
    }
  }
  void expand(const Vertex& u) {
    const Label& label = labels_.at(u);
    const double h = static_cast<double>((*heuristic_)(u));
    out_->expansions.push_back({out_->expansions.size() + 1, u, label.g, h, key(label.g, h), label.backpointer, open_});
  }

  SearchTrace<Vertex>* out_;
  Search algorithm_;
  double weighting_;
  const Heuristic* heuristic_;
  const WeightFn* weight_;
  PredecessorMap predecessor_;
  std::unordered_map<Vertex, Label, Hash> labels_;
  std::size_t open_ = 0;
};

// The visitors take a recorder pointer, null when no trace is recorded.
template <class Vertex, class Recorder>
class AStarGoalVisitor : public boost::default_astar_visitor {
 public:
  AStarGoalVisitor(const GoalTest<Vertex>& goal, SearchCounts& counts, std::vector<Vertex>* trace, Recorder* recorder)
      : goal_(goal), counts_(&counts), trace_(trace), recorder_(recorder) {}
  template <class Graph>
  void discover_vertex(const Vertex& v, const Graph&) {
    ++counts_->generated;
    if (recorder_) recorder_->discovered(v);
  }
  template <class Graph>
  void examine_vertex(const Vertex& u, const Graph&) {
    ++counts_->expanded;
    if (trace_) trace_->push_back(u);
    if (recorder_) recorder_->examined(u);
    goal_.stop_if_goal(u);
  }
  template <class Edge, class Graph>
  void edge_relaxed(const Edge& e, const Graph& g) {
    if (recorder_) recorder_->relaxed(e, g);
  }
  // BGL calls it only when the relaxation re-opened a closed vertex.
  template <class Edge, class Graph>
  void black_target(const Edge&, const Graph&) {
    ++counts_->reopened;
    if (recorder_) recorder_->reopened();
  }

 private:
  GoalTest<Vertex> goal_;
  SearchCounts* counts_;
  std::vector<Vertex>* trace_;  // expansion order, when recorded
  Recorder* recorder_;
};

template <class Vertex, class PredecessorMap, class Recorder>
class BfsGoalVisitor : public boost::default_bfs_visitor {
 public:
  BfsGoalVisitor(const GoalTest<Vertex>& goal, SearchCounts& counts, PredecessorMap predecessor,
                 std::vector<Vertex>* trace, Recorder* recorder)
      : goal_(goal), counts_(&counts), predecessor_(predecessor), trace_(trace), recorder_(recorder) {}
  template <class Graph>
  void discover_vertex(const Vertex& v, const Graph&) {
    ++counts_->generated;
    if (recorder_) recorder_->discovered(v);
  }
  template <class Graph>
  void examine_vertex(const Vertex& u, const Graph&) {
    ++counts_->expanded;
    if (trace_) trace_->push_back(u);
    if (recorder_) recorder_->examined(u);
    goal_.stop_if_goal(u);
  }
  template <class Edge, class Graph>
  void tree_edge(const Edge& e, const Graph& g) {
    put(predecessor_, target(e, g), source(e, g));
    if (recorder_) recorder_->tree_edge(e, g);
  }

 private:
  GoalTest<Vertex> goal_;
  SearchCounts* counts_;
  PredecessorMap predecessor_;
  std::vector<Vertex>* trace_;
  Recorder* recorder_;
};

template <class Vertex, class PredecessorMap, class Recorder>
class DfsCountingVisitor : public boost::default_dfs_visitor {
 public:
  DfsCountingVisitor(SearchCounts& counts, PredecessorMap predecessor, std::vector<Vertex>* trace, Recorder* recorder)
      : counts_(&counts), predecessor_(predecessor), trace_(trace), recorder_(recorder) {}
  template <class Graph>
  void discover_vertex(const Vertex& u, const Graph&) {
    ++counts_->generated;
    ++counts_->expanded;
    if (trace_) trace_->push_back(u);
    if (recorder_) recorder_->discovered_depth_first(u);
  }
  template <class Graph>
  void finish_vertex(const Vertex&, const Graph&) {
    if (recorder_) recorder_->finished_depth_first();
  }
  template <class Edge, class Graph>
  void tree_edge(const Edge& e, const Graph& g) {
    put(predecessor_, target(e, g), source(e, g));
    if (recorder_) recorder_->tree_edge(e, g);
  }

 private:
  SearchCounts* counts_;
  PredecessorMap predecessor_;
  std::vector<Vertex>* trace_;
  Recorder* recorder_;
};

// depth_first_visit asks its terminator about every vertex right after discovering it: the goal
// test of DFS.
template <class Vertex>
struct StopAtGoal {
  GoalTest<Vertex> goal;
  template <class Graph>
  bool operator()(const Vertex& u, const Graph&) const {
    goal.stop_if_goal(u);
    return false;
  }
};

// Sum of the weights along `path`, in path order (the order A* sums g, so for A* and Dijkstra the
// result equals the goal's distance to the last bit). Between consecutive vertices the lightest
// out-edge counts: that is the one a relaxation keeps among parallel edges.
template <class Graph, class Vertex, class WeightFn>
double path_cost(const Graph& g, const std::vector<Vertex>& path, const WeightFn& weight) {
  double cost = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    double lightest = unreached;
    for (auto [e, end] = out_edges(path[i], g); e != end; ++e)
      if (target(*e, g) == path[i + 1]) lightest = std::min(lightest, static_cast<double>(weight(*e)));
    cost += lightest;
  }
  return cost;
}

// Hash: the workspace's, for the trace recorder's labels.
template <class Hash, class Graph, class Table, class Heuristic, class WeightFn>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> search_with_table(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    const std::vector<typename boost::graph_traits<Graph>::vertex_descriptor>& goals, const SearchOptions& options,
    const Heuristic& heuristic, const WeightFn& weight, Table& table,
    FifoBuffer<typename boost::graph_traits<Graph>::vertex_descriptor>& fifo) {
  using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;
  Vertex goal = start;  // the goal the search reaches
  const GoalTest<Vertex> is_goal(goals.data(), goals.size(), goal);
  using Edge = typename boost::graph_traits<Graph>::edge_descriptor;
  const RecordMap<Table, Vertex, DistanceField> distance(table);
  const RecordMap<Table, Vertex, RankField> rank(table);
  const RecordMap<Table, Vertex, PredecessorField> predecessor(table);
  const RecordMap<Table, Vertex, ColorField> color(table);
  const SlotMap<Table, Vertex> slots(table);
  const FunctionWeightMap<Edge, WeightFn> weights(weight);

  SearchCounts counts;
  SearchResult<Vertex> result;
  std::vector<Vertex>* trace = options.record_expanded ? &result.expanded_order : nullptr;
  using Recorder = TraceRecorder<Vertex, Hash, Heuristic, WeightFn, decltype(predecessor)>;
  std::optional<Recorder> recording;
  if (options.record_trace) recording.emplace(result.trace, options, heuristic, weight, predecessor);
  Recorder* recorder = recording ? &*recording : nullptr;
  const auto best_first = [&](auto h, auto edge_weights) {
    put(distance, start, 0.0);
    put(rank, start, h(start));
    const AStarGoalVisitor<Vertex, Recorder> visitor(is_goal, counts, trace, recorder);
    if (options.ties_first_discovered)
      boost::astar_search_no_init(g, start, h, visitor, predecessor, RankThenSlotMap<Table, Vertex>(table), distance,
                                  edge_weights, color, slots, RankThenSlotLess{}, std::plus<double>(), unreached, 0.0);
    else
      boost::astar_search_no_init(g, start, h, visitor, predecessor, rank, distance, edge_weights, color, slots,
                                  std::less<double>(), std::plus<double>(), unreached, 0.0);
  };

  try {
    switch (options.algorithm) {
      case Search::astar: best_first(heuristic, weights); break;
      case Search::wastar:
        if (options.reopen) best_first(ScaledHeuristic<Heuristic>{heuristic, options.weight}, weights);
        else
          best_first(ScaledHeuristic<Heuristic>{heuristic, options.weight},
                     ClosedTargetsOutOfReach<Graph, decltype(weights), decltype(color)>(g, weights, color));
        break;
      case Search::dijkstra: best_first(ZeroHeuristic{}, weights); break;
      case Search::greedy: best_first(heuristic, ZeroWeightMap<Edge>{}); break;
      case Search::bfs:
        fifo.clear();
        boost::breadth_first_visit(
            g, start, fifo,
            BfsGoalVisitor<Vertex, decltype(predecessor), Recorder>(is_goal, counts, predecessor, trace, recorder),
            color);
        break;
      case Search::dfs:
        boost::depth_first_visit(
            g, start, DfsCountingVisitor<Vertex, decltype(predecessor), Recorder>(counts, predecessor, trace, recorder),
            color, StopAtGoal<Vertex>{is_goal});
        break;
    }
  } catch (const FoundGoal&) {
    result.found = true;
  }
  result.expanded = counts.expanded;
  result.generated = counts.generated;
  if (result.found) {
    // Predecessor chains end at the start (its own predecessor); the bound only guards the
    // impossible cycle, never a real path (each path vertex was touched).
    result.path.push_back(goal);
    while (!(result.path.back() == start)) {
      const Vertex p = get(predecessor, result.path.back());
      if (p == result.path.back() || result.path.size() > table.touched())
        throw std::logic_error("polyplan::shortest_path: broken predecessor chain");
      result.path.push_back(p);
    }
    std::reverse(result.path.begin(), result.path.end());
    // A best-first search that summed weights holds the goal's g, summed in path order, and it is
    // the predecessor chain's sum unless a closed vertex's g went down after it was expanded: a
    // re-opening, or on an undirected graph BGL's relax lowering the edge's source without telling
    // any visitor (weighted A*, inconsistent h). Otherwise, and for the searches that ignored the
    // weights (greedy, bfs, dfs), the path's weights are summed now.
    const bool summed_weights = options.algorithm == Search::astar || options.algorithm == Search::dijkstra ||
                                options.algorithm == Search::wastar;
    const bool g_is_the_path_cost = summed_weights && counts.reopened == 0 && boost::is_directed(g);
    result.cost = g_is_the_path_cost ? get(distance, goal) : path_cost(g, result.path, weight);
  }
  return result;
}

inline void check_options(const SearchOptions& options) {
  if (options.algorithm == Search::wastar && !(std::isfinite(options.weight) && options.weight >= 1.0))
    throw std::invalid_argument("shortest_path: weighted A* needs a finite weight >= 1");
  if (to_string(options.algorithm) == "unknown") throw std::invalid_argument("shortest_path: unknown algorithm");
}

}  // namespace detail

// shortest_path (below) to any one of `goals` (at least one): the search stops at the first goal it takes out of
// its open list (DFS: discovers), which for A* with a heuristic admissible to every goal (the
// minimum over them, say) and for Dijkstra is a nearest one; the path ends there (path.back()).
// Throws std::invalid_argument when `goals` is empty, and as shortest_path does.
template <class Graph, class Heuristic, class WeightFn, class Hash>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> shortest_path_to_any(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    const std::vector<typename boost::graph_traits<Graph>::vertex_descriptor>& goals, const SearchOptions& options,
    Heuristic heuristic, WeightFn weight,
    SearchWorkspace<typename boost::graph_traits<Graph>::vertex_descriptor, Hash>& workspace) {
  detail::check_options(options);
  if (goals.empty()) throw std::invalid_argument("shortest_path_to_any: no goal");
  const auto began = std::chrono::steady_clock::now();
  auto& fifo = detail::WorkspaceAccess::fifo(workspace);
  auto result = [&] {
    if constexpr (has_dense_vertex_ids<Graph>::value) {
      const std::size_t n = num_vertices(g);
      const auto outside = [&](auto v) { return static_cast<std::size_t>(v) >= n; };
      if (outside(start) || std::any_of(goals.begin(), goals.end(), outside))
        throw std::out_of_range("shortest_path: start or goal is not a vertex of the graph");
      if (workspace.storage() == VertexStorage::automatic && dense_vertex_table_fits(g)) {
        auto& table = detail::WorkspaceAccess::dense(workspace);
        detail::WorkspaceAccess::set_used_dense(workspace, true);
        table.begin_query(n);
        return detail::search_with_table<Hash>(g, start, goals, options, heuristic, weight, table, fifo);
      }
    }
    auto& table = detail::WorkspaceAccess::hashed(workspace);
    detail::WorkspaceAccess::set_used_dense(workspace, false);
    table.begin_query();
    return detail::search_with_table<Hash>(g, start, goals, options, heuristic, weight, table, fifo);
  }();
  result.algorithm = options.algorithm;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return result;
}

// Searches g from start to goal with options.algorithm.
//   heuristic: double(const Vertex&), an estimate of the cost to the goal (admissible for A* to be
//              optimal); ignored by dijkstra, bfs and dfs.
//   weight:    double(const Edge&) >= 0, the cost of an edge (boost::negative_edge otherwise);
//              bfs, dfs and greedy ignore it while searching and use it for the reported cost.
//   workspace: reused across queries; its state from earlier queries never leaks into this one.
// Throws std::invalid_argument for a weighted-A* weight that is not finite and >= 1, and
// std::out_of_range for a vertex id outside a graph with dense ids.
template <class Graph, class Heuristic, class WeightFn, class Hash>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> shortest_path(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    typename boost::graph_traits<Graph>::vertex_descriptor goal, const SearchOptions& options, Heuristic heuristic,
    WeightFn weight, SearchWorkspace<typename boost::graph_traits<Graph>::vertex_descriptor, Hash>& workspace) {
  return shortest_path_to_any(g, start, {goal}, options, heuristic, weight, workspace);
}

// One query with a fresh hash-storage workspace: cost proportional to what the search touches.
// For many queries on one graph, keep a SearchWorkspace and pass it.
template <class Graph, class Heuristic, class WeightFn>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> shortest_path_to_any(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    const std::vector<typename boost::graph_traits<Graph>::vertex_descriptor>& goals, const SearchOptions& options,
    Heuristic heuristic, WeightFn weight) {
  SearchWorkspace<typename boost::graph_traits<Graph>::vertex_descriptor> workspace(VertexStorage::hashed);
  return shortest_path_to_any(g, start, goals, options, heuristic, weight, workspace);
}
template <class Graph, class Heuristic, class WeightFn>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> shortest_path(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    typename boost::graph_traits<Graph>::vertex_descriptor goal, const SearchOptions& options, Heuristic heuristic,
    WeightFn weight) {
  return shortest_path_to_any(g, start, {goal}, options, heuristic, weight);
}

}  // namespace polyplan
