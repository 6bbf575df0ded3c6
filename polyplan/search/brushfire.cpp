#include <polyplan/search/brushfire.hpp>

#include <array>
#include <limits>
#include <stdexcept>

namespace polyplan {
namespace {

constexpr std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t outside = 0;

constexpr std::array<std::array<int, 2>, 8> neighbour_offsets{{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

class Grid {
 public:
  Grid(std::size_t columns, std::size_t rows) : columns_(static_cast<long>(columns)), rows_(static_cast<long>(rows)) {}
  bool inside(long x, long y) const { return x >= 0 && y >= 0 && x < columns_ && y < rows_; }
  std::size_t index(long x, long y) const { return static_cast<std::size_t>(x + y * columns_); }
  long x(std::size_t i) const { return static_cast<long>(i) % columns_; }
  long y(std::size_t i) const { return static_cast<long>(i) / columns_; }
  // Calls f(inside, index) for the 8 neighbours of cell i; index is meaningless when outside.
  template <class F>
  void for_each_neighbour(std::size_t i, F&& f) const {
    const long cx = x(i), cy = y(i);
    for (const auto& [dx, dy] : neighbour_offsets) {
      const long nx = cx + dx, ny = cy + dy;
      const bool in = inside(nx, ny);
      f(in, in ? index(nx, ny) : std::size_t{0});
    }
  }

 private:
  long columns_, rows_;
};

// Ids 1, 2, ... for the 8-connected components of blocked cells, in the order of their lowest cell.
std::uint32_t label_obstacles(const Grid& grid, const std::vector<std::uint8_t>& blocked, std::vector<std::uint32_t>& obstacle) {
  std::uint32_t next = outside + 1;
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < blocked.size(); ++seed) {
    if (!blocked[seed] || obstacle[seed] != unreached) continue;
    obstacle[seed] = next;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
        if (in && blocked[n] && obstacle[n] == unreached) {
          obstacle[n] = next;
          stack.push_back(n);
        }
      });
    }
    ++next;
  }
  return next;
}

// Whether free cell c meets the front of another obstacle by the rule of brushfire.hpp.
bool on_front(const Grid& grid, const std::vector<std::uint8_t>& blocked, const std::vector<std::uint32_t>& obstacle,
              std::size_t c) {
  bool meets = false;
  grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
    if (!in) meets = meets || obstacle[c] != outside;
    else if (blocked[n]) meets = meets || obstacle[n] != obstacle[c];
    else meets = meets || obstacle[n] > obstacle[c];
  });
  return meets;
}

}  // namespace

Brushfire brushfire(std::size_t columns, std::size_t rows, const std::vector<std::uint8_t>& blocked,
                    const std::vector<std::uint8_t>& outside_cells) {
  if (blocked.size() != columns * rows) throw std::invalid_argument("brushfire: the blocked flags are not columns x rows");
  if (!outside_cells.empty() && outside_cells.size() != blocked.size())
    throw std::invalid_argument("brushfire: the outside flags are not columns x rows");
  const Grid grid(columns, rows);
  Brushfire b;
  b.columns = columns;
  b.rows = rows;
  b.distance.assign(blocked.size(), unreached);
  b.obstacle.assign(blocked.size(), unreached);
  b.gvd.assign(blocked.size(), 0);
  for (std::size_t c = 0; c < outside_cells.size(); ++c)
    if (blocked[c] && outside_cells[c]) b.obstacle[c] = outside;
  b.obstacle_count = label_obstacles(grid, blocked, b.obstacle);

  // Layer 0: the blocked cells; the outside reaches the border cells in layer 1 with the lowest id.
  std::vector<std::size_t> layer, next;
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (blocked[c]) {
      b.distance[c] = 0;
      layer.push_back(c);
    } else if (grid.x(c) == 0 || grid.y(c) == 0 || grid.x(c) + 1 == static_cast<long>(columns) ||
               grid.y(c) + 1 == static_cast<long>(rows)) {
      b.distance[c] = 1;
      b.obstacle[c] = outside;
      next.push_back(c);
    }
  }
  // A cell first reached in layer d + 1 keeps the lowest id among its neighbours of layer d.
  for (std::uint32_t d = 0; !layer.empty() || !next.empty(); ++d) {
    for (const std::size_t c : layer)
      grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
        if (!in || blocked[n]) return;
        if (b.distance[n] == unreached) {
          b.distance[n] = d + 1;
          b.obstacle[n] = b.obstacle[c];
          next.push_back(n);
        } else if (b.distance[n] == d + 1 && b.obstacle[c] < b.obstacle[n]) {
          b.obstacle[n] = b.obstacle[c];
        }
      });
    if (!next.empty()) b.max_distance = d + 1;
    layer.swap(next);
    next.clear();
  }

  for (std::size_t c = 0; c < blocked.size(); ++c)
    if (!blocked[c] && on_front(grid, blocked, b.obstacle, c)) b.gvd[c] = 1;

  // Two GVD cells meeting only at a corner beside a blocked cell are joined through the free cell
  // on the corner's other side (the diagonal move between them would cut the blocked corner).
  std::vector<std::size_t> joins;
  for (long y = 0; y + 1 < static_cast<long>(rows); ++y)
    for (long x = 0; x + 1 < static_cast<long>(columns); ++x) {
      const std::size_t a = grid.index(x, y), bb = grid.index(x + 1, y), c = grid.index(x, y + 1), d = grid.index(x + 1, y + 1);
      const auto join = [&](std::size_t p, std::size_t q, std::size_t side1, std::size_t side2) {
        if (!b.gvd[p] || !b.gvd[q] || b.gvd[side1] || b.gvd[side2]) return;
        if (blocked[side1] && !blocked[side2]) joins.push_back(side2);
        if (blocked[side2] && !blocked[side1]) joins.push_back(side1);
      };
      join(a, d, bb, c);
      join(bb, c, a, d);
    }
  for (const std::size_t c : joins) b.gvd[c] = 1;
  for (const std::uint8_t g : b.gvd) b.gvd_cells += g;
  return b;
}

}  // namespace polyplan
