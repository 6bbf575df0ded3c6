#pragma once
// The facts the grids planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// A rasterised world's grid.
struct RasterFacts {
  static constexpr FactKey<std::int64_t> cells_per_axis{"raster.cells_per_axis"};
  static constexpr FactKey<std::int64_t> blocked_cells{"raster.blocked_cells"};
  static constexpr FactKey<FactCell> start_cell{"raster.start_cell"};
  static constexpr FactKey<FactCell> goal_cell{"raster.goal_cell"};
  static constexpr FactKey<double> grid_cost{"raster.grid_cost"};
  // The grid conventions searched (search/grid_conventions.hpp): 8 or 4, and "sqrt2" or the number.
  static constexpr FactKey<std::int64_t> connectivity{"raster.connectivity"};
  static constexpr FactKey<bool> corner_cutting{"raster.corner_cutting"};
  static constexpr FactKey<std::string> diagonal_cost{"raster.diagonal_cost"};
};

// The grid GVD's distance field and ridge.
struct GvdFacts {
  static constexpr FactKey<std::int64_t> cells{"gvd.cells"};
  static constexpr FactKey<double> max_distance{"gvd.max_distance"};
  static constexpr FactKey<double> clearance_bound{"gvd.clearance_bound"};
  static constexpr FactKey<FactCell> start_cell{"gvd.start_cell"};
  static constexpr FactKey<FactCell> goal_cell{"gvd.goal_cell"};
};

}  // namespace polyplan
