#pragma once
// The graph every roadmap builder produces and search/ searches: exact vertex positions (for the
// exact path that is printed and checked) with their double approximations (for lengths and
// heuristics, which are irrational by nature), and edges weighted by Euclidean length.
#include <polyplan/geometry/rational.hpp>

#include <boost/graph/adjacency_list.hpp>

#include <cmath>

namespace polyplan {

struct RoadmapVertex {
  ExactPoint exact;
  double x = 0, y = 0;  // exact rounded to double, kept so searches never touch GMP
};

struct RoadmapEdge {
  double length = 0;  // Euclidean, from the vertices' doubles
};

// vecS vertices: ids are 0..n-1, which lets searches keep their per-vertex state in a reused array
// (see search/search_workspace.hpp). Vertices are never removed from a roadmap.
using Roadmap = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, RoadmapVertex, RoadmapEdge>;
using RoadmapVertexId = boost::graph_traits<Roadmap>::vertex_descriptor;

// Adds a vertex at `p`, its doubles rounded from the exact coordinates.
inline RoadmapVertexId add_vertex(Roadmap& roadmap, const ExactPoint& p) {
  // Not boost::add_vertex(property, g): its named-graph look-up draws a false -Wmaybe-uninitialized
  // from GCC 12 under the sanitizers.
  const RoadmapVertexId v = boost::add_vertex(roadmap);
  roadmap[v] = RoadmapVertex{p, to_double(p.x), to_double(p.y)};
  return v;
}

// Adds the edge u–v weighted by the distance between their doubles. std::hypot: no overflow or
// underflow in the squares, and the formula of the Euclidean search heuristic, so heuristic and
// lengths agree to the last bit where they measure the same segment.
inline void add_edge(Roadmap& roadmap, RoadmapVertexId u, RoadmapVertexId v) {
  const double length = std::hypot(roadmap[u].x - roadmap[v].x, roadmap[u].y - roadmap[v].y);
  boost::add_edge(u, v, RoadmapEdge{length}, roadmap);
}

}  // namespace polyplan
