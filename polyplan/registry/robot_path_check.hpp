#pragma once
// Whether a path file is a valid motion of a world's robot, each robot by its own motion model:
// `polyplan check WORLD PATH`. A translating robot's path is a polyline ({"path": [[x, y], ...]}),
// checked exactly in its C-space (geometry/path_check.hpp); a car's is its segments ({"segments":
// [...]}, as plan --json writes them), checked by the car's model (car/car_path_check.hpp): a
// polyline would let the car slide sideways.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/world.hpp>

#include <string>

namespace polyplan {

// InputError for a bad path file, or a car's path in a build without the car planners.
PathCheck check_path_file(const World& world, const std::string& path_file);

}  // namespace polyplan
