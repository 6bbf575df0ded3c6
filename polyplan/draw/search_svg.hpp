#pragma once
// The picture of a graph search on a weighted digraph (polyplan search), drawn as the course's graph-search homework's
// Graph.plot draws one: the graph's edges and vertices, the vertices the search expanded, its open
// list (discovered, not yet expanded), arrows from each vertex to its backpointer, the labels
// g / h / f, the path found, start and goal. Graph.plot's flags are the options below.
//
// The result must have been searched with SearchOptions::record_trace: the open list, the
// backpointers and the labels are read from its trace (search/search_trace.hpp).
#include <polyplan/draw/svg.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <string>

namespace polyplan {

struct SearchPictureOptions {
  bool edge_weights = false;      // each edge's cost at its middle (Graph.plot's flag_edge_weights)
  bool labels = false;            // "g= h= f=" beside each vertex the search gave a g (flag_backpointers_cost)
  bool backpointers = false;      // an arrow from each such vertex to its backpointer (flag_backpointers)
  bool heuristic = false;         // "h=" below every vertex, the Euclidean distance to the goal (flag_heuristic)
  bool indices = false;           // each vertex's index (flag_labels)
  double seconds_per_step = 0.6;  // the animation's: one step per expansion
};

// "polyplan search FILE (ALGORITHM, START → GOAL)": the title the program gives.
std::string search_title(const std::string& file, const SearchResult<DigraphVertexId>& result, DigraphVertexId start,
                         DigraphVertexId goal);

// The search's final state: every vertex it expanded, the open list it left, the labels and
// backpointers as they ended, the path.
svg::Drawing draw_search(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                         const SearchResult<DigraphVertexId>& result, const SearchPictureOptions& options,
                         const std::string& title);

// The same search as an animation (SMIL, looping): step k (k = 1 .. expanded) shows the k-th
// vertex expanded, each vertex entering the open list when it is discovered and leaving it when it
// is expanded, and the labels and backpointer arrows changing as shorter ways are found; the path
// appears after the last step, and the whole picture holds for a step before the loop begins again.
// Each expanded vertex is one <circle class="expanded"> with its own <animate>. About 1 kB of
// SVG a vertex, so a graph of more than max_animated_vertices is refused (InputError): a still
// picture draws it.
inline constexpr std::size_t max_animated_vertices = 20000;
svg::Drawing draw_search_animation(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                                   const SearchResult<DigraphVertexId>& result, const SearchPictureOptions& options,
                                   const std::string& title);

}  // namespace polyplan
