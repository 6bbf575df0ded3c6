#include <polyplan/search/brushfire.hpp>

#include <array>
#include <cstdlib>
#include <deque>
#include <limits>
#include <stdexcept>

namespace polyplan {
namespace {

constexpr std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t outside = 0;

constexpr std::array<std::array<int, 2>, 8> neighbour_offsets{
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

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
  // Calls f(index) for each free cell one move from cell i: 8-connected, a diagonal move only
  // when both cells beside it are free (no corner cutting, as search/grid_graph.hpp moves).
  template <class F>
  void for_each_move(std::size_t i, const std::vector<std::uint8_t>& blocked, F&& f) const {
    const long cx = x(i), cy = y(i);
    const auto free = [&](long px, long py) { return inside(px, py) && !blocked[index(px, py)]; };
    for (const auto& [dx, dy] : neighbour_offsets)
      if (free(cx + dx, cy + dy) && free(cx + dx, cy) && free(cx, cy + dy)) f(index(cx + dx, cy + dy));
  }

 private:
  long columns_, rows_;
};

// Ids 1, 2, ... for the 8-connected components of blocked cells, in the order of their lowest cell.
std::uint32_t label_obstacles(const Grid& grid, const std::vector<std::uint8_t>& blocked,
                              std::vector<std::uint32_t>& obstacle) {
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

std::int64_t squared_distance(long x, long y, BrushfireOrigin o) {
  const std::int64_t dx = x - o.column, dy = y - o.row;
  return dx * dx + dy * dy;
}

// Origins of one front along its obstacle: the same or 8-adjacent cells.
bool adjacent(BrushfireOrigin a, BrushfireOrigin b) {
  return std::abs(a.column - b.column) <= 1 && std::abs(a.row - b.row) <= 1;
}

// A front: the obstacle it left and the cell of that obstacle it left from.
struct Front {
  std::uint32_t id;
  BrushfireOrigin origin;
};

// Whether `front` beats `held` at cell (x, y): the lower id (the tie rule of brushfire.hpp), then
// the origin nearer the cell, then the origin of lower row, then column — an order that does not
// depend on which neighbour the queue offers first.
bool beats(const Front& front, const Front& held, long x, long y) {
  if (front.id != held.id) return front.id < held.id;
  const std::int64_t mine = squared_distance(x, y, front.origin), theirs = squared_distance(x, y, held.origin);
  if (mine != theirs) return mine < theirs;
  if (front.origin.row != held.origin.row) return front.origin.row < held.origin.row;
  return front.origin.column < held.origin.column;
}

// Of the free cells c at (x, y) and n at (nx, ny), one front each, whether c is the one on the GVD.
bool takes_the_pair(long x, long y, std::size_t c, long nx, long ny, std::size_t n, const Front& mine,
                    const Front& theirs) {
  if (theirs.id != mine.id) return theirs.id > mine.id;
  // One obstacle's fronts from two places: the cell nearer the bisector of the two origins,
  // measured by how much farther each cell is from the other's origin than from its own.
  const std::int64_t here = squared_distance(x, y, theirs.origin) - squared_distance(x, y, mine.origin);
  const std::int64_t there = squared_distance(nx, ny, mine.origin) - squared_distance(nx, ny, theirs.origin);
  if (here != there) return here < there;
  // Equally near (a symmetric place): the cell whose origin comes first along the axis the two
  // origins lie farther apart on, so that every pair across one meeting line, side by side or
  // diagonal, takes the same side and the line stays one cell wide (the cell index would not:
  // it takes the left cell of a pair side by side, the right one of a pair going down-left).
  const long ox = theirs.origin.column - mine.origin.column, oy = theirs.origin.row - mine.origin.row;
  if (ox == 0 && oy == 0) return c < n;
  return std::abs(ox) >= std::abs(oy) ? ox > 0 : oy > 0;
}

// How free cell c is on the GVD by the rules of brushfire.hpp: not, by fronts of one obstacle
// only (thin_one_obstacle_meetings may take it off), or by fronts of two.
enum class Meeting { none, one_obstacle, two_obstacles };

Meeting on_front(const Grid& grid, const std::vector<std::uint8_t>& blocked, const Brushfire& b, std::size_t c) {
  const long x = grid.x(c), y = grid.y(c);
  const Front mine{b.obstacle[c], b.origin[c]};
  Meeting meeting = Meeting::none;
  for (const auto& [dx, dy] : neighbour_offsets) {
    const long nx = x + dx, ny = y + dy;
    const bool in = grid.inside(nx, ny);
    const std::size_t n = in ? grid.index(nx, ny) : 0;
    // A blocked neighbour, and the outside beyond the border, is its own origin.
    const Front theirs =
        in ? Front{b.obstacle[n], b.origin[n]}
           : Front{outside, BrushfireOrigin{static_cast<std::int32_t>(nx), static_cast<std::int32_t>(ny)}};
    if (theirs.id == mine.id && adjacent(theirs.origin, mine.origin)) continue;  // one front
    const Meeting here_is = theirs.id != mine.id ? Meeting::two_obstacles : Meeting::one_obstacle;
    if (here_is <= meeting) continue;
    if (!in || blocked[n] || takes_the_pair(x, y, c, nx, ny, n, mine, theirs)) meeting = here_is;
  }
  return meeting;
}

// Whether the climb goes on from free cell c: c is on the GVD, or a GVD cell or a cell of larger
// distance is one move away.
bool climbs_on(const Grid& grid, const std::vector<std::uint8_t>& blocked, const Brushfire& b, std::size_t c) {
  bool on = b.gvd[c] != 0;
  grid.for_each_move(c, blocked, [&](std::size_t n) { on = on || b.gvd[n] || b.distance[n] > b.distance[c]; });
  return on;
}

// Whether taking GVD cell c off the GVD keeps its GVD neighbours joined: those one move from c
// are all joined to each other by moves between GVD cells of the 3 × 3 block round c (without
// c). A local test, enough for the whole GVD: any path through c can go round it in the block.
bool removable(const Grid& grid, const std::vector<std::uint8_t>& blocked, const Brushfire& b, std::size_t c) {
  std::array<std::size_t, 8> ring{};
  std::size_t count = 0;
  grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
    if (in && !blocked[n] && b.gvd[n]) ring[count++] = n;
  });
  // Flood the ring's GVD cells, by moves between them, from the first one c can move to.
  std::array<std::uint8_t, 8> reached{};
  std::array<std::size_t, 8> stack{};
  std::size_t top = 0;
  bool seeded = false;
  const auto reach = [&](std::size_t n) {
    for (std::size_t k = 0; k < count; ++k)
      if (ring[k] == n && !reached[k]) {
        reached[k] = 1;
        stack[top++] = k;
      }
  };
  grid.for_each_move(c, blocked, [&](std::size_t n) {
    if (seeded) return;
    reach(n);
    seeded = top > 0;
  });
  while (top > 0) grid.for_each_move(ring[stack[--top]], blocked, reach);
  bool joined = true;
  grid.for_each_move(c, blocked, [&](std::size_t n) {
    for (std::size_t k = 0; k < count; ++k) joined = joined && (ring[k] != n || reached[k]);
  });
  return joined;
}

// Takes the GVD cells where only one obstacle's fronts meet off the GVD wherever that splits no
// piece (removable) and strands no climb (it and every cell one move from it climb on), in a
// fixed order until none can go. Those meetings are everywhere the boundary of one obstacle is
// concave: every corner of a room and every step of a jagged (rasterised slanted or curved)
// boundary grows a spur, and lines come two wide; what stays is what the GVD needs them for —
// the joins through doors and pockets and between posts, and the cells where climbs end (the
// local maxima of the distance, such as the middle of an empty room).
void thin_one_obstacle_meetings(const Grid& grid, const std::vector<std::uint8_t>& blocked, Brushfire& b,
                                const std::vector<std::uint8_t>& thinnable) {
  std::deque<std::size_t> work;
  std::vector<std::uint8_t> queued = thinnable;
  for (std::size_t c = 0; c < thinnable.size(); ++c)
    if (thinnable[c]) work.push_back(c);
  while (!work.empty()) {
    const std::size_t c = work.front();
    work.pop_front();
    queued[c] = 0;  // tried again when a neighbour goes
    if (!b.gvd[c] || !removable(grid, blocked, b, c)) continue;
    b.gvd[c] = 0;
    bool stranded = !climbs_on(grid, blocked, b, c);
    grid.for_each_move(c, blocked, [&](std::size_t n) { stranded = stranded || !climbs_on(grid, blocked, b, n); });
    if (stranded) {
      b.gvd[c] = 1;
      continue;
    }
    grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
      if (in && b.gvd[n] && thinnable[n] && !queued[n]) {
        queued[n] = 1;
        work.push_back(n);
      }
    });
  }
}

}  // namespace

