#pragma once
// Incremental shortest paths on graphs whose edge costs change: LPA* (Koenig, Likhachev & Furcy,
// "Lifelong Planning A*", AIJ 2004) and D* Lite (Koenig & Likhachev, AAAI 2002: the optimized
// version of its Figure 4, with the key modifier k_m). One algorithm, run in either direction:
//
//   LpaStar    searches from the start: g(s) is the cost start → s, rhs(s) = min over
//              predecessors p of g(p) + c(p, s); the goal may be moved (move_goal re-keys the
//              open list, which is what D* Lite's k_m exists to avoid).
//   DStarLite  searches from the goal: g(s) is the cost s → goal, rhs(s) = min over successors of
//              c(s, p) + g(p); the start may move (move_start: k_m += h(s_last, s_start)).
//
// After compute_shortest_path() the vertex the search is aimed at (LPA*'s goal, D* Lite's start)
// is locally consistent: its g is its optimal cost, and path() follows the minimising neighbours.
// The loop runs while the open list's top key is below that vertex's key *or* the vertex is
// inconsistent either way (the paper tests only rhs > g): with exact costs a tie between the two
// keys may otherwise stop the search with the aimed-at vertex overconsistent, its rhs right but the
// g values path() reads not yet settled.
//
// Requirements (all header-only, so that any graph the other searches take can be used):
// - Graph: a Boost Graph IncidenceGraph (out_edges, target) whose every edge has its reverse
//   (GridGraph, an undirected Roadmap) and whose vertex ids are 0..num_vertices(g)-1: per-vertex
//   state is a flat table (has_dense_vertex_ids).
// - Costs: `Cost operator()(Vertex from, Vertex to) const`, the cost of the move, Cost::infinity()
//   when it is blocked; costs may change between calls if the search is told (edge_changed). For
//   update_edge, also `void set(Vertex from, Vertex to, Cost)`.
// - Heuristic: `Cost operator()(Vertex from, Vertex to) const`, a consistent lower bound on the
//   cost from → to under every cost the edges will take (the free-space distance).
// - Cost: default-constructed zero, Cost::infinity(), exact +, <=> and ==, to_double() (for
//   traces). OctileLength (search/octile_length.hpp) on grids: every comparison exact, so the costs
//   reported equal a fresh search's exactly and ties are true ties; ScaledLength on a stored
//   Roadmap (search/roadmap_costs.hpp): integer units, exact sums.
//
// Not thread-safe; one search per thread. Heavy include (Boost.Heap): include it where a search
// is instantiated.
#include <polyplan/search/search_workspace.hpp>

#include <boost/graph/graph_traits.hpp>
#include <boost/heap/d_ary_heap.hpp>

#include <algorithm>
#include <chrono>
#include <compare>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace polyplan {

enum class IncrementalDirection { from_start, from_goal };

// What a search did, summed over its life (subtract two readings for one call).
struct IncrementalCounts {
  std::size_t expanded = 0;   // vertices taken from the open list and made consistent or raised to ∞
  std::size_t generated = 0;  // vertices put in the open list for the first time
  std::size_t heap_pushes = 0, heap_pops = 0, heap_updates = 0, heap_removals = 0;
  std::size_t searches = 0;  // calls of compute_shortest_path
  std::size_t heap_operations() const { return heap_pushes + heap_pops + heap_updates + heap_removals; }
};

// No preference between equally good neighbours in path_to_root: the first found keeps its place.
struct NoTieBreak {
  template <class Vertex>
  bool operator()(Vertex, Vertex) const {
    return false;
  }
};

template <class Cost>
struct IncrementalKey {
  Cost first{}, second{};  // [min(g, rhs) + h + k_m; min(g, rhs)]
  friend bool operator==(const IncrementalKey&, const IncrementalKey&) = default;
  friend auto operator<=>(const IncrementalKey& a, const IncrementalKey& b) {
    if (const auto c = a.first <=> b.first; c != 0) return c;
    return a.second <=> b.second;
  }
};

// g > rhs: overconsistent (it will get cheaper), g < rhs: underconsistent (it got dearer).
enum class Consistency { consistent, overconsistent, underconsistent };

