#include <polyplan/io/movingai_map.hpp>

#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
#include <polyplan/io/detail/text_file.hpp>

#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace polyplan {
namespace {

using namespace detail;

// Whether a terrain character of the benchmark blocks the cell; nullopt for a character that is
// not one (a free cell by mistake would be a silent wrong answer).
std::optional<bool> terrain_blocks(char c) {
  switch (c) {
    case '.':
    case 'G': return false;
    case '@':
    case 'O':
    case 'T':
    case 'W':
    case 'S': return true;
    default: return std::nullopt;
  }
}

std::string printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (std::isprint(u)) return std::string("'") + c + "'";
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", u);
  return hex;
}

struct GridPoint {
  int x, y;
  bool operator==(const GridPoint&) const = default;
};

// Appends `cycle` to `cycles` as simple loops. Turning left at a diagonal touch keeps apart the
// cycles of two cells that meet only there, but one cycle still passes a pinch point twice when
// the two cells are joined elsewhere (found by fuzzing: such a weakly simple polygon crashed
// CGAL's symmetric difference). Cutting the cycle at each corner it revisits leaves loops whose
// winding numbers add up to the cycle's, so the blocked region (odd winding) is unchanged.
void split_at_repeated_corners(std::vector<GridPoint> cycle, std::vector<std::vector<GridPoint>>& cycles) {
  std::vector<GridPoint> open;                             // the corners walked and not yet closed into a loop
  std::unordered_map<std::int64_t, std::size_t> position;  // where each corner of `open` is
  auto key = [](const GridPoint& p) { return (static_cast<std::int64_t>(p.y) << 32) + p.x; };
  for (const GridPoint& p : cycle) {
    const auto again = position.find(key(p));
    if (again == position.end()) {
      position.emplace(key(p), open.size());
      open.push_back(p);
      continue;
    }
    const std::size_t start = again->second;
    cycles.emplace_back(open.begin() + static_cast<std::ptrdiff_t>(start), open.end());
    for (std::size_t i = start + 1; i < open.size(); ++i) position.erase(key(open[i]));
    open.resize(start + 1);  // p stays: the walk goes on from it
  }
  cycles.push_back(std::move(open));
}

// The boundary of the blocked cells as directed unit edges with the blocked side on the left,
// traced into closed cycles. At a point where two blocked cells touch only diagonally, the trace
// turns left, hugging the cell it walks along, so that every cycle is a simple polygon (the two
// cells' cycles touch at that point).
std::vector<std::vector<GridPoint>> trace_cycles(const GridMap& map) {
  const int w = map.width, h = map.height;
  auto blocked = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && map.is_blocked(x, y); };
  auto key = [&](GridPoint p) { return static_cast<std::size_t>(p.y) * (w + 1) + p.x; };
  const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};  // east, north, west, south (y up)
  // Bit d of leaving[p]: a boundary edge leaves lattice point p in direction d (two at a
  // diagonal touch); the same bit of used[p] once a cycle has taken it.
  std::vector<std::uint8_t> leaving(static_cast<std::size_t>(w + 1) * (h + 1), 0), used(leaving.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!blocked(x, y)) continue;
      // The cell's sides counter-clockwise, each where the neighbour across it is free.
      if (!blocked(x, y - 1)) leaving[key({x, y})] |= 1 << 0;
      if (!blocked(x + 1, y)) leaving[key({x + 1, y})] |= 1 << 1;
      if (!blocked(x, y + 1)) leaving[key({x + 1, y + 1})] |= 1 << 2;
      if (!blocked(x - 1, y)) leaving[key({x, y + 1})] |= 1 << 3;
    }
  auto next_direction = [&](GridPoint at, int heading) {
    for (int turn : {1, 0, 3}) {  // left, straight, right: hug the cell walked along
      const int d = (heading + turn) % 4;
      if (leaving[key(at)] & (1 << d)) return d;
    }
    return -1;  // cannot happen: every boundary edge is followed by one
  };
  std::vector<std::vector<GridPoint>> cycles;
  for (std::size_t k = 0; k < leaving.size(); ++k)
    for (int first_dir = 0; first_dir < 4; ++first_dir) {
      if (!(leaving[k] & (1 << first_dir)) || (used[k] & (1 << first_dir))) continue;
      const GridPoint first{static_cast<int>(k % (w + 1)), static_cast<int>(k / (w + 1))};
      std::vector<GridPoint> cycle;
      GridPoint at = first;
      int dir = first_dir, heading = -1;
      do {
        used[key(at)] |= static_cast<std::uint8_t>(1 << dir);
        if (dir != heading) cycle.push_back(at);  // a corner: straight runs merge
        heading = dir;
        at = {at.x + dx[dir], at.y + dy[dir]};
        dir = next_direction(at, heading);
      } while (!(at == first && dir == first_dir));
      split_at_repeated_corners(std::move(cycle), cycles);
    }
  return cycles;
}

}  // namespace