Brushfire brushfire(std::size_t columns, std::size_t rows, const std::vector<std::uint8_t>& blocked,
                    const std::vector<std::uint8_t>& outside_cells) {
  if (blocked.size() != columns * rows)
    throw std::invalid_argument("brushfire: the blocked flags are not columns x rows");
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

  // Layer 0: the blocked cells, each its own origin; the outside reaches the border cells in
  // layer 1 with the lowest id, from the cell beyond the border nearest each.
  b.origin.assign(blocked.size(), BrushfireOrigin{});
  std::vector<std::size_t> layer, next;
  const auto offer = [&](std::size_t n, const Front& front) {
    if (!beats(front, Front{b.obstacle[n], b.origin[n]}, grid.x(n), grid.y(n))) return;
    b.obstacle[n] = front.id;
    b.origin[n] = front.origin;
  };
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    const long x = grid.x(c), y = grid.y(c);
    b.origin[c] = BrushfireOrigin{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
    if (blocked[c]) {
      b.distance[c] = 0;
      layer.push_back(c);
      continue;
    }
    for (const auto& [dx, dy] : neighbour_offsets)
      if (const long nx = x + dx, ny = y + dy; (dx == 0 || dy == 0) && !grid.inside(nx, ny)) {
        if (b.distance[c] == unreached) {
          b.distance[c] = 1;
          next.push_back(c);
        }
        offer(c, Front{outside, BrushfireOrigin{static_cast<std::int32_t>(nx), static_cast<std::int32_t>(ny)}});
      }
  }
  // A cell first reached in layer d + 1 keeps the best front (beats) among its neighbours of layer d.
  for (std::uint32_t d = 0; !layer.empty() || !next.empty(); ++d) {
    for (const std::size_t c : layer)
      grid.for_each_neighbour(c, [&](bool in, std::size_t n) {
        if (!in || blocked[n]) return;
        if (b.distance[n] == unreached) {
          b.distance[n] = d + 1;
          next.push_back(n);
        }
        if (b.distance[n] == d + 1) offer(n, Front{b.obstacle[c], b.origin[c]});
      });
    if (!next.empty()) b.max_distance = d + 1;
    layer.swap(next);
    next.clear();
  }

  std::vector<std::uint8_t> thinnable(blocked.size(), 0);
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (blocked[c]) continue;
    const Meeting meeting = on_front(grid, blocked, b, c);
    b.gvd[c] = meeting != Meeting::none;
    thinnable[c] = meeting == Meeting::one_obstacle;
  }

  // Two GVD cells meeting only at a corner beside a blocked cell are joined through the free cell
  // on the corner's other side (the diagonal move between them would cut the blocked corner).
  std::vector<std::size_t> joins;
  for (long y = 0; y + 1 < static_cast<long>(rows); ++y)
    for (long x = 0; x + 1 < static_cast<long>(columns); ++x) {
      const std::size_t a = grid.index(x, y), bb = grid.index(x + 1, y), c = grid.index(x, y + 1),
                        d = grid.index(x + 1, y + 1);
      const auto join = [&](std::size_t p, std::size_t q, std::size_t side1, std::size_t side2) {
        if (!b.gvd[p] || !b.gvd[q] || b.gvd[side1] || b.gvd[side2]) return;
        if (blocked[side1] && !blocked[side2]) joins.push_back(side2);
        if (blocked[side2] && !blocked[side1]) joins.push_back(side1);
      };
      join(a, d, bb, c);
      join(bb, c, a, d);
    }
  for (const std::size_t c : joins) {
    b.gvd[c] = 1;
    thinnable[c] = 1;  // the move it makes stays while nothing else joins the two cells (removable)
  }
  thin_one_obstacle_meetings(grid, blocked, b, thinnable);
  for (const std::uint8_t g : b.gvd) b.gvd_cells += g;
  return b;
}

}  // namespace polyplan