template <class Cost>
Consistency consistency(const Cost& g, const Cost& rhs) {
  if (g == rhs) return Consistency::consistent;
  return g > rhs ? Consistency::overconsistent : Consistency::underconsistent;
}

// What a step's UpdateVertex did to a vertex's place in the open list (the seed's "add", "readd").
enum class OpenListAction { added, rekeyed, removed, unchanged };

template <class Vertex, class Cost>
struct OpenListEntry {
  Vertex vertex{};
  Cost g{}, rhs{};
  IncrementalKey<Cost> key{};
  Consistency state = Consistency::consistent;
};

// One pass of compute_shortest_path's loop, as a course works it by hand.
template <class Vertex, class Cost>
struct IncrementalStep {
  enum class Kind {
    overconsistent,   // g(u) := rhs(u); its neighbours' rhs lowered
    underconsistent,  // g(u) := ∞; the neighbours whose rhs rested on it recomputed
    stale_key,        // its key was out of date (k_m grew): put back with the new one
  };
  struct Update {
    Vertex vertex{};
    Cost g{}, rhs{};
    OpenListAction action = OpenListAction::unchanged;
  };
  Vertex popped{};
  IncrementalKey<Cost> key{};  // the key it was popped with
  Cost g_before{}, g_after{}, rhs{};
  Kind kind = Kind::overconsistent;
  std::vector<Update> updated;  // the vertices whose rhs or open-list membership this pass changed, in order
                                // (the popped vertex itself too, when it was raised)
};

// BGL-visitor-like hook: called after each pass with what it did; the search is there to be read
// (open_list()), not changed.
template <class Search>
struct IncrementalObserver {
  virtual ~IncrementalObserver() = default;
  virtual void step(const Search&,
                    const IncrementalStep<typename Search::vertex_type, typename Search::cost_type>&) = 0;
};

template <class Graph, class Costs, class Heuristic, IncrementalDirection Direction>
class IncrementalSearch {
 public:
  using vertex_type = typename boost::graph_traits<Graph>::vertex_descriptor;
  using cost_type = decltype(std::declval<const Costs&>()(std::declval<vertex_type>(), std::declval<vertex_type>()));
  using Key = IncrementalKey<cost_type>;
  using Step = IncrementalStep<vertex_type, cost_type>;
  using Observer = IncrementalObserver<IncrementalSearch>;
  static_assert(has_dense_vertex_ids<Graph>::value, "the incremental searches keep a flat table per vertex");

  // Throws std::out_of_range for a start or goal that is no vertex of the graph.
  IncrementalSearch(const Graph& graph, Costs costs, Heuristic heuristic, vertex_type start, vertex_type goal)
      : graph_(&graph), costs_(std::move(costs)), heuristic_(std::move(heuristic)) {
    const auto n = static_cast<std::size_t>(num_vertices(graph));
    if (static_cast<std::size_t>(start) >= n || static_cast<std::size_t>(goal) >= n)
      throw std::out_of_range("incremental search: the start or the goal is not a vertex of the graph");
    records_.resize(n);
    root_ = from_start ? start : goal;
    aim_ = last_aim_ = from_start ? goal : start;
    records_[root_].rhs = cost_type{};
    update_vertex_queue(root_);
  }

  // Brings the aimed-at vertex up to date; true when it is reachable. Given `until`, it stops there
  // (the clock read every 256 passes, a few microseconds' work) with stopped() true: each pass
  // leaves the queue consistent, so a later call goes on from where this one stopped.
  bool compute_shortest_path(std::optional<std::chrono::steady_clock::time_point> until = std::nullopt) {
    settle_key_modifier();
    ++counts_.searches;
    stopped_ = false;
    for (std::size_t pass = 1;
         !open_.empty() && (open_.top().key < key_of(aim_) || records_[aim_].g != records_[aim_].rhs); ++pass) {
      if (until && pass % 256 == 0 && std::chrono::steady_clock::now() >= *until) {
        stopped_ = true;
        break;
      }
      const vertex_type u = open_.top().vertex;
      const Key old_key = open_.top().key, new_key = key_of(u);
      Record& r = records_[u];
      Step* step = begin_step(u, old_key);
      if (old_key < new_key) {
        open_.update(r.handle, Entry{new_key, u});
        ++counts_.heap_updates;
        if (step) step->kind = Step::Kind::stale_key;
      } else if (r.g > r.rhs) {
        lower(u, step);
      } else {
        raise(u, step);
      }
      if (step) finish_step(*step);
    }
    return records_[aim_].g != cost_type::infinity();
  }

