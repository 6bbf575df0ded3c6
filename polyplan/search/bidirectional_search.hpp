#pragma once
// Bidirectional Dijkstra on a Boost graph with dense vertex ids (a vecS adjacency_list), undirected,
// or directed with its reverse given: one uniform-cost search from the start and one from the
// goal, each taking the cheaper of the two frontiers in turn; every edge scanned offers a meeting
// (cost to its one end from the start + the edge + cost to its other end from the goal), and the
// search stops once the two smallest frontier costs add up to at least the best meeting: no path
// through an unsettled vertex can be cheaper then (Pohl 1971; the course's bidirectional search on
// PRM roadmaps, and on its graphs, search/weighted_digraph.hpp). BGL has no bidirectional search,
// so it is written here; the queue is std::priority_queue with lazy deletion.
//
// Counts as search_result.hpp defines them, over both searches: generated (vertices reached for
// the first time by either), expanded (vertices settled, the meeting ones included).
#include <polyplan/search/search_result.hpp>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace polyplan {

// The directed form: `forward` searched from the start along its out-edges, `backward` (the same
// vertex ids, every edge reversed, its weight kept) from the goal along its out-edges, which are
// forward's in-edges. forward_weight and backward_weight: double(const Edge&) >= 0 of each graph.
// Throws std::out_of_range for a start or goal outside the graphs.
template <class Forward, class ForwardWeight, class Backward, class BackwardWeight>
SearchResult<typename boost::graph_traits<Forward>::vertex_descriptor> bidirectional_dijkstra(
    const Forward& forward, ForwardWeight forward_weight, const Backward& backward, BackwardWeight backward_weight,
    typename boost::graph_traits<Forward>::vertex_descriptor start,
    typename boost::graph_traits<Forward>::vertex_descriptor goal) {
  using Vertex = typename boost::graph_traits<Forward>::vertex_descriptor;
  constexpr double unreached = std::numeric_limits<double>::infinity();
  const auto began = std::chrono::steady_clock::now();
  const std::size_t n = num_vertices(forward);
  if (start >= n || goal >= n || num_vertices(backward) != n)
    throw std::out_of_range("bidirectional_dijkstra: start or goal is not a vertex of the graph");

  SearchResult<Vertex> result;
  result.algorithm = Search::dijkstra;
  struct Side {
    std::vector<double> cost;
    std::vector<Vertex> predecessor;
    std::vector<bool> settled;
    std::priority_queue<std::pair<double, Vertex>, std::vector<std::pair<double, Vertex>>, std::greater<>> open;
  };
  Side sides[2];
  for (Side& side : sides) {
    side.cost.assign(n, unreached);
    side.predecessor.assign(n, Vertex{});
    side.settled.assign(n, false);
  }
  const Vertex roots[2] = {start, goal};
  for (int s = 0; s < 2; ++s) {
    sides[s].cost[roots[s]] = 0;
    sides[s].predecessor[roots[s]] = roots[s];
    sides[s].open.emplace(0.0, roots[s]);
  }
  result.generated = start == goal ? 1 : 2;

  double best = start == goal ? 0 : unreached;
  Vertex meet = start;
  const auto top = [&](Side& side) {
    while (!side.open.empty() && side.settled[side.open.top().second]) side.open.pop();
    return side.open.empty() ? unreached : side.open.top().first;
  };
  // One side, having settled u, scans its out-edges in its own graph.
  const auto scan = [&](Side& side, const Side& other, Vertex u, const auto& g, const auto& weight) {
    for (auto [e, end] = out_edges(u, g); e != end; ++e) {
      const Vertex v = target(*e, g);
      const double through = side.cost[u] + static_cast<double>(weight(*e));
      if (through < side.cost[v]) {
        if (side.cost[v] == unreached && other.cost[v] == unreached) ++result.generated;
        side.cost[v] = through;
        side.predecessor[v] = u;
        side.open.emplace(through, v);
      }
      if (other.cost[v] != unreached && side.cost[v] + other.cost[v] < best) {
        best = side.cost[v] + other.cost[v];
        meet = v;
      }
    }
  };
  while (true) {
    const double ahead = top(sides[0]), behind = top(sides[1]);
    if (ahead == unreached || behind == unreached || ahead + behind >= best) break;
    const int s = ahead <= behind ? 0 : 1;
    Side &side = sides[s], &other = sides[1 - s];
    const Vertex u = side.open.top().second;
    side.open.pop();
    side.settled[u] = true;
    ++result.expanded;
    if (s == 0) scan(side, other, u, forward, forward_weight);
    else scan(side, other, u, backward, backward_weight);
  }
  if (best != unreached) {
    result.found = true;
    result.cost = best;
    for (Vertex v = meet; v != start; v = sides[0].predecessor[v]) result.path.push_back(v);
    result.path.push_back(start);
    std::reverse(result.path.begin(), result.path.end());
    for (Vertex v = meet; v != goal;) {
      v = sides[1].predecessor[v];
      result.path.push_back(v);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return result;
}

// On an undirected graph both searches walk the same edges. weight: double(const Edge&) >= 0.
// Throws std::out_of_range for a start or goal outside the graph.
template <class Graph, class WeightFn>
SearchResult<typename boost::graph_traits<Graph>::vertex_descriptor> bidirectional_dijkstra(
    const Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor start,
    typename boost::graph_traits<Graph>::vertex_descriptor goal, WeightFn weight) {
  return bidirectional_dijkstra(g, weight, g, weight, start, goal);
}

}  // namespace polyplan
