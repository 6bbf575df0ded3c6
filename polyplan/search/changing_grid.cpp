#include <polyplan/search/changing_grid.hpp>

#include <stdexcept>

namespace polyplan {
namespace {

GridGraph all_free(int width, int height, Connectivity connectivity) {
  if (width < 1 || height < 1) throw std::invalid_argument("changing grid: the width and height must be at least 1");
  return GridGraph({{width, AxisKind::bounded, 1.0}, {height, AxisKind::bounded, 1.0}}, connectivity,
                   StepCost::euclidean, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height, 1));
}

}  // namespace

ChangingGrid::ChangingGrid(int width, int height, GridConventions conventions)
    : width_(width), height_(height), conventions_(conventions),
      graph_(all_free(width, height, conventions.connectivity)), blocked_(static_cast<std::size_t>(width) * height, 0) {
}

OctileLength ChangingGrid::cost(GridCell from, GridCell to) const {
  if (blocked(from) || blocked(to)) return OctileLength::infinity();
  const int fx = x(from), fy = y(from), dx = x(to) - fx, dy = y(to) - fy;
  if (dx == 0 || dy == 0) return conventions_.straight_step();
  if (conventions_.connectivity == Connectivity::axis_aligned) return OctileLength::infinity();
  // A diagonal move brushes the two cells beside it: both must be free, unless it may cut corners.
  if (!conventions_.corner_cutting && (blocked_at(fx + dx, fy) || blocked_at(fx, fy + dy)))
    return OctileLength::infinity();
  return conventions_.diagonal_step();
}

bool ChangingGrid::set_blocked(GridCell c, bool blocked, std::vector<ChangedMove>& changed) {
  if (this->blocked(c) == blocked) return false;
  const int cx = x(c), cy = y(c);
  // The moves into and out of c, and the diagonals that brush it (between two of its
  // 4-neighbours), with their costs before the change.
  const std::size_t first = changed.size();
  const auto note = [&](int ax, int ay, int bx, int by) {
    if (!contains(ax, ay) || !contains(bx, by)) return;
    const GridCell a = cell(ax, ay), b = cell(bx, by);
    changed.push_back({a, b, cost(a, b)});
    changed.push_back({b, a, cost(b, a)});
  };
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (dx != 0 || dy != 0) note(cx, cy, cx + dx, cy + dy);
  for (const int sx : {-1, 1})
    for (const int sy : {-1, 1}) note(cx + sx, cy, cx, cy + sy);
  blocked_[c] = blocked ? 1 : 0;
  // Only the moves whose cost did change (a move already blocked by another cell stays so).
  std::size_t kept = first;
  for (std::size_t i = first; i < changed.size(); ++i)
    if (cost(changed[i].from, changed[i].to) != changed[i].old_cost) changed[kept++] = changed[i];
  changed.resize(kept);
  return true;
}

}  // namespace polyplan
