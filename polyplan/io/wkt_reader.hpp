#pragma once
// POLYGON and MULTIPOLYGON obstacles from a WKT file (a world file's "obstacles_wkt"), keywords
// in any case, a geometry on one line or several. As docs/design.md says, numbers pass through double,
// so WKT coordinates are exact only as the doubles they become; the JSON world format is the
// exact one.
#include <polyplan/geometry/world.hpp>

#include <string>
#include <vector>

namespace polyplan {

// Throws InputError "<from_file>: obstacles_wkt \"<wkt_path>\": ..." when the file cannot be read
// or a line is not a polygon. The rings are not validated: validate_world does that.
std::vector<PolygonWithHoles> read_wkt_obstacles(const std::string& wkt_path, const std::string& from_file);

// The same from text already in memory; messages start with `prefix` (read_wkt_obstacles passes
// "<from_file>: obstacles_wkt \"<wkt_path>\": ").
std::vector<PolygonWithHoles> parse_wkt_obstacles(const std::string& text, const std::string& prefix);

}  // namespace polyplan
