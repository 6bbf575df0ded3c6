#pragma once
// The per-vertex state of a graph search (distance, priority, predecessor, colour), kept between
// queries so that a query costs what it touches, never O(V) of initialisation. Light on purpose:
// users construct one next to their graph; the algorithms are in search/graph_search.hpp.
#include <boost/container_hash/hash.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace boost {
// Declared, not included: naming a vecS adjacency_list below must not cost its header.
struct vecS;
template <class OutEdgeListS, class VertexListS, class DirectedS, class VertexProperty, class EdgeProperty,
          class GraphProperty, class EdgeListS>
class adjacency_list;
}  // namespace boost

namespace polyplan {

// True for graphs whose vertex descriptors are the integers 0..num_vertices(g)-1, for which a
// workspace may keep its state in an array of num_vertices(g) records (VertexStorage::automatic).
// Specialise it for another graph type only if that holds; when num_vertices(g) may be too large to
// allocate (an implicit grid), also overload dense_vertex_table_fits for it, found by ADL.
template <class Graph>
struct has_dense_vertex_ids : std::false_type {};
template <class OutEdgeListS, class DirectedS, class VertexProperty, class EdgeProperty, class GraphProperty,
          class EdgeListS>
struct has_dense_vertex_ids<
    boost::adjacency_list<OutEdgeListS, boost::vecS, DirectedS, VertexProperty, EdgeProperty, GraphProperty, EdgeListS>>
    : std::true_type {};

// Whether this graph object is small enough for a table of num_vertices(g) records; otherwise
// the workspace hashes the vertices touched. Stored graphs always fit.
template <class Graph>
constexpr bool dense_vertex_table_fits(const Graph&) {
  return true;
}

// Where a workspace keeps the per-vertex state.
//
// Measured (bench/search_workspace_bench.cpp: 400 x 250 8-connected grid Roadmap, 10^5
// vertices; microseconds per query, reused workspace, versioned array / hash map):
//   A*        goal within 3 cells 4.2 / 3.6    within 30 cells  53 / 87     anywhere 2880 / 5390
//   Dijkstra                     16 / 20                      772 / 1223            24200 / 37400
//   BFS                         4.1 / 8.0                     148 / 363              4380 / 12600
// Plain boost::astar_search, which initialises its vector property maps for all V vertices per
// query: 73 / 115 / 2920 (A*), i.e. the versioned array matches raw arrays on big queries and
// drops the O(V) term (~70 us here) on small ones. A fresh versioned array per query pays that
// term too (86 us for a 4-vertex A* query), which is why one-shot queries use the hash map.
enum class VertexStorage {
  // A versioned array for graphs whose vertex ids are 0..n-1 (has_dense_vertex_ids, e.g. the
  // Roadmap): allocated once for n vertices, made stale in O(1) per query by a generation counter.
  // A hash map for every other graph (implicit graphs: memory proportional to vertices touched).
  automatic,
  // Always the hash map: nothing of size V is ever allocated, at the price of a hash look-up on
  // each property access: on the Roadmap as fast on tiny queries, 1.3x to 2.9x slower on larger
  // ones (measured above).
  hashed,
};

namespace detail {

inline constexpr double unreached = std::numeric_limits<double>::infinity();

// One vertex's search state. Absent from the table means: distance and rank infinite,
// predecessor itself, colour white (the BGL initialisation that *_no_init algorithms skip).
template <class Vertex>
struct VertexRecord {
  double distance;  // g
  double rank;      // the open-list key (f = g + h for A*)
  Vertex predecessor;
  std::uint32_t slot;  // order of first touch in this query: the dense index BGL's heap needs
  std::uint8_t color;  // boost::default_color_type, stored narrow
};

template <class Vertex>
VertexRecord<Vertex> fresh_record(const Vertex& v, std::size_t slot) {
  return {unreached, unreached, v, static_cast<std::uint32_t>(slot), 0 /* white */};
}

template <class Vertex, class Hash>
class HashedVertexTable {
 public:
  using Record = VertexRecord<Vertex>;
  void begin_query() { records_.clear(); }
  Record* find(const Vertex& v) {
    const auto it = records_.find(v);
    return it == records_.end() ? nullptr : &it->second;
  }
  Record& touch(const Vertex& v) {
    auto [it, inserted] = records_.try_emplace(v);
    if (inserted) it->second = fresh_record(v, records_.size() - 1);
    return it->second;
  }
  std::size_t touched() const { return records_.size(); }
  void release() { std::unordered_map<Vertex, Record, Hash>().swap(records_); }

