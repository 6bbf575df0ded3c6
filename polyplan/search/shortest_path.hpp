#pragma once
// Shortest paths on a Roadmap: A* with the Euclidean heuristic, Dijkstra, BFS, DFS, greedy
// best-first and weighted A*, each a Boost Graph algorithm (see search/graph_search.hpp, which also
// searches any other Boost graph, implicit ones included).
//
//   polyplan::SearchWorkspace<polyplan::RoadmapVertexId> workspace;   // reuse for many queries
//   auto result = polyplan::shortest_path(roadmap, start, goal, {Search::astar}, workspace);
//   if (result.found) use(result.path, result.cost, result.expanded);
//
// Cheap to include: no BGL algorithm headers; the Roadmap instantiation is compiled once in
// search/shortest_path.cpp.
#include <polyplan/search/roadmap.hpp>
#include <polyplan/search/search_result.hpp>
#include <polyplan/search/search_workspace.hpp>

namespace polyplan {

// Heuristic: Euclidean distance to the goal on the vertices' doubles (std::hypot, like the edge
// lengths); weights: the edge lengths. start == goal gives the one-vertex path of cost 0; a goal
// the start cannot reach gives found == false. Throws std::out_of_range for a vertex id that is
// not in the roadmap and std::invalid_argument for a weighted-A* weight that is not >= 1.
//
// The workspace keeps per-vertex state for the roadmap's vertex count (one allocation, then O(1)
// reset per query by a generation counter): queries cost what they touch, never O(V).
SearchResult<RoadmapVertexId> shortest_path(const Roadmap& roadmap, RoadmapVertexId start, RoadmapVertexId goal,
                                            const SearchOptions& options, SearchWorkspace<RoadmapVertexId>& workspace);

// One query, no workspace to keep: uses a fresh hash-storage workspace, so nothing of the size of the
// roadmap is allocated or initialised (cost proportional to the vertices touched).
SearchResult<RoadmapVertexId> shortest_path(const Roadmap& roadmap, RoadmapVertexId start, RoadmapVertexId goal,
                                            const SearchOptions& options = {});

// shortest_path(roadmap, start, goal, Search::bfs)
inline SearchResult<RoadmapVertexId> shortest_path(const Roadmap& roadmap, RoadmapVertexId start, RoadmapVertexId goal,
                                                   Search algorithm) {
  return shortest_path(roadmap, start, goal, SearchOptions{algorithm});
}

}  // namespace polyplan
