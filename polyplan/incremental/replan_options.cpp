#include <polyplan/incremental/replan_options.hpp>

#include <cmath>

namespace polyplan {

OptionTable<ReplanOptions> replan_option_table() {
  OptionTable<ReplanOptions> table;
  return table
      .add("algorithm", &ReplanOptions::algorithm, "D* Lite, LPA* or A* from scratch", replan_algorithm_choices())
      .add("sensor", &ReplanOptions::sensor_radius,
           "sensor radius in cells: at least sqrt(2), so that the robot sees every cell its next move touches",
           at_least(std::sqrt(2.0)))
      .add("memory-mb", &ReplanOptions::memory_mb, "the memory the drive's tables may take (a larger map is refused)",
           OptionRange{0, 1e7, true, false})
      .add("time-limit", &ReplanOptions::time_limit, "seconds before the drive stops with status limit (0: none)",
           at_least(0));
}

}  // namespace polyplan
