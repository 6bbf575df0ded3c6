#pragma once
// The visibility graph of a translating robot's free space, exact, built once and answering many
// queries. Nodes are the free space's corners: a boundary vertex together with one of its free
// wedges (so a pinch vertex where two wedges meet is two nodes) — in the reduced graph only the
// wedges wider than 180 degrees, the corners a taut path bends around; edges are the segments
// between corners that lie in the closure of the free space, passing no zero-width place, and
// (reduced) are tangent to the obstacles at both ends. The full graph keeps every free wedge of
// every vertex and every visible pair, as courses draw it — except a pair seen only along a line
// that grazes corners from alternating sides (no open cone of sight lines around it): the graph
// then has the same straight motion through the grazed corner, two edges of the same length.
//
// Queries connect start and goal to the corners they see (without rebuilding; in a world without
// bounds a query beyond the frame of the triangulation rebuilds it around the query), search with any
// algorithm of search/, and check the path exactly (a walk through the triangulated free space,
// independent of the visibility cones) before returning it. Registered as `visibility` (reduced)
// and `visibility-full`.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/roadmap.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

enum class VisibilityKind { reduced, full };

class VisibilityGraph final : public Planner<TranslatingRobot> {
 public:
  // `cspace` must outlive the graph (it names what a blocked start or goal hits). `search` is
  // what plan(query) searches with.
  explicit VisibilityGraph(const CSpace& cspace, VisibilityKind kind = VisibilityKind::reduced,
                           SearchOptions search = {});
  ~VisibilityGraph() override;
  VisibilityGraph(VisibilityGraph&&) noexcept;
  VisibilityGraph& operator=(VisibilityGraph&&) noexcept;

  // The corners and their edges (the two vertices after the corners are reserved for queries).
  const Roadmap& roadmap() const;
  std::size_t corner_count() const;

  // Shortest path from start to goal with the constructor's search. Facts: roadmap.kind
  // ("visibility" or "visibility-full"), roadmap.vertices (corners), roadmap.edges,
  // roadmap.seconds (building it, once), search.algorithm, search.expanded, search.generated,
  // search.path_edges, search.seconds, query_seconds. When start sees goal the path is the
  // segment and nothing is searched (expanded 0). Not thread-safe: queries reuse the query slots.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;
  // The same with another search on the same graph (a course compares them).
  PlanReport<ExactPoint> plan(const Query& query, SearchOptions search, const QueryOptions& options = {});

 private:
  void build(const CSpace& cspace, VisibilityKind kind, SearchOptions search, const std::vector<ExactPoint>& inside);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The registry's `visibility` and `visibility-full`: options search (astar) and weight (1).
PlannerEntry<TranslatingRobot> visibility_planner_entry(VisibilityKind kind);

}  // namespace polyplan
