#pragma once
// K-PRM (Kavraki et al. 1996) over any sampling space: free samples become milestones, each joined
// to its k nearest milestones by certified motions; the roadmap is kept from query to query (a
// multiple-query planner). A query joins its start and goal the same way and samples until they
// are in one component (union-find), then searches the roadmap (A* by default, or bidirectional
// Dijkstra, the course's extra). With several goals it joins each, samples until one shares the
// start's component, and keeps the cheapest path to those that do. k is fixed (the course's K
// values; 10 is OMPL's) or, with k = 0, PRM*'s k = ⌈e·(1 + 1/d)·log n⌉. With roadmap-size N the
// roadmap of N samples is built before any query and every query answered on it, not grown
// (sampling/detail/roadmap_planner.hpp). Registered as `prm` for polygon worlds and arms.
#include <polyplan/sampling/sampling_planner.hpp>
#include <polyplan/search/search_result.hpp>

namespace polyplan {

struct PrmOptions : SamplingLimits {
  std::size_t k = 10;  // neighbours each milestone is joined to; 0: ⌈e·(1 + 1/d)·log n⌉
  SearchOptions search{Search::astar};
  bool bidirectional = false;    // search with bidirectional Dijkstra instead (search/bidirectional_search.hpp)
  std::size_t roadmap_size = 0;  // > 0: the K-PRM of that many free samples built before any query
};

// The registry's `prm` for a space: options k, search, weight, bidirectional, roadmap-size and the sampling limits
// (iterations: samples per query). Facts: roadmap.vertices, roadmap.edges, search.algorithm,
// search.expanded (with several goals, every goal's search together).
template <class Space>
PlannerEntry<Space> prm_planner_entry(SamplingSpaceFactory<Space> make_space);

}  // namespace polyplan
