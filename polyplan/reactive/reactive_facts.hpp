#pragma once
// The facts the reactive planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// A gradient descent's steps and where it stopped, under its planner's prefix.
struct DescentFacts {
  FactKey<std::int64_t> steps;
  FactKey<FactPoint> stopped_at;
};

// A Bug's walk.
struct BugFacts {
  static constexpr FactKey<double> bound{"bug.bound"};
  static constexpr FactKey<double> distance{"bug.distance"};
  static constexpr FactKey<FactPoints> hits{"bug.hits"};
  static constexpr FactKey<FactPoints> leaves{"bug.leaves"};
};

// A descent of the potential field.
struct PotentialFacts {
  static constexpr FactKey<double> value{"potential.value"};
  static constexpr FactKey<double> gradient{"potential.gradient"};
  static constexpr FactKey<double> step{"potential.step"};
  static constexpr DescentFacts descent{{"potential.steps"}, {"potential.stopped_at"}};
};

// A descent of the navigation function.
struct NavigationFacts {
  static constexpr FactKey<double> kappa{"navigation.kappa"};
  static constexpr FactKey<std::int64_t> spheres{"navigation.spheres"};
  static constexpr DescentFacts descent{{"navigation.steps"}, {"navigation.stopped_at"}};
};

// TangentBug's walk.
struct TangentBugFacts {
  static constexpr FactKey<double> d_followed{"tangent_bug.d_followed"};
  static constexpr FactKey<std::string> sensor_range{"tangent_bug.sensor_range"};
  static constexpr FactKey<std::int64_t> stops{"tangent_bug.stops"};
};

}  // namespace polyplan
