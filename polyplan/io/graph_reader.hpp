#pragma once
// Reading graphs in the course's graph-search homework's graph_vector format: a JSON list of vertices,
//
//   [ {"x": [0, 0], "neighbors": [1, 2], "neighbors_cost": [1, 1.5]},
//     {"x": [1, 0], "neighbors": [0],    "neighbors_cost": [1]}, ... ]
//
// or an object {"vertices": [...]} holding the same list. Indices are 0-based; a vertex's
// neighbours are where its edges lead (the graph is directed: an undirected edge is listed at both
// ends) and neighbors_cost[k] is the cost of the move to neighbors[k], finite and >= 0. The seed's
// "g" and "backpointer" (a search's output) are accepted and ignored. As the seed's Python writes
// them, "x" may be a column [[x], [y]] and a one-element list may stand for its number. Numbers are
// read from their text and rounded once to the nearest double.
//
// Every problem throws InputError with one line "<file>: <object>: <what is wrong>", e.g.
// "graph.json: vertices[3].neighbors[1]: index 9 outside [0, 5)".
#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

struct GraphVertex {
  double x = 0, y = 0;
  std::vector<std::size_t> neighbors;
  std::vector<double> neighbors_cost;  // as many as neighbors
};

struct GraphFile {
  std::string source;                 // the file, for messages and titles
  std::vector<GraphVertex> vertices;  // at least one
};

// Reads and validates a graph file. Unknown fields are warnings: appended to `warnings` when it is
// given, otherwise printed to stderr as "warning: <file>: <object>: unknown field ... ignored".
GraphFile read_graph(const std::string& path, std::vector<std::string>* warnings = nullptr);

// The same from text already in memory; `name` stands for the file in messages.
GraphFile parse_graph(const std::string& text, const std::string& name, std::vector<std::string>* warnings = nullptr);

}  // namespace polyplan
