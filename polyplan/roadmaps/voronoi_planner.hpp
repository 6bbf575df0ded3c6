#pragma once
// The maximum-clearance roadmap (free_space/voronoi_diagram.hpp): start and goal are retracted onto
// the diagram, moving straight away from their nearest boundary point (their clearance only grows
// on the way), and the search maximises the smallest clearance along the path first, its length
// second: the bottleneck r* (the widest path, by joining the diagram's pieces in order of falling
// clearance until start and goal meet) and then the shortest path over the pieces of clearance at
// least r*. r* is the best possible: the largest r for which start and goal lie in one component
// of {p : distance(p, C-obstacles and walls) >= r}, capped by their own clearances.
//
// Parabolic arcs are sampled for the path only as finely as the bottleneck needs: a chord strays
// from its arc by its sagitta, so a chord is kept when the arc's smallest clearance between its
// ends, less the sagitta, is at least r* - 1e-7 (and at least half of r* — a chord never comes near
// the boundary); elsewhere chords halve until it is. The path's clearance is then within 1e-7 of
// r*.
//
// The diagram is in doubles (free_space/voronoi_diagram.hpp): a passage narrower than the doubles
// resolve (decimal.json's gap of 1e-17) is closed in it. When the diagram does not join start and
// goal but the exact free space does, the best clearance is below that resolution, and the
// planner returns the exact shortest path (the visibility graph's) through the passage, with the
// fact voronoi.narrows. Its corners are the doubles the diagram computed, as exact rationals, and the path is checked
// exactly (geometry/path_check.hpp) before it is returned: a path that fails (which would take a
// rounding of the diagram's doubles across the boundary) is not returned but named in why_not.
// Registered as `voronoi`.
#include <polyplan/free_space/voronoi_diagram.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

struct VoronoiOptions {
  SearchOptions search{};  // the second stage: shortest among the pieces of clearance >= r*
};

class VoronoiPlanner final : public Planner<TranslatingRobot> {
 public:
  // Builds the diagram of `cspace` (which must outlive the planner) once; without bounds the
  // frame holds the world's queries, and a query beyond it builds the diagram anew.
  explicit VoronoiPlanner(const CSpace& cspace, VoronoiOptions options = {});
  ~VoronoiPlanner() override;

  // Facts: roadmap.kind "voronoi", roadmap.vertices, roadmap.edges (the diagram's), roadmap.seconds,
  // voronoi.sites, voronoi.parabolic_edges, and when found `clearance` (the path's smallest
  // distance to the C-obstacles and walls, measured on the returned path: geometry/clearance.hpp),
  // voronoi.bottleneck (r* on the diagram), bottleneck.x and bottleneck.y (where the path is
  // nearest the boundary), search.*, query_seconds.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

  const VoronoiDiagram& diagram() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The registry's `voronoi`: options search and weight.
PlannerEntry<TranslatingRobot> voronoi_planner_entry();

}  // namespace polyplan