  // The cost of the move from → to has changed; costs() already returns the new value, `old` is
  // what it was. Call compute_shortest_path() once after all the changes of a moment.
  void edge_changed(vertex_type from, vertex_type to, const cost_type& old) {
    settle_key_modifier();
    const auto [child, parent] = from_start ? std::pair{to, from} : std::pair{from, to};
    const cost_type now = link(child, parent);
    Record& c = records_[child];
    if (child != root_) {
      if (old > now) c.rhs = std::min(c.rhs, now + records_[parent].g);
      else if (c.rhs == old + records_[parent].g) c.rhs = best_rhs(child);
    }
    update_vertex_queue(child);
  }

  // Sets the cost of the move from → to (Costs::set) and tells the search.
  void update_edge(vertex_type from, vertex_type to, const cost_type& cost) {
    const cost_type old = costs_(from, to);
    costs_.set(from, to, cost);
    edge_changed(from, to, old);
  }

  // Recomputes v's rhs from its neighbours and its place in the open list: after changes the
  // search was not told of edge by edge.
  void update_vertex(vertex_type v) {
    settle_key_modifier();
    if (v != root_) records_[v].rhs = best_rhs(v);
    update_vertex_queue(v);
  }

  // D* Lite: the robot moved to s. k_m grows by h(s_last, s) before the next change or search.
  void move_start(vertex_type s) requires(Direction == IncrementalDirection::from_goal) {
    check_vertex(s);
    aim_ = s;
  }

  // LPA*: a new goal. The heuristic changes for every vertex, so every key in the open list is
  // recomputed (what D* Lite's k_m avoids when the moving end is the one the search aims at).
  void move_goal(vertex_type s) requires(Direction == IncrementalDirection::from_start) {
    check_vertex(s);
    aim_ = last_aim_ = s;
    std::vector<vertex_type> queued;
    for (const Entry& e : open_) queued.push_back(e.vertex);
    for (const vertex_type v : queued) {
      open_.update(records_[v].handle, Entry{key_of(v), v});
      ++counts_.heap_updates;
    }
  }

  // Forgets everything and starts again between the current start and goal: a search from
  // scratch, whose first compute_shortest_path expands what A* expands (every vertex at most once,
  // in order of g + h, ties towards smaller g). Takes time in proportion to what was touched, not
  // to the graph: repeated A* on the same graph, costs and heap.
  void restart() {
    for (const vertex_type v : touched_) records_[v] = Record{};
    touched_.clear();
    open_.clear();
    key_modifier_ = cost_type{};
    last_aim_ = aim_;
    records_[root_].rhs = cost_type{};
    update_vertex_queue(root_);
  }

  // The optimal cost from the start to the goal after compute_shortest_path (infinity if none).
  cost_type cost() const { return records_[aim_].g; }
  cost_type g(vertex_type v) const { return records_[v].g; }
  cost_type rhs(vertex_type v) const { return records_[v].rhs; }
  vertex_type start() const { return from_start ? root_ : aim_; }
  vertex_type goal() const { return from_start ? aim_ : root_; }

  // Start ... goal, each step to a neighbour minimising the link cost + g; empty without a path.
  std::vector<vertex_type> path() const {
    std::vector<vertex_type> path = path_to_root(aim_);
    if constexpr (from_start) std::reverse(path.begin(), path.end());
    return path;
  }

  // v, then each step to a neighbour minimising the link cost + g, to the vertex the search grows
  // from (D* Lite: the goal, a path v → goal; LPA*: the start, a path v → start on the reversed
  // edges). For any v whose g is settled: the aimed-at vertex and every vertex on its path. Empty
  // when g(v) is infinite. Ties between equally good neighbours go to the first `before(a, b)`
  // puts first (a strict order, e.g. nearer the goal), else to the first in the graph's order.
  template <class Before = NoTieBreak>
  std::vector<vertex_type> path_to_root(vertex_type v, const Before& before = {}) const {
    std::vector<vertex_type> path;
    if (records_[v].g == cost_type::infinity()) return path;
    path.push_back(v);
    while (path.back() != root_) {
      const vertex_type u = path.back();
      const auto [parent, through] = best_parent(u, before);
      // g strictly decreases along a consistent chain with positive costs; anything else is a bug.
      if (through != records_[u].g || !(records_[parent].g < records_[u].g) || path.size() > records_.size())
        throw std::logic_error("incremental search: the g values do not form a path (not computed after a change?)");
      path.push_back(parent);
    }
    return path;
  }

