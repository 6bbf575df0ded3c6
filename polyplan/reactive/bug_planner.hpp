#pragma once
// Bug1 and Bug2 (Lumelsky & Stepanov; Choset et al. ch. 2), registered as `bug1` and `bug2`, on
// the exact C-space: the robot heads for the goal along the straight line; where that line would
// enter a C-obstacle (the hit point, exact: where the line meets the free space's boundary) it
// follows the boundary with the obstacle on its right, along the free space's boundary cycles
// (CSpace::free_components(): C-obstacles and walls alike), and leaves
//   bug1  after going round the whole obstacle, from the boundary point nearest the goal (exact:
//         the foot of the perpendicular or a corner), reached the shorter way round;
//   bug2  at the first point of the m-line (the segment start–goal) nearer the goal than the hit
//         point from which it can head for the goal.
// In a polygon world every point it reports is rational and every motion runs along the straight
// line or along a boundary edge, so the path is checked exactly like any other. In a round world
// (RoundRobot: discs, walls, a disc robot, disc bounds) the boundary has arcs and its points are
// real algebraic numbers (detail/arc_boundary.hpp): the walk follows the arcs, and the path is
// reported as pieces, segments and arcs, checked exactly in CORE's numbers, its length bounded
// outward. A wall is an obstacle of two sides: the walk goes up one, round its end and down the
// other; Bug2 leaves on the far side at the point where it hit (as near the goal as the hit point,
// and the goal now in sight), Bug1 from the nearest point on the side facing the goal.
//
// Both are complete: the goal is unreachable when Bug1's nearest point cannot head for it, or Bug2
// comes back to its hit point (status no_path, and start and goal lying in different components is
// the proof it finds). Facts: bug.hits, bug.leaves (points "(x, y)" in order), bug.distance,
// bug.bound — D + 1.5 Σ pᵢ for Bug1, D + ½ Σ nᵢ pᵢ for Bug2 (D the start–goal distance, pᵢ the
// perimeters of the boundary cycles met, nᵢ how often the m-line crosses each) — which the
// distance never exceeds.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>

namespace polyplan {

enum class BugKind { bug1, bug2 };

struct BugOptions {
  std::size_t max_hits = 1000;  // then status limit (stopped_by "hit limit")
};

// Space: TranslatingRobot (its problem a CSpace) or RoundRobot (a RoundWorld).
template <class Space>
class BasicBugPlanner final : public Planner<Space> {
 public:
  // The problem must outlive the planner.
  BasicBugPlanner(const typename Space::Problem& problem, BugKind kind, BugOptions options = {});
  ~BasicBugPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using BugPlanner = BasicBugPlanner<TranslatingRobot>;

template <class Space>
PlannerEntry<Space> bug_planner_entry(BugKind kind);

}  // namespace polyplan
