#pragma once
// What the raster tests share: a raster's blocked cells as a set of (x, y), to compare two rasters
// or a raster with hand-counted cells.
#include <polyplan/geometry/rasterize.hpp>

#include <cstddef>
#include <set>
#include <utility>

namespace polyplan::test {

using Cells = std::set<std::pair<std::size_t, std::size_t>>;

inline Cells blocked_cells(const Raster& r) {
  Cells out;
  for (std::size_t y = 0; y < r.cells_per_axis; ++y)
    for (std::size_t x = 0; x < r.cells_per_axis; ++x)
      if (r.is_blocked(x, y)) out.insert({x, y});
  return out;
}

}  // namespace polyplan::test
