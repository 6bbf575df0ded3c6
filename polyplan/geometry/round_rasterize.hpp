#pragma once
// A world with discs, walls of zero thickness or disc bounds, and a point or disc robot
// (geometry/round_world_check.hpp), as an occupancy grid of the robot's centre, decided exactly
// and conservatively: the grid covers the box bounds, or the square round the disc bounds, split
// into n × n equal cells, and a cell is blocked when its closed square holds a configuration that
// is not free — it comes nearer a disc's centre than the disc's radius plus the robot's, nearer a
// wall's piece or a polygon than the robot's radius (a point robot: a wall that meets the closed
// square at all, since crossing it is never allowed; a polygon whose interior it meets), or
// leaves the bounds shrunk by the robot's radius (those cells are the raster's walls too). All of
// it in rationals: squared distances from the square to centres, pieces and edges, compared with
// squared radii; the square's farthest corner against the disc bounds.
//
// A square that only touches a grown disc or polygon along its boundary stays free (the closed
// square meets no open blocked set), as a cell touching a C-obstacle does in a polygon raster. Cost:
// each obstacle tests the cells its grown bounding box meets; polygons then send the centres of the
// cells within their boxes to the exact RoundWorld::config_not_free.
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_world_check.hpp>

#include <cstddef>

namespace polyplan {

// Throws InputError naming the world's file when the world has neither box nor disc bounds, or
// when cells_per_axis is 0 or above max_cells_per_axis. `world` must outlive the call only.
Raster rasterize(const RoundWorld& world, std::size_t cells_per_axis);

}  // namespace polyplan
