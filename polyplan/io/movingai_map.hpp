#pragma once
// MovingAI grid maps (movingai.com benchmarks) as polygon worlds: blocked cells ('@', 'O', 'T',
// 'W', 'S') are closed unit squares, cell (x, y) = [x, x+1] x [y, y+1] with y the row counted
// from the file's first map row, and the map's border is the world's bounds (a wall). Blocked
// cells are merged into solids while reading (boundary tracing), so a 500k-cell map becomes a
// few hundred polygons before any C-space work.
#include <polyplan/geometry/world.hpp>

#include <string>
#include <vector>

namespace polyplan {

struct GridMap {
  std::string source;
  int width = 0, height = 0;
  std::vector<bool> blocked;  // row-major: blocked[y * width + x]
  bool is_blocked(int x, int y) const { return blocked[static_cast<std::size_t>(y) * width + x]; }
};

// Reads a .map file; throws InputError naming the file and line on anything malformed: a header
// beyond limits::map_cells (checked before allocating), rows of the wrong length or number, a
// character that is no terrain of the benchmark.
GridMap read_movingai_map(const std::string& path);

// The same from text already in memory; `name` stands for the file in messages.
GridMap parse_movingai_map(const std::string& text, const std::string& name);

// The blocked cells as a polygon world (point robot, bounds [0, 0, width, height], no queries).
World world_from_grid(const GridMap& map);

}  // namespace polyplan
