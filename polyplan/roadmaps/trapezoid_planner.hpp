#pragma once
// The trapezoidal-decomposition roadmap of a course (free_space/trapezoidal_decomposition.hpp):
// a node at each trapezoid's centroid and at the midpoint of each wall between two trapezoids,
// an edge from each centroid to the midpoints of its walls. Start and goal are located in their
// trapezoids and joined to the centroids; a start and goal in one trapezoid are joined directly
// (the segment stays in the convex cell). Every roadmap edge runs inside one open trapezoid or
// across an open wall, so the roadmap is complete: it finds a path exactly when one exists.
//
// The search's path zig-zags through centroids and wall midpoints. `path=funnel` (the default)
// returns instead the shortest path within the channel of trapezoids that path crosses (the
// funnel algorithm, free_space/channel_funnel.hpp): exact, bending only at wall ends, never leaving
// the channel. Either path is checked exactly (geometry/path_check.hpp) before it is returned.
// Registered as `trapezoid`.
#include <polyplan/free_space/trapezoidal_decomposition.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/roadmap.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

// What the planner returns of the channel the search found.
enum class ChannelPath {
  zigzag,  // start, centroids and wall midpoints, goal: the course's drawing
  funnel,  // the shortest path within the channel's trapezoids
};

struct TrapezoidOptions {
  ChannelPath path = ChannelPath::funnel;
  SearchOptions search{};
};

class TrapezoidPlanner final : public Planner<TranslatingRobot> {
 public:
  // Decomposes the free space of `cspace` (which must outlive the planner) once. Without bounds
  // the frame holds the world's queries; a later query outside it rebuilds the decomposition.
  explicit TrapezoidPlanner(const CSpace& cspace, TrapezoidOptions options = {});
  ~TrapezoidPlanner() override;

  // Facts: roadmap.kind "trapezoid", roadmap.vertices (centroids and wall midpoints),
  // roadmap.edges, roadmap.seconds, trapezoid.cells, trapezoid.walls, sweep.insertions,
  // sweep.deletions, sweep.events, sweep.most_crossed (trapezoidal_decomposition.hpp's
  // SweepCounts), search.*, and when found trapezoid.channel_cells, trapezoid.zigzag_length and
  // trapezoid.funnel_length (both paths' lengths, whichever is returned), query_seconds.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

  const TrapezoidalDecomposition& decomposition() const;
  // Vertices 0..cells-1 are the centroids, then one per wall in decomposition().walls() order,
  // then two reserved for queries.
  const Roadmap& roadmap() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The registry's `trapezoid`: options path (funnel|zigzag), search, weight.
PlannerEntry<TranslatingRobot> trapezoid_planner_entry();

}  // namespace polyplan
