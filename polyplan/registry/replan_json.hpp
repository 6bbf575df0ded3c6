#pragma once
// A drive through a discovered map (incremental/discovering_robot.hpp) as JSON: the drive as
// `polyplan replan --json` prints it, and the course's g/rhs trace as --rhs-trace writes it, a
// line per replan's start and per pass. Python's Drive reads the same.
#include <polyplan/incremental/discovering_robot.hpp>

#include <nlohmann/json_fwd.hpp>

namespace polyplan {

nlohmann::json replan_json(const ReplanResult& drive, double sensor_radius);
// {"replan", "at": [x, y], "changed_cells"}
nlohmann::json replan_begins_json(std::size_t replan, GridPoint at, std::size_t changed_cells);
// {"replan", "pass", "popped", "key": [k1, k2], "kind", "g_before", "g_after", "rhs", "updated": [{cell, g, rhs,
// list}], "open": [{cell, g, rhs, key, state}]}; an infinite cost is null.
nlohmann::json replan_pass_json(const ReplanTracePass& pass);
// A cell as the JSON gives it: [x, y].
nlohmann::json grid_point_json(GridPoint p);
// {"connectivity": 8 or 4, "corner_cutting": bool, "diagonal_cost": "sqrt2" or the number as text}.
nlohmann::json grid_conventions_json(const GridConventions& grid);

}  // namespace polyplan
