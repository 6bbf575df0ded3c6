#pragma once
// The exact pass over a roadmap's shortest path. A search in doubles (search/shortest_path.hpp)
// ranks paths by sums of rounded lengths, and two paths whose exact lengths — sums of square
// roots — are equal or within rounding of each other may come out in either order: the path it
// calls shortest may be longer, by 1e-16, than another. This pass proves the search's path
// shortest, or finds the one that is: a Dijkstra whose lengths are compared exactly
// (geometry/chain_lengths.hpp), over only the vertices that could lie on a path no longer than the
// search's (their distance from the start plus a lower bound on the straight distance to the goal).
// Where no other path comes within rounding of the search's, every comparison is decided by
// bounds in doubles.
#include <polyplan/search/roadmap.hpp>

#include <vector>

namespace polyplan {

// The shortest path from found.front() to found.back() in the roadmap, exactly: `found` itself
// when no path is exactly shorter (ties keep it), else the shortest (among equals, the first
// settled). `found` must be a path of the roadmap.
std::vector<RoadmapVertexId> exactly_shortest_path(const Roadmap& roadmap, const std::vector<RoadmapVertexId>& found);

}  // namespace polyplan
