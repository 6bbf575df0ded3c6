#pragma once
// The facts the incremental planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// A robot driving and replanning as its world changes.
struct ReplanFacts {
  static constexpr FactKey<std::string> algorithm{"replan.algorithm"};
  static constexpr FactKey<std::int64_t> changes_made{"replan.changes_made"};
  static constexpr FactKey<double> grid_cost{"replan.grid_cost"};
  static constexpr FactKey<std::int64_t> moves{"replan.moves"};
  static constexpr FactKey<std::int64_t> replans{"replan.replans"};
  static constexpr FactKey<double> sensor_cells{"replan.sensor_cells"};
  static constexpr FactKey<bool> known_map{"replan.known_map"};  // the robot knew the raster at the start
};

}  // namespace polyplan