GridMap read_movingai_map(const std::string& path) { return parse_movingai_map(detail::read_text_file(path), path); }

GridMap parse_movingai_map(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  GridMap map;
  map.source = path;
  std::string line, word;
  int line_number = 0;
  auto fail = [&](const std::string& what) {
    throw InputError(path + ": line " + std::to_string(line_number) + ": " + what);
  };
  bool in_grid = false;
  std::int64_t width = 0, height = 0;
  while (!in_grid && std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream fields(line);
    fields >> word;
    std::string rest;
    if (word == "type") continue;
    if (word == "height" && (fields >> height) && !(fields >> rest)) continue;
    if (word == "width" && (fields >> width) && !(fields >> rest)) continue;
    if (word == "map" && !(fields >> rest)) {
      in_grid = true;
      continue;
    }
    fail("expected the header lines 'type', 'height H', 'width W', 'map', got \"" + detail::abbreviated_text(line) +
         "\"");
  }
  if (!in_grid) fail("missing the 'map' line");
  // Checked before the cells are allocated: the header alone must not cost gigabytes.
  if (width <= 0 || height <= 0 ||
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > limits::map_cells)
    fail("width and height must be positive, with at most " + std::to_string(limits::map_cells) + " cells, got " +
         std::to_string(width) + "x" + std::to_string(height));
  map.width = static_cast<int>(width);
  map.height = static_cast<int>(height);
  map.blocked.assign(static_cast<std::size_t>(map.width) * map.height, false);
  for (int y = 0; y < map.height; ++y) {
    if (!std::getline(in, line))
      fail("the map has " + std::to_string(y) + " rows, the header says " + std::to_string(map.height));
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (static_cast<int>(line.size()) != map.width)
      fail("row " + std::to_string(y) + " has " + std::to_string(line.size()) + " cells, the header says " +
           std::to_string(map.width));
    for (int x = 0; x < map.width; ++x) {
      const auto terrain = terrain_blocks(line[x]);
      if (!terrain)
        fail("row " + std::to_string(y) + ", column " + std::to_string(x) + ": unknown terrain " + printable(line[x]) +
             " (free: . G; blocked: @ O T S W)");
      map.blocked[static_cast<std::size_t>(y) * map.width + x] = *terrain;
    }
  }
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      fail("more rows than the header's " + std::to_string(map.height));
  }
  return map;
}

World world_from_grid(const GridMap& map) {
  World world;
  world.source = map.source;
  world.bounds = Bounds{0, 0, map.width, map.height};
  // Outer boundaries run counter-clockwise, holes clockwise, and none cross: the blocked region is
  // where an odd number of cycles wind, the symmetric difference of their interiors, computed in
  // one aggregated sweep.
  std::vector<Polygon> polygons;
  for (const auto& cycle : trace_cycles(map)) {
    Polygon polygon;
    for (const GridPoint& p : cycle) polygon.push_back(Point(p.x, p.y));
    // A non-simple loop would crash CGAL below (undefined behaviour): a bug of the trace, told.
    if (!polygon.is_simple())
      throw std::logic_error("world_from_grid: a traced boundary of " + map.source + " is not simple");
    if (polygon.orientation() == CGAL::CLOCKWISE) polygon.reverse_orientation();
    polygons.push_back(std::move(polygon));
  }
  CGAL::Polygon_set_2<Kernel> blocked;
  blocked.symmetric_difference(polygons.begin(), polygons.end());
  std::vector<PolygonH> solids;
  blocked.polygons_with_holes(std::back_inserter(solids));
  for (std::size_t i = 0; i < solids.size(); ++i) {
    world.obstacles.push_back(to_exact(solids[i]));
    world.obstacle_names.push_back("blocked region " + std::to_string(i));
  }
  return world;
}

}  // namespace polyplan
