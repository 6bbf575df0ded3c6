#pragma once
// The brushfire of an occupancy grid (the course's GVD exercise): a wavefront leaves every
// obstacle at once and labels each free cell with its distance to the nearest obstacle, that
// obstacle's id and the obstacle cell its front came from (its origin: a discrete nearest-point
// transform, as in the brushfire with wavefront origins of Lau, Sprunk & Burgard's dynamic
// Voronoi maps); the generalized Voronoi diagram (GVD) is where two fronts meet: fronts of two
// obstacles, or fronts of one obstacle that came round it from two places, thinned to what joins
// and what climbs need. A pure grid algorithm: cells, flags and counts, no geometry.
//
// - Obstacles: the 8-connected components of blocked cells, ids 1, 2, ... in the order of their
//   lowest cell index; the outside of the grid (a world's bounds, which are walls) is ONE more
//   obstacle, id 0, next to every border cell. Blocked cells may be marked as part of the
//   outside (where a robot with extent would leave the bounds): they take id 0 and join no
//   component, so an obstacle touching the walls keeps its own id.
// - Wavefront: 8-connected, one layer per step, so a free cell's distance is the chessboard
//   distance max(|dx|, |dy|) to the nearest blocked cell or to the outside: a border cell is 1
//   from the outside, a blocked cell is 0. Every cell nearer than d to a cell at distance d is
//   free, so the free square of half-side d - 1/2 cells around its centre bounds its clearance
//   from below.
// - Ties: a cell that fronts of several obstacles reach in the same layer takes the lowest id
//   (the outside first), whatever the order of the queue. Its origin is, among the origins of
//   that id's fronts reaching it, the one of least Euclidean distance (then lowest row, column):
//   a blocked cell is its own origin; the outside's are the cells just beyond the border, so the
//   outside's origins, like an obstacle's, run along its boundary one cell apart.
// - Meetings: a free cell c meets another front when one of its 8 neighbours n holds one:
//   another id, or the same id from an origin that is not 8-adjacent to c's (the outside beyond
//   the border counts as blocked cells of id 0, each blocked cell being its own origin). Of two
//   free cells of one meeting only one takes it: of two ids the lower id's; of one id the cell
//   nearer the bisector of the two origins (the smaller excess of its squared distance to the
//   other's origin over that to its own), then the one whose origin comes first along the axis
//   the origins lie farther apart on. So a line is one cell wide where the front is
//   axis-parallel and up to two where it is diagonal; a free cell touching a blocked cell of
//   another front takes the meeting too, so the GVD runs through a passage one cell wide.
// - Why "not 8-adjacent": neighbouring cells in front of one stretch of boundary (an
//   axis-parallel wall, a convex corner) take origins at most one cell apart, as the nearest
//   boundary cell moves along it; origins two or more apart mean the fronts left two places of
//   the boundary with free space or a concave corner between them — the two jambs of a door (a
//   door one cell wide puts them exactly 2 apart, so any larger threshold would miss it), the
//   two sides of a pocket, the far sides of the bounds between two posts.
// - GVD: every meeting of two obstacles, and of the meetings of one obstacle what the GVD needs.
//   One obstacle's fronts also meet wherever its boundary is concave — every corner of a room,
//   every step of a jagged (rasterised slanted or curved) boundary grows a spur, the medial axis
//   of the cells — so those cells are thinned: one by one, in a fixed order, a cell of one
//   obstacle's meeting leaves the GVD when its GVD neighbours stay joined round it within its
//   3 × 3 block and every cell one move from it still climbs (below). What stays joins pieces
//   (through doors and pockets, between posts) and ends climbs (the local maxima of the
//   distance: the middle of an empty room keeps one cell).
// - Connected: the GVD is travelled by the moves of an 8-connected grid that never cuts a corner
//   (a diagonal move needs both cells beside it free, search/grid_graph.hpp). Along a front the
//   GVD cells of consecutive pairs touch (any two cells of a 2 × 2 block are neighbours); where
//   two GVD cells touch only at a corner whose other two cells are one blocked and one free, the
//   free one joins the GVD, so that the move exists. Within every component of free cells the
//   GVD is one piece, and every free cell off it has a GVD cell or a cell of larger distance one
//   move away, so a steepest ascent of the distance (the gvd-grid planner's climb) reaches it:
//   tested on random grids of rectangles and of noise (tests/search/brushfire_test.cpp), not
//   proven; the thinning keeps both by construction. Taking one side of each front loses no
//   connection that the two-sided meeting set of ids has.
//
// Cost: O(cells), each cell looked at a bounded number of times (a thinned cell puts its 8
// neighbours back on the work list once).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace polyplan {

// A cell a front left from: a blocked cell, or for the outside the cell just beyond the border
// (column -1 or columns, row -1 or rows).
struct BrushfireOrigin {
  std::int32_t column = 0, row = 0;
};

struct Brushfire {
  std::size_t columns = 0, rows = 0;
  // Per cell, index column + row · columns:
  std::vector<std::uint32_t> distance;  // 0 for a blocked cell; >= 1 for a free one (chessboard steps)
  std::vector<std::uint32_t> obstacle;  // the nearest obstacle's id; a blocked cell's own component
  std::vector<BrushfireOrigin> origin;  // where that obstacle's front came from; a blocked cell itself
  std::vector<std::uint8_t> gvd;        // 1 for a free cell on the GVD
  std::uint32_t obstacle_count = 0;     // ids 0 .. obstacle_count - 1, the outside (0) included
  std::uint32_t max_distance = 0;       // the largest distance of a free cell (0 when none is free)
  std::size_t gvd_cells = 0;

  std::size_t index(std::size_t column, std::size_t row) const { return column + row * columns; }
};

// `blocked`: columns · rows flags, index column + row · columns, non-zero = blocked. `outside`:
// the same size, non-zero for blocked cells that belong to the outside, or empty for none.
// Throws std::invalid_argument when a size is not columns · rows.
Brushfire brushfire(std::size_t columns, std::size_t rows, const std::vector<std::uint8_t>& blocked,
                    const std::vector<std::uint8_t>& outside = {});

}  // namespace polyplan