 private:
  std::unordered_map<Vertex, Record, Hash> records_;  // node-based: references stay valid
};

// For vertex ids 0..n-1. A record is valid only if its stamp equals the current generation, so a
// new query invalidates everything by incrementing the generation.
template <class Vertex>
class DenseVertexTable {
 public:
  using Record = VertexRecord<Vertex>;
  void begin_query(std::size_t vertex_count) {
    if (entries_.size() < vertex_count) entries_.resize(vertex_count);  // new entries: stamp 0
    if (++generation_ == 0) {  // after 2^32 - 1 queries: make every stamp stale once
      for (Entry& e : entries_) e.stamp = 0;
      generation_ = 1;
    }
    touched_ = 0;
  }
  Record* find(Vertex v) {
    Entry& e = entries_[static_cast<std::size_t>(v)];
    return e.stamp == generation_ ? &e.record : nullptr;
  }
  Record& touch(Vertex v) {
    Entry& e = entries_[static_cast<std::size_t>(v)];
    if (e.stamp != generation_) {
      e.record = fresh_record(v, touched_++);
      e.stamp = generation_;
    }
    return e.record;
  }
  std::size_t touched() const { return touched_; }
  std::size_t capacity() const { return entries_.size(); }
  void release() {
    std::vector<Entry>().swap(entries_);
    touched_ = 0;
  }

 private:
  struct Entry {
    Record record;
    std::uint32_t stamp = 0;
  };
  std::vector<Entry> entries_;
  std::uint32_t generation_ = 0;
  std::size_t touched_ = 0;
};

// The FIFO open list of breadth-first search, reused across queries (a BGL Buffer).
template <class Vertex>
class FifoBuffer {
 public:
  using value_type = Vertex;
  using size_type = std::size_t;
  void push(const Vertex& v) { items_.push_back(v); }
  void pop() { ++head_; }
  Vertex& top() { return items_[head_]; }
  const Vertex& top() const { return items_[head_]; }
  bool empty() const { return head_ == items_.size(); }
  size_type size() const { return items_.size() - head_; }
  void clear() {
    items_.clear();
    head_ = 0;
  }
  void release() {
    std::vector<Vertex>().swap(items_);
    head_ = 0;
  }

 private:
  std::vector<Vertex> items_;
  std::size_t head_ = 0;
};

struct WorkspaceAccess;

}  // namespace detail

// Reuse one workspace for many queries on one graph (or on graphs of the same vertex type): a query
// then allocates nothing proportional to the graph. Vertex must be equality-comparable and hashable
// with Hash (boost::hash handles integers, std::pair, std::array, std::tuple and types with a
// hash_value overload). Not thread-safe: one workspace per thread.
template <class Vertex, class Hash = boost::hash<Vertex>>
class SearchWorkspace {
 public:
  explicit SearchWorkspace(VertexStorage storage = VertexStorage::automatic) : storage_(storage) {}

  VertexStorage storage() const { return storage_; }

  // Vertices the last query touched (gave a distance, a colour or a predecessor to): what that
  // query's time and, for the hash storage, its memory are proportional to.
  std::size_t touched() const { return used_dense_ ? dense_.touched() : hashed_.touched(); }

  // Frees all memory; the workspace stays usable.
  void release() {
    hashed_.release();
    dense_.release();
    fifo_.release();
  }

 private:
  friend struct detail::WorkspaceAccess;
  VertexStorage storage_;
  bool used_dense_ = false;  // which table the last query used
  detail::HashedVertexTable<Vertex, Hash> hashed_;
  detail::DenseVertexTable<Vertex> dense_;  // used only for graphs with dense vertex ids
  detail::FifoBuffer<Vertex> fifo_;
};

}  // namespace polyplan
