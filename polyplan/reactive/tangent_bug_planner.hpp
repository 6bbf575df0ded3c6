#pragma once
// TangentBug (Kamon, Rivlin & Rimon; Choset et al. ch. 2.3), registered as `tangent-bug`, on the
// exact C-space, with a range sensor of radius `sensor-range` (inf: unlimited; 0: touch only).
//
// Motion to the goal: the robot heads straight for the goal while its sensor sees the way free;
// where the obstacle blocking it is within range it heads for the discontinuity O of its sensed
// region (the near end of a window of its exact visibility polygon, see visibility_region.hpp)
// that minimises d(x, O) + d(O, goal), among those nearer the goal than itself (so the distance to
// the goal falls on every motion to the goal). Touching the obstacle it slides along the edge while
// that brings it nearer. Where no such move is left (a local minimum of the distance to the goal)
// it follows the boundary, towards the best discontinuity (with the obstacle on its right when
// none decides), keeping d_followed, the distance to the goal where it began, and leaves as soon
// as d_reach < d_followed, d_reach being the distance to the goal of the farthest point it sees
// free on its straight way to the goal within range: continuously for its own position along each
// edge (exact: the rational point just past where its distance falls below d_followed), and at
// each corner for the range. Going once round a boundary cycle without leaving proves the goal
// unreachable (no_path). `max-distance` bounds the walk: the course's planning problem set's endless wall ends `limit`.
//
// The robot senses at its stops (corners, hit and leave points), not continuously between them:
// between stops it moves along one straight line, so every motion is a segment between rational
// points, checked exactly like any other path. Points where the exact event is irrational (where
// the range or d_followed meets an edge) are rational points on the same line within 1e-15 of it.
//
// In a round world (RoundRobot: discs, walls, a disc robot, disc bounds) it walks the Bugs'
// boundary of segments and arcs in real algebraic numbers (detail/arc_boundary.hpp), its sensing
// there detail/tangent_senses.hpp's ArcSenses: every stop exact, the walk reported as pieces.
//
// Facts: bug.hits (where boundary following began), bug.leaves, bug.distance,
// tangent_bug.sensor_range, tangent_bug.d_followed (the last), tangent_bug.stops. The picture:
// the m-line, hits, leaves and the sensed region (the visibility polygon within range) at the
// first stops.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace polyplan {

struct TangentBugOptions {
  std::string sensor_range = "inf";  // a number >= 0, or inf
  Rational max_distance = 10000;     // the walk's length before status limit (exactly, on polygon worlds)
  std::size_t max_stops = 10000;     // stops (each a sensing) before status limit
};

// Space: TranslatingRobot (its problem a CSpace) or RoundRobot (a RoundWorld).
template <class Space>
class BasicTangentBugPlanner final : public Planner<Space> {
 public:
  // The problem must outlive the planner. Throws std::invalid_argument for a bad option.
  BasicTangentBugPlanner(const typename Space::Problem& problem, TangentBugOptions options = {});
  ~BasicTangentBugPlanner() override;
  PlanReport<ExactPoint> plan(const Query& query, const QueryOptions& options = {}) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using TangentBugPlanner = BasicTangentBugPlanner<TranslatingRobot>;

template <class Space>
PlannerEntry<Space> tangent_bug_planner_entry();

}  // namespace polyplan
