#pragma once
// Exact Euclidean shortest paths for many queries in a world whose free-space corners are integer
// points (MovingAI maps: polyplan scen). The reduced visibility graph of visibility_graph.hpp —
// corners a taut path bends around, bitangent edges — is built in 64-bit integer arithmetic
// (free_space/detail/integer_triangulation.hpp: exact), and then, when it fits the memory budget, every
// corner-to-corner distance with the first step of each shortest path (one Dijkstra per corner);
// when the table does not fit, hub labels of the corner graph (search/hub_labels.hpp) if they fit,
// else nothing more; and the corners each integer point of the map sees. A query is then: locate start and goal,
// the segment if they see each other, else the corners each sees and the best pair through the
// table, the best hub through the labels, or an A* over the corners;
// the path is checked exactly by the integer segment walk before it is returned.
//
// Queries are const and take their scratch space from the caller: threads share one instance,
// each with its own Scratch, and get the answers one thread gets.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/integer_point.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace polyplan {

struct GridMap;

struct EuclideanShortestPathsOptions {
  // The corner-to-corner table is built when it needs at most this many bytes (12 per pair); the
  // same bound caps the table of each integer point's corners.
  std::size_t table_bytes = std::size_t{1} << 30;
  // Else hub labels of the corner graph, when they take at most this many bytes (16 per entry);
  // else queries search the corner graph.
  std::size_t label_bytes = std::size_t{1} << 30;
  // Threads that build the graph and the table (0: every core).
  unsigned threads = 0;
};

struct EuclideanPathAnswer {
  bool found = false;
  double length = 0;  // sum of the segments' correctly rounded lengths
  std::vector<IntegerPoint> path;
  std::string why_not;  // when not found
};

class EuclideanShortestPaths {
 public:
  // Throws std::invalid_argument when a free-space vertex is not an integer point below 2^30
  // in magnitude (then use VisibilityGraph).
  explicit EuclideanShortestPaths(const CSpace& cspace, EuclideanShortestPathsOptions options = {});
  // A MovingAI map's free space for a point robot (the C-space of world_from_grid(map)), read
  // straight from its cells: the same answers, without the exact polygon overlay.
  explicit EuclideanShortestPaths(const GridMap& map, EuclideanShortestPathsOptions options = {});
  ~EuclideanShortestPaths();
  EuclideanShortestPaths(EuclideanShortestPaths&&) noexcept;
  EuclideanShortestPaths& operator=(EuclideanShortestPaths&&) noexcept;

  // One per thread.
  class Scratch {
   public:
    Scratch();
    ~Scratch();
    Scratch(Scratch&&) noexcept;

   private:
    friend class EuclideanShortestPaths;
    struct Impl;
    std::unique_ptr<Impl> impl_;
  };

  // The shortest path from start to goal (integer points; a blocked one is not found, saying so).
  EuclideanPathAnswer query(const IntegerPoint& start, const IntegerPoint& goal, Scratch& scratch) const;

  std::size_t corner_count() const;
  std::size_t edge_count() const;
  bool has_table() const;
  bool has_labels() const;
  std::size_t label_entries() const;
  // Bytes of the triangulation, the graph and the table.
  std::size_t memory_bytes() const;
  double build_seconds() const;
  // Whether a step of the preprocessing ran on fewer threads than asked (the system could not
  // start them all: the work went on with those that started).
  bool short_of_threads() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  void build(EuclideanShortestPathsOptions options);
};

// A batch of (start, goal) queries answered on `threads` threads sharing `paths`, each thread with
// its own scratch. Answer i, with the µs its query took in its thread, lands in slot i: the answers
// do not depend on the number of threads. `progress(done)` is called on the calling thread after
// each query it answers while some are left, and once at the end with every query done;
// `short_of_threads`, when given, says whether fewer threads ran than asked (the system could not
// start them all).
struct TimedPathAnswer {
  EuclideanPathAnswer answer;
  double us = 0;
};
std::vector<TimedPathAnswer> answer_all(const EuclideanShortestPaths& paths,
                                        const std::vector<std::pair<IntegerPoint, IntegerPoint>>& queries,
                                        unsigned threads, const std::function<void(std::size_t done)>& progress = {},
                                        bool* short_of_threads = nullptr);

}  // namespace polyplan
