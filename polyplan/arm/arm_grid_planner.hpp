#pragma once
// An n-link arm planned on a grid over its C-space (seed 000 Problem 3): joint angles in steps of
// `resolution_degrees`, each joint a circle (the torus, by default) or the interval [0, 2π).
// A grid cell is free when the arm at that configuration is; a move between neighbouring cells
// (one joint turns one step) is allowed when the motion is free at `check_degrees`. Cells and
// moves are decided when the search first touches them (lazy), or every cell up front (eager:
// what seed 000's grid2graph does). The search is search/'s shortest_path on search/grid_graph.
//
// The returned path begins exactly at the start and ends exactly at the goal; they are joined to a
// nearby free grid cell by a motion checked like every other.
#include <polyplan/arm/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/search/search_result.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace polyplan {

struct ArmGridOptions {
  double resolution_degrees = 5;  // the grid step; must divide 360
  // Motions between configurations are checked every check_degrees of every joint; 0 means
  // min(1, resolution_degrees). Coarser than the grid is refused (a move would go unchecked).
  double check_degrees = 0;
  bool torus = true;  // false: each joint is the interval [0, 2π) and may not cross 0
  bool lazy = true;   // false: evaluate every cell before searching (at most 2^24 cells)
  SearchOptions search{Search::astar};
  bool keep_cspace = false;  // 2 joints only: return every cell's state, for the C-space picture
};

struct ArmGridPlan {
  bool found = false;
  std::string why_not;             // when not found: what stopped it, in words
  std::vector<JointAngles> path;   // start, grid configurations, goal; angles in [0, 2π)
  // Sum of the joints' rotations along the path: on the torus each joint the short way between
  // consecutive configurations, on the interval the way it actually turns (never across 0).
  double length = 0;
  std::size_t cells_per_axis = 0;
  double check_degrees = 0;        // what motions were checked at
  std::size_t cells_evaluated = 0; // collision checks of grid cells
  std::size_t moves_checked = 0;   // grid moves and start/goal joins checked as motions
  std::size_t expanded = 0, generated = 0;
  double seconds = 0;              // the whole plan: evaluation, search, joins
  // keep_cspace and 2 joints: cells_per_axis^2 states, index i + j * cells_per_axis (i: joint 1),
  // 0 not evaluated, 1 free, 2 blocked.
  std::vector<std::uint8_t> cspace;
};

// Throws std::invalid_argument for options that make no sense (a resolution that does not divide
// 360, a check coarser than the grid, eager evaluation of too many cells, a query of the wrong
// size). A start or goal in collision is an answer (found = false, why_not names the contact).
ArmGridPlan plan_arm_on_grid(const ArmProblem& problem, const ArmQuery& query, const ArmGridOptions& options);

// The length of a path as ArmGridPlan::length measures it.
double arm_path_length(const std::vector<JointAngles>& path, bool torus);

}  // namespace polyplan
