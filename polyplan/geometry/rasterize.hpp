#pragma once
// A polygon world as an occupancy grid (the course's graph-search homework's discretised sphere world), decided
// exactly: the world's bounds split into n × n equal cells, a cell blocked when its square meets the interior of a
// C-obstacle (the obstacles' regularized union for a point robot) or reaches where the robot's reference point cannot
// be because the bounds are walls.
//
// A closed square meets an open set iff the open square does, so a cell that only touches an
// obstacle along its boundary (a shared edge or corner) stays free. Touching obstacles count as
// one solid (docs/design.md), so two free cells may meet at a pinch point between obstacles; the grid
// graph's diagonal moves need both side cells free, so a grid path never passes there.
//
// Cost: each C-obstacle edge visits the cells along it (exact rationals, no floating point);
// every other cell whose centre lies in some C-obstacle's bounding box is decided by one exact
// point location. The course's graph-search homework's sphere world at 200 × 200 takes about 0.05 s.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/geometry/world.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace polyplan {

struct Raster {
  Bounds bounds;                      // the world's bounds, exact
  std::size_t cells_per_axis;         // n: the bounds box split into n × n equal cells (non-square if the box is)
  std::vector<std::uint8_t> blocked;  // n·n, 1 = blocked; index x + y·n, x from xmin, y from ymin (y up)
  // n·n, 1 = blocked because the robot would leave the bounds there (the square leaves the box
  // the reference point must stay in): the walls, as opposed to the C-obstacles. All 0 for a
  // point robot, whose box is the bounds.
  std::vector<std::uint8_t> walls;

  ExactPoint cell_center(std::size_t x, std::size_t y) const;  // exact rationals
  Rational cell_width() const;                                 // (xmax - xmin) / n, exact
  Rational cell_height() const;                                // (ymax - ymin) / n, exact
  bool is_blocked(std::size_t x, std::size_t y) const { return blocked[x + y * cells_per_axis] != 0; }
  std::size_t blocked_count() const;
};

// The cells i0 <= i <= i1, j0 <= j <= j1 of a raster.
struct CellWindow {
  long i0, j0, i1, j1;
};

// The cells whose closed squares meet the closed box (none when it lies beyond the grid): where
// an obstacle inside that box can block anything.
std::optional<CellWindow> cells_meeting(const Raster& raster, const Bounds& box);

// The largest cells_per_axis accepted (limits::raster_cells_per_axis).
inline constexpr std::size_t max_cells_per_axis = limits::raster_cells_per_axis;

// Throws InputError naming the world's file when the world has no bounds, or when cells_per_axis
// is 0 or above max_cells_per_axis. The CSpace overload reuses a C-space built already (its
// world's bounds and C-obstacles); the World overload builds one. (A world with discs or walls:
// geometry/round_rasterize.hpp.)
Raster rasterize(const CSpace& cspace, std::size_t cells_per_axis);
Raster rasterize(const World& world, std::size_t cells_per_axis);

// What every rasteriser starts from: n × n free cells over the box the grid covers — the world's
// box bounds, or the square round its disc bounds. Throws InputError naming the world's file when
// the world has neither, or when cells_per_axis is 0 or above max_cells_per_axis.
Raster empty_raster(const World& world, std::size_t cells_per_axis);

// Blocks, and marks as walls, every cell whose closed square is not inside the closed box where
// the robot's reference point may be (the bounds shrunk by the robot): the bounds are walls. A box
// the robot does not fit in (xmin >= xmax) holds no square, so every cell is blocked.
void block_outside_box(const Bounds& reference_box, Raster& raster);

// The raster of `after`'s world, which differs from the world `before` rasterised only by the
// `changed` obstacles (added or removed): `before` with the cells near each one's C-obstacle
// decided again. Equal to rasterize(after, n), at the cost of the cells a change touches (a world
// that changes at every move of a drive at 2048 cells per axis).
Raster rasterize_change(const CSpace& after, const Raster& before, const std::vector<const PolygonWithHoles*>& changed);

// The free cell (x, y) whose centre is nearest to p (exact Euclidean distance; among equally near
// cells the one of lowest index x + y·n); nullopt when every cell is blocked. Where the grid
// planners snap a start or a goal that need not be a cell centre.
std::optional<std::pair<std::size_t, std::size_t>> nearest_free_cell(const Raster& raster, const ExactPoint& p);

}  // namespace polyplan
