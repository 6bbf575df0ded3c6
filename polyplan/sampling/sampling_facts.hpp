#pragma once
// The facts the sampling planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// The sampling planners' runs.
struct SamplingFacts {
  static constexpr FactKey<std::int64_t> seed{"seed"};
  static constexpr FactKey<std::int64_t> iterations{"iterations"};
  static constexpr FactKey<std::int64_t> samples{"samples"};
  static constexpr FactKey<std::int64_t> motions_checked{"motions_checked"};
  static constexpr FactKey<double> raw_length{"raw_length"};
  static constexpr FactKey<double> first_solution_seconds{"first_solution_seconds"};
  static constexpr FactKey<std::int64_t> tree_size{"tree_size"};
  static constexpr FactKey<std::int64_t> start_tree_size{"start_tree_size"};
  static constexpr FactKey<std::int64_t> goal_tree_size{"goal_tree_size"};
  static constexpr FactKey<std::int64_t> edges_removed{"edges_removed"};
  static constexpr FactKey<std::int64_t> searches{"searches"};
  static constexpr FactKey<std::int64_t> solutions{"solutions"};
  static constexpr FactKey<std::int64_t> rewired{"rewired"};
  static constexpr FactKey<std::string> rewire{"rewire"};
  // A roadmap built before the queries (prm and lazyprm's roadmap-size): its free samples (the
  // queries' ends not counted) and connected components.
  static constexpr FactKey<std::int64_t> roadmap_samples{"roadmap.samples"};
  static constexpr FactKey<std::int64_t> roadmap_components{"roadmap.components"};
};

}  // namespace polyplan
