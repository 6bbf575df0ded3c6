#pragma once
// Geometric validation of a world built in code or read from a file (io/world_reader.hpp calls
// it): simple polygons with at least three distinct vertices, holes inside their outer boundary,
// sensible bounds, robot parts that are simple polygons. Exact (CGAL Epeck).
#include <polyplan/geometry/world.hpp>

namespace polyplan {

// Throws InputError "<world.source>: <object>: <problem>" for the first problem found, naming the
// object as world.obstacle_names does. On success, drops repeated consecutive vertices and orients
// every ring: outer boundaries and robot parts counter-clockwise, holes clockwise.
void validate_world(World& world);

}  // namespace polyplan
