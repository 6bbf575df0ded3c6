#pragma once
// Shortest paths of a point or disc robot among discs, walls of zero thickness and polygons
// (RoundRobot): the tangent visibility graph. The robot's centre keeps out of every obstacle grown
// by its radius; a shortest path then runs along common tangents of circles — the discs grown by
// the radius and the corners of polygons and walls with it — and along arcs of those circles between
// the tangents' touching points. The graph has a node per touching point (a corner of radius 0, a
// point robot's, has one node per side a path may pass it on), an edge per tangent that the exact
// rules of geometry/round_world_check.hpp accept, and an edge per arc between consecutive touching
// points on a circle that keeps clear of every other obstacle; a query adds its start and goal and
// searches with A* (or any search of search/).
//
// Every point is a real algebraic number (CORE): the path is decided exactly, and checked again as
// a whole before it is returned. Its length is certified: the report's length lies within
// [length_lower, length_upper], bounds of doubles rounded outward, and the pieces (PlanReport::
// pieces: segments and arcs with centre and radius) say how the path's points join. Registered as
// `visibility` for round worlds.
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/search_result.hpp>

#include <memory>

namespace polyplan {

class TangentVisibilityGraph final : public Planner<RoundRobot> {
 public:
  // `world` must outlive the graph. The tangents between the world's circles are found and checked
  // here, once; a query adds its own.
  explicit TangentVisibilityGraph(const RoundWorld& world, SearchOptions search = {});
  ~TangentVisibilityGraph() override;
  TangentVisibilityGraph(TangentVisibilityGraph&&) noexcept;
  TangentVisibilityGraph& operator=(TangentVisibilityGraph&&) noexcept;

  // Facts: roadmap.kind ("tangent-visibility"), roadmap.vertices, roadmap.edges, roadmap.seconds,
  // search.*, length_lower, length_upper, query_seconds. No path in the graph is status no_path:
  // the graph holds a shortest path whenever a path exists.
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

PlannerEntry<RoundRobot> tangent_visibility_planner_entry();

}  // namespace polyplan
