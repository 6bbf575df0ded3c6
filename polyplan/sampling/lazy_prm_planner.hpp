#pragma once
// Lazy PRM (Bohlin & Kavraki 2000) over any sampling space: milestones are free samples joined to
// their k nearest without checking the motions; a query searches the roadmap for the shortest
// path (to each of its goals, when it has several, keeping the cheapest) and certifies only that
// path's unchecked edges, from the start on. An edge that is not
// free is removed and the search runs again; when no path is left, the roadmap grows by half its
// size (at least 10 samples: an easy query needs a dozen milestones). Certified edges are remembered from query to
// query. With roadmap-size N it builds, as prm does, the certified roadmap of N samples before any
// query and answers every query on it. Registered as `lazyprm` for polygon worlds and arms.
#include <polyplan/sampling/sampling_planner.hpp>

namespace polyplan {

struct LazyPrmOptions : SamplingLimits {
  std::size_t k = 10;            // neighbours each milestone is joined to; 0: ⌈e·(1 + 1/d)·log n⌉
  std::size_t roadmap_size = 0;  // > 0: the K-PRM of that many free samples built before any query
};

// The registry's `lazyprm` for a space: options k, roadmap-size and the sampling limits. Facts: roadmap.vertices,
// roadmap.edges, searches (shortest-path searches run), edges_removed (edges found not free).
template <class Space>
PlannerEntry<Space> lazy_prm_planner_entry(SamplingSpaceFactory<Space> make_space);

}  // namespace polyplan
