#pragma once
// A directed graph given as the course's graph-search homework's graph_vector: vertices at points of the plane, each
// with its out-neighbours and the cost of the move to each (costs need not be lengths, nor symmetric), and the searches
// of search/graph_search.hpp on it with the Euclidean heuristic (the course's graph-search homework's Graph.heuristic).
// Read one from a file with io/graph_reader.hpp.
//
//   const WeightedDigraph graph = make_weighted_digraph(read_graph("graph.json").vertices);
//   auto result = shortest_path(graph, 0, 5, SearchOptions{Search::astar});
#include <polyplan/search/search_result.hpp>

#include <boost/graph/adjacency_list.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace polyplan {

// The course's names of searches beyond search_result.hpp's, which `polyplan search --method` and
// Python's search_graph take: "uniform-cost" is Dijkstra (and so is the graph-search homework's
// "bfs", which takes the vertex of least g out of its queue first).
inline constexpr std::pair<std::string_view, Search> course_search_names[] = {{"uniform-cost", Search::dijkstra}};

struct DigraphVertex {
  double x = 0, y = 0;
};

struct DigraphEdge {
  double cost = 0;  // finite, >= 0
};

// vecS: vertex ids are the indices of the graph_vector, 0..n-1. Parallel edges are kept (the
// search relaxes the cheapest).
using WeightedDigraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, DigraphVertex, DigraphEdge>;
using DigraphVertexId = boost::graph_traits<WeightedDigraph>::vertex_descriptor;

// From any list of vertices with members x and y (doubles), neighbors (indices) and
// neighbors_cost (doubles, as many): io/graph_reader.hpp's GraphVertex, say. The list is expected to
// be valid (the reader checks it); throws std::invalid_argument on an index out of range or lists of
// different lengths all the same, rather than build a broken graph.
template <class VertexList>
WeightedDigraph make_weighted_digraph(const VertexList& vertices) {
  WeightedDigraph graph(vertices.size());
  std::size_t i = 0;
  for (const auto& v : vertices) {
    graph[i] = DigraphVertex{v.x, v.y};
    if (v.neighbors.size() != v.neighbors_cost.size())
      throw std::invalid_argument("make_weighted_digraph: vertex " + std::to_string(i) +
                                  ": neighbors and costs differ in length");
    for (std::size_t k = 0; k < v.neighbors.size(); ++k) {
      if (static_cast<std::size_t>(v.neighbors[k]) >= vertices.size())
        throw std::invalid_argument("make_weighted_digraph: vertex " + std::to_string(i) + ": neighbour out of range");
      boost::add_edge(i, static_cast<std::size_t>(v.neighbors[k]),
                      DigraphEdge{static_cast<double>(v.neighbors_cost[k])}, graph);
    }
    ++i;
  }
  return graph;
}

// The course's graph-search homework's heuristic: the Euclidean distance between the vertices' points, sqrt(dx² + dy²).
double euclidean_distance(const WeightedDigraph& graph, DigraphVertexId a, DigraphVertexId b);

// options.algorithm from start to goal: weights the edges' costs, heuristic the Euclidean distance
// to the goal (admissible when no edge costs less than the distance it spans). Throws
// std::out_of_range for a start or goal that is no vertex, std::invalid_argument as shortest_path.
SearchResult<DigraphVertexId> shortest_path(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                                            const SearchOptions& options);

// Bidirectional Dijkstra (search/bidirectional_search.hpp) from start to goal, the backward search
// on the graph with its edges reversed: an optimal path, its cost and the counts of both searches
// (no trace, no expansion order; algorithm Search::dijkstra). Throws std::out_of_range for a start
// or goal that is no vertex.
SearchResult<DigraphVertexId> bidirectional_shortest_path(const WeightedDigraph& graph, DigraphVertexId start,
                                                          DigraphVertexId goal);

}  // namespace polyplan
