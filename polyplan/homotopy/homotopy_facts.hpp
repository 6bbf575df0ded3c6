#pragma once
// The facts the homotopy planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// The homotopy classes of a query's paths.
struct HomotopyFacts {
  static constexpr FactKey<std::int64_t> classes{"homotopy.classes"};
  static constexpr FactKey<std::int64_t> rays{"homotopy.rays"};
  static constexpr FactKey<std::int64_t> states{"homotopy.states"};
  static constexpr FactKey<std::string> word{"homotopy.word"};
  static constexpr FactKey<std::string> path_word{"word"};  // each of the paths': its class
};

// A tethered robot's classes and its tether at the goal.
struct TetherFacts {
  static constexpr FactKey<FactPoints> at_goal{"tether.at_goal"};
  static constexpr FactKey<std::string> classes{"tether.classes"};
  static constexpr FactKey<double> largest{"tether.largest"};
  static constexpr FactKey<double> length{"tether.length"};
  static constexpr FactKey<std::int64_t> reachable{"tether.reachable"};
  static constexpr FactKey<std::string> word{"tether.word"};
};

}  // namespace polyplan
