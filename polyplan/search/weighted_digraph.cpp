#include <polyplan/search/weighted_digraph.hpp>

#include <polyplan/search/bidirectional_search.hpp>
#include <polyplan/search/graph_search.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {

// The seed's formula (numpy's norm), not std::hypot: on integer grids the sum of squares is exact and
// its square root correctly rounded, so an A* written from the seed finds the same f, and the same
// ties. Coordinates are at most 1e100 in magnitude (the readers' limit): the squares do not overflow.
double euclidean_distance(const WeightedDigraph& graph, DigraphVertexId a, DigraphVertexId b) {
  const double dx = graph[a].x - graph[b].x, dy = graph[a].y - graph[b].y;
  return std::sqrt(dx * dx + dy * dy);
}

SearchResult<DigraphVertexId> shortest_path(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                                            const SearchOptions& options) {
  if (start >= num_vertices(graph) || goal >= num_vertices(graph))
    throw std::out_of_range("shortest_path: start or goal is not a vertex of the graph");
  const auto to_goal = [&graph, goal](DigraphVertexId v) { return euclidean_distance(graph, v, goal); };
  const auto cost = [&graph](const boost::graph_traits<WeightedDigraph>::edge_descriptor& e) { return graph[e].cost; };
  // A dense table: one query on a small graph, and its records are what the trace reads.
  SearchWorkspace<DigraphVertexId> workspace;
  return shortest_path(graph, start, goal, options, to_goal, cost, workspace);
}

namespace {

WeightedDigraph reversed_digraph(const WeightedDigraph& graph) {
  WeightedDigraph out(num_vertices(graph));
  for (auto [e, end] = edges(graph); e != end; ++e)
    boost::add_edge(target(*e, graph), source(*e, graph), graph[*e], out);
  return out;
}

}  // namespace

SearchResult<DigraphVertexId> bidirectional_shortest_path(const WeightedDigraph& graph, DigraphVertexId start,
                                                          DigraphVertexId goal) {
  const WeightedDigraph backward = reversed_digraph(graph);
  using Edge = boost::graph_traits<WeightedDigraph>::edge_descriptor;
  return bidirectional_dijkstra(
      graph, [&graph](const Edge& e) { return graph[e].cost; }, backward,
      [&backward](const Edge& e) { return backward[e].cost; }, start, goal);
}

}  // namespace polyplan
