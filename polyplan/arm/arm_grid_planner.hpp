#pragma once
// An n-link arm planned on a grid over its C-space (the course's graph-search homework Problem 3): joint angles in
// steps of `resolution_degrees`, each joint a circle (the torus, by default) or the interval [0, 2π). A grid cell is
// free when the arm at that configuration is; a move between neighbouring cells (one joint turns one step) is allowed
// when the motion is certified free (arm/arm_motion.hpp: conservative advancement, every intermediate configuration,
// not samples). Cells and moves are decided when the search first touches them (lazy), or every cell up front (eager:
// what the course's graph-search homework's grid2graph does). The search is search/'s shortest_path on
// search/grid_graph. Registered as the arm planner `grid`.
//
// The returned path begins exactly at the start and ends exactly at the goal; they are joined to a
// nearby free grid cell by a motion certified like every other. A goal in the workspace (the hand at
// a point) is its goal set (arm/arm_goal_set.hpp): every goal configuration is joined to its cell,
// and the path ends at the nearest one the grid reaches (fewest grid steps).
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/plan/planner.hpp>
#include <polyplan/plan/planner_entry.hpp>
#include <polyplan/search/search_result.hpp>

#include <vector>

namespace polyplan {

struct ArmGridOptions {
  double resolution_degrees = 5;  // the grid step; must divide 360
  bool torus = true;              // false: each joint is the interval [0, 2π) and may not cross 0
  bool lazy = true;               // false: evaluate every cell before searching (at most 2^24 cells)
  SearchOptions search{Search::astar};
  // Coarse to fine: a grid finer than coarse_degrees (which must divide 360) is first searched at
  // that resolution. When the fine search over the whole grid would evaluate more than
  // exact_cells cells (predicted: the coarse search's cells times the fine cells per coarse cell),
  // only a corridor of `corridor` coarse cells around the coarse path is searched, doubled up to
  // `widenings` times while it cannot prove its path the grid's shortest. coarse_degrees 0: always
  // the whole grid. A coarse grid without a path may have missed a passage narrower than its
  // cells: guides at half its step, a quarter, … (while they divide 360 and stay coarser than the
  // grid) are tried, each searched whole, before the whole fine grid; grid.coarse_degrees says
  // which guided the answer. When the corridor holds no path, the whole grid is searched after all (within
  // memory_mb; at the budget the answer is status limit, never a claim that no path exists). A*
  // and Dijkstra with lazy evaluation only (the other searches always search the whole grid).
  double coarse_degrees = 5;
  std::size_t exact_cells = 4'000'000;
  int corridor = 2;
  int widenings = 0;
  // The memory one query's tables may take; a query that reaches it stops, saying so, instead of
  // being killed by the system (a widening that reaches it returns the narrower corridor's path).
  double memory_mb = 1500;
};

class ArmGridPlanner final : public Planner<PlanarArm> {
 public:
  // `problem` must outlive the planner. Throws std::invalid_argument for options that make no
  // sense (a resolution that does not divide 360 into at least 3 cells, eager evaluation of more
  // than 2^24 cells).
  explicit ArmGridPlanner(const ArmProblem& problem, ArmGridOptions options = {});

  // Each query searches a grid of its own (cells and moves decided afresh). Facts: cells_evaluated
  // (collision checks of grid cells), moves_checked (motions given to certify_motion: grid moves
  // near contact and the start/goal joins), moves_by_clearance (grid moves proved free by their
  // ends' safe angles alone), moves_uncertified (motions refused because no bound could prove
  // them free near contact), expanded, seconds, memory_mb (the search tables at their largest),
  // grid.resolution_degrees, grid.cells_per_axis, grid.torus, grid.evaluation ("lazy"/"eager"),
  // grid.shortest ("proved": no grid path between the joined cells is shorter; "corridor": the
  // shortest within the corridor, grid.lower_bound then bounds the grid's shortest from below),
  // search.algorithm, search.expanded, search.generated; coarse to fine also grid.coarse_degrees,
  // grid.corridor (the final half-width in coarse cells), grid.rounds, grid.whole_grid (true when
  // the corridor held no path and the whole grid was searched).
  // With several goal configurations (a workspace goal's) also goal.candidates, and on success
  // goal.reached and the other facts of set_goal_facts (arm/arm_goal_set.hpp), as the sampling
  // planners give them.
  // A start or goal in collision is an answer (found = false, why_not names the contact); so is
  // a query of the wrong size, and a goal point with no goal configuration (status no_path when it
  // is out of reach, not_found otherwise). With options.record and two joints, report.cells is the C-space
  // grid (angle k·step is the centre of cell k).
  PlanReport<JointAngles> plan(const ArmQuery& query, const QueryOptions& options = {}) override;

 private:
  const ArmProblem* problem_;
  ArmGridOptions options_;
  std::int64_t cells_per_axis_;
  ArmCollisionChecker checker_;
};

// The registry's arm planner `grid`: options resolution (degrees, 5), torus (true),
// evaluation (lazy|eager), search, weight, coarse, corridor, widenings, memory_mb.
PlannerEntry<PlanarArm> arm_grid_planner_entry();

// The sum of the joints' rotations along a path: on the torus each joint the short way between
// consecutive configurations, on the interval the way it actually turns (never across 0).
double arm_path_length(const std::vector<JointAngles>& path, bool torus);

}  // namespace polyplan
