#pragma once
// Reading world and path files (docs/design.md "World file"). Numbers are read exactly from their
// text. Every problem throws InputError with one line: file, object, what is wrong.
#include <polyplan/geometry/world.hpp>

#include <string>
#include <vector>

namespace polyplan {

// Reads and validates a world file. Unknown fields are reported in `warnings` (if given).
World read_world(const std::string& path, std::vector<std::string>* warnings = nullptr);

// The same from text already in memory; `name` stands for the file in messages and relative
// paths (obstacles_wkt) resolve against its folder.
World parse_world(const std::string& text, const std::string& name, std::vector<std::string>* warnings = nullptr);

// Reads {"path": [[x, y], ...]}.
std::vector<ExactPoint> read_path(const std::string& path);

// The same from text already in memory; `name` stands for the file in messages.
std::vector<ExactPoint> parse_path(const std::string& text, const std::string& name);

// A path file of any robot's configurations, {"path": [[...], ...]}, each row as many exact
// numbers as the first: (x, y) points, (x, y, degrees) or (x, y, sin, cos) poses, joint angles.
std::vector<std::vector<Rational>> read_path_rows(const std::string& path);
std::vector<std::vector<Rational>> parse_path_rows(const std::string& text, const std::string& name);

}  // namespace polyplan
