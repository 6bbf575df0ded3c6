#pragma once
// The drive's options by name (`polyplan replan --algorithm --sensor --memory-mb --time-limit`,
// Python's replan(algorithm=, sensor=, memory_mb=, time_limit=)): one table, so that both check
// them alike.
#include <polyplan/incremental/discovering_robot.hpp>
#include <polyplan/plan/planner_options.hpp>

namespace polyplan {

OptionTable<ReplanOptions> replan_option_table();

}  // namespace polyplan
