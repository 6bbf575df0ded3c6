#pragma once
// A box of the plane cut into n × n cells, and the potential sampled on it for a picture: log(1 +
// U) at each free cell's centre (a cell is blocked when its centre is not free, by the exact
// C-space), as the heat map the drawing code draws (CellGrid::values).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/reactive/obstacle_field.hpp>

#include <cstddef>
#include <functional>

namespace polyplan {

struct BoxGrid {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  std::size_t cells_per_axis = 256;
  // Throws std::invalid_argument for an empty box or 0 cells.
  void check() const;
  double diagonal() const;
};

// The world's bounds, or without bounds the box around its C-obstacles and queries (at least 1 wide).
BoxGrid box_around(const CSpace& cspace, std::size_t cells_per_axis);
// The same for a world of discs, walls and polygons: its box bounds, the box round its disc
// bounds, or the box around its discs, walls, polygons and queries.
BoxGrid box_around(const RoundWorld& world, std::size_t cells_per_axis);

CellGrid potential_map(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                       const PotentialParameters& parameters, const BoxGrid& grid);
// The same where `free` says which cells' centres are free (exactly).
CellGrid potential_map(const std::function<bool(const ExactPoint&)>& free, const Repellers& field, Vec2 goal,
                       const PotentialParameters& parameters, const BoxGrid& grid);

}  // namespace polyplan
