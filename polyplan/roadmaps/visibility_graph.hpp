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
// Queries connect start and goal to the corners they see (without rebuilding), search with any
// algorithm of search/, and check the path exactly before returning it.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/roadmaps/plan.hpp>
#include <polyplan/search/roadmap.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

enum class VisibilityKind { reduced, full };

class VisibilityGraph {
 public:
  // The graph keeps what it needs of `cspace` (its triangulated free space); queries do not use it.
  explicit VisibilityGraph(const CSpace& cspace, VisibilityKind kind = VisibilityKind::reduced);
  ~VisibilityGraph();
  VisibilityGraph(VisibilityGraph&&) noexcept;
  VisibilityGraph& operator=(VisibilityGraph&&) noexcept;

  // The corners and their edges (the two vertices after the corners are reserved for queries).
  const Roadmap& roadmap() const;
  RoadmapFacts facts() const;

  // Shortest path from start to goal with the chosen search. found == false when they are not
  // connected (or either is blocked). Not thread-safe: queries reuse the graph's query slots.
  Plan plan(const ExactPoint& start, const ExactPoint& goal, const SearchOptions& options = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
