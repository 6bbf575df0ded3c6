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

namespace {

// The box around `points`, at least 1 wide each way, so that a world of one point still has one.
BoxGrid box_around_points(const std::vector<Vec2>& points, std::size_t cells_per_axis) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Vec2& v : points)
    x0 = std::min(x0, v.x), y0 = std::min(y0, v.y), x1 = std::max(x1, v.x), y1 = std::max(y1, v.y);
  if (!(x1 >= x0)) return {0, 0, 1, 1, cells_per_axis};
  const double grow_x = std::max(0.0, (1 - (x1 - x0)) / 2), grow_y = std::max(0.0, (1 - (y1 - y0)) / 2);
  return {x0 - grow_x, y0 - grow_y, x1 + grow_x, y1 + grow_y, cells_per_axis};
}

BoxGrid box_of_bounds(const Bounds& b, std::size_t cells_per_axis) {
  return {to_double(b.xmin), to_double(b.ymin), to_double(b.xmax), to_double(b.ymax), cells_per_axis};
}

// The corners of the square round a disc: the box of its points.
std::vector<Vec2> square_round(const Disc& d) {
  const Vec2 c = approximate(d.center);
  const double r = to_double(d.radius);
  return {{c.x - r, c.y - r}, {c.x + r, c.y + r}};
}

}  // namespace

BoxGrid box_around(const CSpace& cspace, std::size_t cells_per_axis) {
  const World& world = cspace.world();
  if (world.bounds) return box_of_bounds(*world.bounds, cells_per_axis);
  std::vector<Vec2> points;
  for (const PolygonWithHoles& c : cspace.cobstacles())
    for (const ExactPoint& p : c.outer) points.push_back(approximate(p));
  for (const ExactPoint& p : query_points(world)) points.push_back(approximate(p));
  return box_around_points(points, cells_per_axis);
}

BoxGrid box_around(const RoundWorld& round, std::size_t cells_per_axis) {
  const World& world = round.world();
  if (world.bounds) return box_of_bounds(*world.bounds, cells_per_axis);
  if (world.disc_bounds) return box_around_points(square_round(*world.disc_bounds), cells_per_axis);
  std::vector<Vec2> points;  // the square round every point of every core, at its radius
  for (const RoundCore& core : round.cspace().obstacles)
    for (const ExactPoint& p : core.kind == RoundCore::Kind::polygon ? core.rings[0] : core.points)
      for (const Vec2& corner : square_round({p, core.radius})) points.push_back(corner);
  for (const ExactPoint& p : query_points(world)) points.push_back(approximate(p));
  return box_around_points(points, cells_per_axis);
}

CellGrid potential_map(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                       const PotentialParameters& parameters, const BoxGrid& grid) {
  return potential_map([&](const ExactPoint& p) { return cspace.locate(p).kind == Location::Kind::free; }, field, goal,
                       parameters, grid);
}

CellGrid potential_map(const std::function<bool(const ExactPoint&)>& is_free, const Repellers& field, Vec2 goal,
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
      const bool free = is_free(exactly(centre));
      map.states.push_back(free ? CellGrid::free : CellGrid::blocked);
      map.values.push_back(free ? static_cast<float>(std::log1p(field.potential(centre, goal, parameters).value))
                                : 0.0f);
    }
  return map;
}

}  // namespace polyplan
