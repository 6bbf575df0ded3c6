#pragma once
// The shortest path on an arm's C-space grid (cells k·δ on every joint, moves of one joint by one
// step δ, each costing δ), found by A* or Dijkstra with every cell and move decided lazily and
// exactly, in memory proportional to the cells the search touched.
//
// Why its own search rather than search/'s shortest_path over GridGraph: a 4-joint grid at 1° has
// 1.7·10^10 cells, and an optimal search of a forest touches 10^7–10^8 of them. GridGraph's hash
// maps of touched cells, BGL's heap records and a hash map of checked moves cost 200–330 bytes a
// cell; here a cell costs 6 + joints bytes in blocks of ~4096 neighbouring cells, the open list is
// a bucket queue of cell numbers (costs and the heuristic are whole steps), and a move costs
// nothing to store:
//  - each cell is measured once (JointSafeAngles): free or not, exactly, and how far each joint
//    may turn from it with every configuration on the way free (a lower bound, in 1/255 of the
//    longest move, rounded down: safe_angle_units);
//  - a move a → b along joint j is free when the two ends' free stretches overlap (see
//    JointSafeAngles); only when they do not is the motion certified (certify_motion), near
//    contact. Either way every intermediate configuration is proved free.
//
// A corridor restricts the search to some cells (coarse-to-fine planning): cells outside are
// never entered, and the search reports a lower bound on the cost of any path that leaves it, so
// that the caller knows whether the corridor's best path is the grid's best.
#include <polyplan/arm/arm_collision.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace polyplan {

struct ArmGridSearchProblem {
  std::int64_t cells_per_axis = 72;  // n: the angles k · 2π/n, k in [0, n)
  bool torus = true;                 // false: an axis ends at 0 and n − 1
  std::vector<std::int32_t> start;   // cell coordinates
  // The cells the path may end at (at least one): the search stops at the first it expands, the
  // nearest. A*'s heuristic is the grid distance to the nearest of them, ignoring obstacles (a minimum
  // of consistent heuristics, so consistent itself).
  std::vector<std::vector<std::int32_t>> goals;
  bool use_heuristic = true;                        // A*; false: Dijkstra
  std::size_t memory_bytes = std::size_t{1} << 30;  // the search stops when its tables would exceed it
  bool record_expanded = false;
  // Cells the search may enter (coarse-to-fine): empty for every cell.
  std::function<bool(std::span<const std::int32_t>)> in_corridor;
};

struct ArmGridSearchResult {
  bool found = false;
  bool over_budget = false;                     // stopped at memory_bytes
  std::vector<std::vector<std::int32_t>> path;  // start … goal, cell coordinates
  std::size_t goal_reached = 0;                 // which of the problem's goals the path ends at (the first equal)
  std::int64_t cost_steps = 0;                  // path.size() − 1 when found
  // A lower bound, in steps, on the cost of any path that enters a cell outside the corridor
  // (infinity, as max(), when the search never stepped out of it): the corridor's path is the
  // grid's shortest when cost_steps ≤ this.
  std::int64_t outside_bound_steps = std::numeric_limits<std::int64_t>::max();
  std::size_t expanded = 0, generated = 0, cells_evaluated = 0;
  std::size_t moves_by_clearance = 0;                     // moves proved free by their ends' safe angles alone
  std::size_t moves_certified = 0;                        // moves given to certify_motion
  std::size_t moves_uncertified = 0;                      // of those, refused near contact (treated as blocked)
  std::size_t peak_bytes = 0;                             // the tables' memory at its largest
  std::vector<std::vector<std::int32_t>> expanded_order;  // with record_expanded
};

// How the search stores a joint's safe angle at a cell (JointSafeAngles::measure): in units of
// `unit` — the longest move of one step over 255, rounded up — rounded down, at most 255. The
// units stored never exceed the angle measured (units · unit ≤ safe as real numbers), which the
// moves proved by their two ends' safe angles rely on: a + b > 255 units cover any move.
std::uint8_t safe_angle_units(double safe, double unit);

// A cell's state as the search left it, for pictures of a 2-joint C-space.
enum class ArmCellState : std::uint8_t { unknown, free, blocked };

class ArmGridSearch {
 public:
  // `checker` must outlive the search. Throws std::invalid_argument for no goal, and for start or
  // goal coordinates of the wrong count or outside [0, n).
  ArmGridSearch(const ArmCollisionChecker& checker, ArmGridSearchProblem problem);
  ~ArmGridSearch();
  ArmGridSearch(const ArmGridSearch&) = delete;
  ArmGridSearch& operator=(const ArmGridSearch&) = delete;

  ArmGridSearchResult run();
  // Cells measured so far keep their state across runs; run() may be called again after
  // set_corridor (a wider corridor reuses every cell measured).
  void set_corridor(std::function<bool(std::span<const std::int32_t>)> in_corridor);
  ArmCellState state(std::span<const std::int32_t> cell) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
