#pragma once
// The facts the car planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// A car's paths and its planners' searches.
struct CarFacts {
  static constexpr FactKey<std::int64_t> gear_changes{"gear_changes"};
  static constexpr FactKey<std::int64_t> certification_enclosures{"certification.enclosures"};
  static constexpr FactKey<std::int64_t> connections_tried{"connections_tried"};
  static constexpr FactKey<std::int64_t> controls_tried{"controls_tried"};
  static constexpr FactKey<double> goal_miss{"goal_miss"};
  static constexpr FactKey<double> cost{"cost"};
  static constexpr FactKey<std::string> heuristic{"heuristic"};
  static constexpr FactKey<double> grid_cell{"grid.cell"};
  static constexpr FactKey<std::int64_t> grid_headings{"grid.headings"};
  static constexpr FactKey<double> grid_step{"grid.step"};
};

}  // namespace polyplan
