#pragma once
// The brushfire of an occupancy grid (the course's GVD exercise): a wavefront leaves every
// obstacle at once and labels each free cell with its distance to the nearest obstacle and that
// obstacle's id; the generalized Voronoi diagram (GVD) is where the fronts of two obstacles meet.
// A pure grid algorithm: cells, flags and counts, no geometry.
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
//   (the outside first), whatever the order of the queue.
// - GVD: a free cell c is on it when one of its 8 neighbours n has another id and n is blocked
//   (the outside counts as blocked) or has the higher id. Of two neighbouring free cells of
//   different ids only the lower id's is on the GVD, so the line is one cell wide where the front
//   is axis-parallel and up to two where it is diagonal; a free cell touching an obstacle other
//   than its own is on it too, so the GVD runs through a passage one cell wide between two
//   obstacles.
// - Connected: the GVD is travelled by the moves of an 8-connected grid that never cuts a corner
//   (a diagonal move needs both cells beside it free, search/grid_graph.hpp). Along a front the
//   GVD cells of consecutive pairs touch (any two cells of a 2 × 2 block are neighbours); where
//   two GVD cells touch only at a corner whose other two cells are one blocked and one free, the
//   free one joins the GVD, so that the move exists. Taking one side of each front loses no
//   connection that the two-sided meeting set has (tested on random grids of rectangles).
// - Not connected everywhere the free space is: the GVD of obstacle ids has a gap where only
//   fronts of ONE obstacle meet — a door between two parts of a wall, the mouth of a pocket of
//   one obstacle, or the outside's fronts from two sides of the bounds meeting between obstacles
//   (two posts far apart in a low room, each with its own loop).
//
// Cost: O(cells), each cell looked at a bounded number of times.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace polyplan {

struct Brushfire {
  std::size_t columns = 0, rows = 0;
  // Per cell, index column + row · columns:
  std::vector<std::uint32_t> distance;  // 0 for a blocked cell; >= 1 for a free one (chessboard steps)
  std::vector<std::uint32_t> obstacle;  // the nearest obstacle's id; a blocked cell's own component
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
