#pragma once
// Geometric validation of a parsed world (CGAL side, in world_checks.cpp): simple polygons,
// holes inside their outer boundary, sensible bounds. Orientation is normalised silently.
#include "geometry/world.hpp"

#include <string>
#include <vector>

namespace polyplan::detail {

// Throws InputError "<file>: <object>: <problem>".
void check_and_orient_world(World& world);

// Reads POLYGON / MULTIPOLYGON obstacles from a WKT file (CGAL's reader, through double).
// Throws InputError naming `from_file` and the WKT file when it cannot be read.
std::vector<PolygonWithHoles> read_wkt_obstacles(const std::string& wkt_path, const std::string& from_file);

}  // namespace polyplan::detail
