#pragma once
// The facts the arm planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// The arm's torus-grid search.
struct ArmGridFacts {
  static constexpr FactKey<std::int64_t> cells_evaluated{"cells_evaluated"};
  static constexpr FactKey<std::int64_t> expanded{"expanded"};
  static constexpr FactKey<std::int64_t> grid_cells_per_axis{"grid.cells_per_axis"};
  static constexpr FactKey<double> grid_coarse_degrees{"grid.coarse_degrees"};
  static constexpr FactKey<std::int64_t> grid_corridor{"grid.corridor"};
  static constexpr FactKey<std::string> grid_evaluation{"grid.evaluation"};
  static constexpr FactKey<double> grid_lower_bound{"grid.lower_bound"};
  static constexpr FactKey<double> grid_predicted_cells{"grid.predicted_cells"};
  static constexpr FactKey<double> grid_resolution_degrees{"grid.resolution_degrees"};
  static constexpr FactKey<std::int64_t> grid_rounds{"grid.rounds"};
  static constexpr FactKey<std::string> grid_shortest{"grid.shortest"};
  static constexpr FactKey<bool> grid_torus{"grid.torus"};
  static constexpr FactKey<bool> grid_whole_grid{"grid.whole_grid"};
  static constexpr FactKey<double> memory_mb{"memory_mb"};
  static constexpr FactKey<std::int64_t> moves_by_clearance{"moves_by_clearance"};
  static constexpr FactKey<std::int64_t> moves_checked{"moves_checked"};
  static constexpr FactKey<std::int64_t> moves_uncertified{"moves_uncertified"};
  static constexpr FactKey<double> seconds{"seconds"};
};

}  // namespace polyplan
