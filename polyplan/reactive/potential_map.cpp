#include <polyplan/reactive/potential_map.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace polyplan {

void BoxGrid::check() const {
  if (!(xmax > xmin) || !(ymax > ymin))
    throw std::invalid_argument("the box is empty: expected xmin < xmax and ymin < ymax");
  if (cells_per_axis == 0) throw std::invalid_argument("the box needs at least one cell per axis");
}

double BoxGrid::diagonal() const { return std::hypot(xmax - xmin, ymax - ymin); }

BoxGrid box_around(const CSpace& cspace, std::size_t cells_per_axis) {
  const World& world = cspace.world();
  if (world.bounds)
    return {to_double(world.bounds->xmin), to_double(world.bounds->ymin), to_double(world.bounds->xmax),
            to_double(world.bounds->ymax), cells_per_axis};
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  const auto take = [&](const ExactPoint& p) {
    const Vec2 v = approximate(p);
    x0 = std::min(x0, v.x), y0 = std::min(y0, v.y), x1 = std::max(x1, v.x), y1 = std::max(y1, v.y);
  };
  for (const PolygonWithHoles& c : cspace.cobstacles())
    for (const ExactPoint& p : c.outer) take(p);
  for (const ExactPoint& p : query_points(world)) take(p);
  if (!(x1 >= x0)) return {0, 0, 1, 1, cells_per_axis};
  // At least 1 wide each way, so that a world of one point still has a box.
  const double grow_x = std::max(0.0, (1 - (x1 - x0)) / 2), grow_y = std::max(0.0, (1 - (y1 - y0)) / 2);
  return {x0 - grow_x, y0 - grow_y, x1 + grow_x, y1 + grow_y, cells_per_axis};
}

CellGrid potential_map(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                       const PotentialParameters& parameters, const BoxGrid& grid) {
  grid.check();
  CellGrid map;
  map.columns = map.rows = grid.cells_per_axis;
  map.x0 = grid.xmin, map.y0 = grid.ymin;
  map.cell_width = (grid.xmax - grid.xmin) / static_cast<double>(grid.cells_per_axis);
  map.cell_height = (grid.ymax - grid.ymin) / static_cast<double>(grid.cells_per_axis);
  map.value_name = "log(1 + potential)";
  for (std::size_t row = 0; row < map.rows; ++row)
    for (std::size_t column = 0; column < map.columns; ++column) {
      const Vec2 centre{map.x0 + (static_cast<double>(column) + 0.5) * map.cell_width,
                        map.y0 + (static_cast<double>(row) + 0.5) * map.cell_height};
      const bool free = cspace.locate(exactly(centre)).kind == Location::Kind::free;
      map.states.push_back(free ? CellGrid::free : CellGrid::blocked);
      map.values.push_back(free ? static_cast<float>(std::log1p(field.potential(centre, goal, parameters).value))
                                : 0.0f);
    }
  return map;
}

}  // namespace polyplan
