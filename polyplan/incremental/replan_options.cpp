#include <polyplan/incremental/replan_options.hpp>

#include <polyplan/plan/grid_options.hpp>

#include <cmath>

namespace polyplan {

OptionTable<ReplanOptions> replan_option_table() {
  OptionTable<ReplanOptions> table;
  table.add("algorithm", &ReplanOptions::algorithm, "D* Lite, LPA* or A* from scratch", replan_algorithm_choices())
      .add("sensor", &ReplanOptions::sensor_radius,
           "sensor radius in cells: at least sqrt(2) (1 with connectivity 4 or corner cutting), so that the robot "
           "sees every cell its next move touches",
           at_least(1))
      .add("memory-mb", &ReplanOptions::memory_mb, "the memory the drive's tables may take (a larger map is refused)",
           OptionRange{0, 1e7, true, false})
      .add("time-limit", &ReplanOptions::time_limit, "seconds before the drive stops with status limit (0: none)",
           at_least(0));
  add_grid_conventions(
      table, [](auto& o) -> auto& { return o.grid; });
  table.add("known-map", &ReplanOptions::known_map,
            "the robot starts knowing the map as it is at the start (changes are still found by sensing)");
  // The sensor's least radius depends on the grid: checked once every option is set.
  return table.require("sensor", [](const ReplanOptions& o) -> std::optional<std::string> {
    const double least = smallest_sensor_radius(o.grid);
    if (least == 1.0 || o.sensor_radius * o.sensor_radius >= 2.0) return std::nullopt;
    return "expected a number in " + at_least(least).text() + " (1 with connectivity 4 or corner cutting)";
  });
}

}  // namespace polyplan
