#pragma once
// Reading a car's path: its segments, each with the pose it starts from, as `polyplan plan --json`
// writes them ({"segments": [{"start": [x, y, theta], "steer": "L", "gear": 1, "length": 1.5},
// ...]}, theta in degrees). A car moves along arcs and straights in its heading's direction, so a
// list of points, which would slide it sideways between them, is refused.
#include <polyplan/geometry/car_pose.hpp>

#include <string>
#include <vector>

namespace polyplan {

std::vector<CarPathSegment> read_car_path(const std::string& path);

// The same from text already in memory; `name` stands for the file in messages.
std::vector<CarPathSegment> parse_car_path(const std::string& text, const std::string& name);

}  // namespace polyplan
