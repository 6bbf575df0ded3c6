#pragma once
// What a graph search is asked (the algorithm and its options) and what it reports (path, cost,
// the counts a course compares, time). Shared by the roadmap search (search/shortest_path.hpp) and
// the generic search on any Boost graph (search/graph_search.hpp). No Boost here.
#include <polyplan/search/search_trace.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace polyplan {

enum class Search {
  astar,     // A*: f = g + h; optimal with an admissible heuristic
  dijkstra,  // uniform cost: f = g; optimal
  bfs,       // breadth first: fewest edges, costs ignored while searching
  dfs,       // depth first: the first path found, neither shortest nor fewest edges
  greedy,    // greedy best first: f = h; fast, may be far from optimal
  wastar,    // weighted A*: f = g + weight * h; cost at most weight * optimal (consistent h)
};

namespace detail {
struct SearchName {
  Search algorithm;
  std::string_view name;   // the command line's and JSON's
  std::string_view title;  // a listing's
};
inline constexpr std::array<SearchName, 6> search_names{{
    {Search::astar, "astar", "A*"},
    {Search::dijkstra, "dijkstra", "Dijkstra"},
    {Search::bfs, "bfs", "BFS"},
    {Search::dfs, "dfs", "DFS"},
    {Search::greedy, "greedy", "greedy best-first"},
    {Search::wastar, "wastar", "weighted A*"},
}};
}  // namespace detail

// "astar", "dijkstra", "bfs", "dfs", "greedy", "wastar": the names the command line and JSON use.
constexpr std::string_view to_string(Search algorithm) {
  for (const auto& s : detail::search_names)
    if (s.algorithm == algorithm) return s.name;
  return "unknown";
}

// "A*", "Dijkstra", ..., "weighted A*": the algorithm's name in a listing.
constexpr std::string_view listing_name(Search algorithm) {
  for (const auto& s : detail::search_names)
    if (s.algorithm == algorithm) return s.title;
  return "unknown";
}

// The inverse of to_string; nullopt for any other text (case-sensitive).
constexpr std::optional<Search> search_from_string(std::string_view name) {
  for (const auto& s : detail::search_names)
    if (s.name == name) return s.algorithm;
  return std::nullopt;
}

struct SearchOptions {
  Search algorithm = Search::astar;
  // wastar only: f = g + weight * h. Must be finite and >= 1 (std::invalid_argument otherwise);
  // weight 1 is A* exactly. Ignored by the other algorithms.
  double weight = 1.0;
  // Keep the expanded vertices in expansion order (SearchResult::expanded_order), for pictures
  // and teaching; off by default, it costs a push per expansion.
  bool record_expanded = false;
  // Keep every expansion with its g, h, f, backpointer and open-list size, and every label a vertex
  // is given (SearchResult::trace, search/search_trace.hpp): for watching a search. Off by default.
  bool record_trace = false;
  // Which of several open vertices of equal f a best-first search (astar, wastar, dijkstra, greedy)
  // expands first. false: whichever Boost's 4-ary heap yields (the fastest). true: the one that
  // entered the open list first, as the course's graph-search homework's priority queue does (a list searched for its
  // first minimum, a vertex keeping its place when its f is lowered): an order any reimplementation can reproduce.
  bool ties_first_discovered = false;
  // wastar only: whether a closed vertex given a shorter distance goes back into the open list. false (the
  // textbook's weighted A*): a vertex once expanded keeps its g and is never expanded again, so expanded <=
  // generated; with a consistent heuristic the cost is at most weight * optimal. true: it is re-opened and
  // expanded again, which may lower the cost but may expand far more vertices (each re-expansion counted).
  bool reopen = false;
};

// How the counts are defined (identical for every graph and every property-map storage):
// - generated: vertices put in the open list for the first time (BGL discover_vertex), the start
//   included. A vertex re-opened by weighted A* is not generated again.
// - expanded: vertices taken out of the open list and examined (BGL examine_vertex), the goal
//   included: the search stops when the goal is taken out, before its edges are looked at. A
//   vertex re-opened and taken out again (weighted A* with SearchOptions::reopen) counts each time;
//   without re-opening each vertex is expanded at most once, so expanded <= generated.
// - DFS has no open list in BGL's (recursive) formulation: a vertex is expanded the moment it is
//   discovered, so for DFS expanded == generated == vertices discovered, the goal included.
// start == goal is found with expanded == generated == 1. Without a path, the counts cover the
// whole component of the start that the search exhausted.
template <class Vertex>
struct SearchResult {
  bool found = false;
  std::vector<Vertex> path;  // start ... goal; empty when not found
  double cost = 0;           // sum of the edge weights along `path` (0 when not found)
  std::size_t expanded = 0, generated = 0;
  std::vector<Vertex> expanded_order;  // with SearchOptions::record_expanded
  SearchTrace<Vertex> trace;           // with SearchOptions::record_trace
  std::size_t path_edges() const { return path.empty() ? 0 : path.size() - 1; }
  double seconds = 0;  // the whole query: search and path reconstruction (std::chrono::steady_clock)
  Search algorithm = Search::astar;
};

}  // namespace polyplan
