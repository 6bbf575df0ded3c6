#pragma once
// What a graph search did, step by step, for watching it (the course's graph-search homework: "plots of the solution
// after every node expansion", g, h and f at each node, arrows for the backpointers). Recorded by every algorithm of
// search/graph_search.hpp when SearchOptions::record_trace is set. No Boost here.
//
// The numbers mean the same for every algorithm:
//   g            the cost of the path start → vertex along the backpointers, summed with the real
//                edge weights (also for greedy, bfs and dfs, which order their open list otherwise)
//   h            the heuristic the caller gave (unweighted), whatever the algorithm uses of it
//   f            the key the open list is ordered by: astar g + h, wastar g + weight·h,
//                dijkstra g, greedy h; bfs and dfs order by arrival (FIFO, LIFO) and report
//                A*'s g + h, for comparison
//   backpointer  the vertex g was reached from (none for the start)
//   open         the open list's size once the vertex has been taken out of it: vertices
//                discovered (or re-opened) and not yet expanded. DFS has no open list in Boost's
//                formulation: there it is the depth-first stack (vertices discovered, not finished)
#include <cstddef>
#include <optional>
#include <vector>

namespace polyplan {

// One vertex taken out of the open list and expanded. Steps count from 1.
template <class Vertex>
struct ExpansionRecord {
  std::size_t step = 0;
  Vertex vertex{};
  double g = 0, h = 0, f = 0;
  std::optional<Vertex> backpointer;
  std::size_t open = 0;
};

// A vertex given a g and a backpointer: when it is discovered (enters the open list), and each
// time a shorter way to it is found. What a picture of the open list draws between expansions.
template <class Vertex>
struct LabelRecord {
  // The expansion during which it happened (ExpansionRecord::step); 0 for the start, labelled
  // before anything is expanded.
  std::size_t step = 0;
  Vertex vertex{};
  double g = 0, h = 0, f = 0;  // as an expansion of the vertex now would report them
  std::optional<Vertex> backpointer;
  bool discovered = false;  // the first label: the vertex entered the open list
};

template <class Vertex>
struct SearchTrace {
  std::vector<ExpansionRecord<Vertex>> expansions;  // in expansion order
  std::vector<LabelRecord<Vertex>> labels;          // in the order they were set
};

}  // namespace polyplan
