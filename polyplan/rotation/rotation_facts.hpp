#pragma once
// The facts the rotation planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// The rotation layers and a path's turns.
struct RotationFacts {
  static constexpr FactKey<std::string> layers_actual{"layers.actual"};
  static constexpr FactKey<std::int64_t> layers_count{"layers.count"};
  static constexpr FactKey<double> layers_max_error_radians{"layers.max_error_radians"};
  static constexpr FactKey<double> layers_step{"layers.step"};
  static constexpr FactKey<std::int64_t> layers_used{"layers.used"};
  static constexpr FactKey<double> rotation{"rotation"};
  static constexpr FactKey<double> rotation_weight{"rotation_weight"};
  static constexpr FactKey<double> translation_length{"translation_length"};
  static constexpr FactKey<std::int64_t> turn_layers_built{"turn_layers.built"};
  static constexpr FactKey<std::int64_t> turn_layers_used{"turn_layers.used"};
};

}  // namespace polyplan