  // The open list sorted by key (ties by vertex): the seed's table.
  std::vector<OpenListEntry<vertex_type, cost_type>> open_list() const {
    std::vector<OpenListEntry<vertex_type, cost_type>> list;
    for (const Entry& e : open_) {
      const Record& r = records_[e.vertex];
      list.push_back({e.vertex, r.g, r.rhs, e.key, consistency(r.g, r.rhs)});
    }
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
      if (a.key != b.key) return a.key < b.key;
      return a.vertex < b.vertex;
    });
    return list;
  }
  Key key(vertex_type v) const { return key_of(v); }
  // The heuristic between v and the vertex the search is aimed at (without k_m).
  cost_type heuristic(vertex_type v) const { return h(v); }
  // The neighbour v's rhs reads its value through (its backpointer, as a course draws it): none
  // for the vertex the search grows from and while rhs(v) is infinite.
  std::optional<vertex_type> backpointer(vertex_type v) const {
    if (v == root_) return std::nullopt;
    const auto [parent, through] = best_parent(v);
    if (through == cost_type::infinity()) return std::nullopt;
    return parent;
  }
  cost_type key_modifier() const { return key_modifier_; }

  const IncrementalCounts& counts() const { return counts_; }
  // Whether the last compute_shortest_path stopped at its time, the aimed-at vertex not yet settled.
  bool stopped() const { return stopped_; }
  Costs& costs() { return costs_; }
  const Costs& costs() const { return costs_; }
  const Graph& graph() const { return *graph_; }
  // Called after every pass of compute_shortest_path; nullptr (the default) for none. Not owned.
  void set_observer(Observer* observer) { observer_ = observer; }

 private:
  static constexpr bool from_start = Direction == IncrementalDirection::from_start;

  struct Entry {
    Key key;
    vertex_type vertex;
  };
  // boost::heap is a max-heap: "a before b" when a's key is larger.
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      if (a.key != b.key) return a.key > b.key;
      return a.vertex > b.vertex;  // the same order whatever the heap's history
    }
  };
  using Heap =
      boost::heap::d_ary_heap<Entry, boost::heap::arity<4>, boost::heap::mutable_<true>, boost::heap::compare<Later>>;
  struct Record {
    cost_type g = cost_type::infinity(), rhs = cost_type::infinity();
    typename Heap::handle_type handle{};
    bool queued = false, generated = false;
  };

  void check_vertex(vertex_type s) const {
    if (static_cast<std::size_t>(s) >= records_.size())
      throw std::out_of_range("incremental search: not a vertex of the graph");
  }
  // The cost along the edge between a vertex and the neighbour its rhs reads (from the start:
  // the edge parent → child; from the goal: child → parent).
  cost_type link(vertex_type child, vertex_type parent) const {
    return from_start ? costs_(parent, child) : costs_(child, parent);
  }
  cost_type h(vertex_type v) const { return from_start ? heuristic_(v, aim_) : heuristic_(aim_, v); }
  Key key_of(vertex_type v) const {
    const Record& r = records_[v];
    const cost_type m = std::min(r.g, r.rhs);
    return {m + h(v) + key_modifier_, m};
  }
  template <class F>
  void for_each_neighbour(vertex_type v, F&& f) const {
    for (auto [e, end] = out_edges(v, *graph_); e != end; ++e) f(static_cast<vertex_type>(target(*e, *graph_)));
  }
  template <class Before = NoTieBreak>
  std::pair<vertex_type, cost_type> best_parent(vertex_type v, const Before& before = {}) const {
    std::pair<vertex_type, cost_type> best{v, cost_type::infinity()};
    for_each_neighbour(v, [&](vertex_type p) {
      const cost_type through = link(v, p) + records_[p].g;
      if (through < best.second ||
          (through == best.second && through != cost_type::infinity() && before(p, best.first)))
        best = {p, through};
    });
    return best;
  }
  cost_type best_rhs(vertex_type v) const { return best_parent(v).second; }

  void settle_key_modifier() {
    if constexpr (!from_start) {
      if (last_aim_ != aim_) {
        key_modifier_ = key_modifier_ + heuristic_(last_aim_, aim_);
        last_aim_ = aim_;
      }
    }
  }

  // UpdateVertex's queue part: inconsistent vertices are in the open list with their key.
  OpenListAction update_vertex_queue(vertex_type v) {
    Record& r = records_[v];
    if (r.g != r.rhs) {
      const Entry entry{key_of(v), v};
      if (r.queued) {
        open_.update(r.handle, entry);
        ++counts_.heap_updates;
        return OpenListAction::rekeyed;
      }
      r.handle = open_.push(entry);
      r.queued = true;
      ++counts_.heap_pushes;
      if (!r.generated) {
        r.generated = true;
        ++counts_.generated;
        touched_.push_back(v);  // every record that changes is queued once: restart() resets these
      }
      return OpenListAction::added;
    }
    if (r.queued) {
      open_.erase(r.handle);
      r.queued = false;
      ++counts_.heap_removals;
      return OpenListAction::removed;
    }
    return OpenListAction::unchanged;
  }

  void pop(vertex_type u) {
    open_.pop();
    records_[u].queued = false;
    ++counts_.heap_pops;
  }
  void lower(vertex_type u, Step* step) {
    Record& r = records_[u];
    r.g = r.rhs;
    pop(u);
    ++counts_.expanded;
    for_each_neighbour(u, [&](vertex_type s) {
      const cost_type before = records_[s].rhs;
      if (s != root_) records_[s].rhs = std::min(records_[s].rhs, link(s, u) + r.g);
      note(step, s, before, update_vertex_queue(s));
    });
  }
  void raise(vertex_type u, Step* step) {
    Record& r = records_[u];
    const cost_type g_old = r.g;
    r.g = cost_type::infinity();
    ++counts_.expanded;
    for_each_neighbour(u, [&](vertex_type s) {
      const cost_type before = records_[s].rhs;
      if (s != root_ && records_[s].rhs == link(s, u) + g_old) records_[s].rhs = best_rhs(s);
      note(step, s, before, update_vertex_queue(s));
    });
    const OpenListAction own = update_vertex_queue(u);
    if (step) step->updated.push_back({u, r.g, r.rhs, own});
    if (step) step->kind = Step::Kind::underconsistent;
  }

  Step* begin_step(vertex_type u, const Key& key) {
    if (!observer_) return nullptr;
    step_ = Step{};
    step_.popped = u;
    step_.key = key;
    step_.g_before = records_[u].g;
    step_.rhs = records_[u].rhs;
    return &step_;
  }
  // A neighbour goes in the step's table when its rhs changed or it entered or left the open list
  // (the seed's "Updated rhs"); a neighbour merely looked at does not.
  void note(Step* step, vertex_type v, const cost_type& rhs_before, OpenListAction action) {
    const Record& r = records_[v];
    if (step && (r.rhs != rhs_before || action == OpenListAction::added || action == OpenListAction::removed))
      step->updated.push_back({v, r.g, r.rhs, action});
  }
  void finish_step(Step& step) {
    step.g_after = records_[step.popped].g;
    observer_->step(*this, step);
  }

  const Graph* graph_;
  Costs costs_;
  Heuristic heuristic_;
  std::vector<Record> records_;
  Heap open_;
  vertex_type root_{}, aim_{}, last_aim_{};
  cost_type key_modifier_{};
  IncrementalCounts counts_;
  bool stopped_ = false;  // the last compute_shortest_path stopped at its time
  Observer* observer_ = nullptr;
  Step step_;
  std::vector<vertex_type> touched_;
};

template <class Graph, class Costs, class Heuristic>
using LpaStar = IncrementalSearch<Graph, Costs, Heuristic, IncrementalDirection::from_start>;
template <class Graph, class Costs, class Heuristic>
using DStarLite = IncrementalSearch<Graph, Costs, Heuristic, IncrementalDirection::from_goal>;

}  // namespace polyplan
