#pragma once
// The limits on what polyplan reads, in one place (the README's "Limits" lists them). Each is
// checked before the memory or the time it guards is spent, and a violation is an InputError
// that names the file, the object and the limit.
#include <cstddef>
#include <cstdint>
#include <string>

namespace polyplan::limits {

// A file polyplan reads (world, arm, path, WKT, MovingAI map, scenario, reference): the largest
// shipped benchmark map is 1.1 MB; a file beyond this is almost certainly not an input.
inline constexpr std::size_t file_bytes = std::size_t{64} << 20;  // 64 MiB

// Arrays and objects nested inside each other in a JSON file. A world needs 6 levels
// (world, obstacles, polygon, outer, point, number); deeper is a mistake or an attack, and the
// recursive code that prints and frees JSON values must not meet 55,000 levels.
inline constexpr int json_depth = 32;

// Characters in one number ("0.1", "-3/7", "2.5e-3"). Exact rational arithmetic on a number
// of 100,000 digits turns every predicate into a long computation.
inline constexpr std::size_t number_characters = 100;

// Every number read is 0 or has a magnitude within [1e-100, 1e100]. CGAL's filters, the search
// heuristics, lengths and pictures use double approximations of squared distances, which
// overflow above about 1e154 and underflow below 1e-154 (CGAL's sweep crashed on coordinates
// around 1e160, lengths printed 0 at 1e-200): the range keeps their squares normal doubles.
inline constexpr int number_decimal_exponent = 100;

// How messages name that range.
inline std::string supported_number_range() {
  const std::string e = std::to_string(number_decimal_exponent);
  return "the supported range (0 or a magnitude from 1e-" + e + " to 1e" + e + ")";
}

// Points of a path or polygon given as an array (Python): a million is more than any drawing of a
// world needs, and each is an exact rational pair.
inline constexpr std::size_t points = std::size_t{1} << 20;

// Cells of a MovingAI map (width × height): the largest benchmark map is 1024 × 1024.
inline constexpr std::uint64_t map_cells = std::uint64_t{1} << 26;  // 8192 × 8192

// Cells per axis of a world's raster (the raster planner's resolution): the maze at 2048 × 2048
// takes 23 s and 155 MB, exactly rasterized and searched; 8192 would take minutes and gigabytes.
inline constexpr std::size_t raster_cells_per_axis = 2048;

// Lines of a scenario file, and so entries of a reference-lengths file.
inline constexpr std::size_t scenario_queries = std::size_t{1} << 20;

}  // namespace polyplan::limits
