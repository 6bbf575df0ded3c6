#pragma once
// What a planner answers for one query: the exact path (checked before it is returned), its
// length, and the facts about the roadmap and the search that the program prints.
#include <polyplan/geometry/rational.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

struct RoadmapFacts {
  std::string kind;  // "visibility", "visibility-full"
  std::size_t vertices = 0, edges = 0;
  double seconds = 0;  // building it (once for all queries)
};

struct Plan {
  bool found = false;
  std::vector<ExactPoint> path;  // start ... goal, exact; empty when not found
  double length = 0;             // Euclidean, in double (irrational by nature)
  RoadmapFacts roadmap;
  Search algorithm = Search::astar;
  std::size_t expanded = 0, generated = 0;
  double search_seconds = 0;       // the graph search
  double query_seconds = 0;        // connecting start and goal, search, exact check: the whole query
  std::vector<ExactPoint> expanded_points;  // where the search expanded, with SearchOptions::record_expanded
};

}  // namespace polyplan
