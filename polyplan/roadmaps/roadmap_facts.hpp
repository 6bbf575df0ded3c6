#pragma once
// The facts the roadmaps planners report, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/plan_report.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// The trapezoidal decomposition and its sweep.
struct TrapezoidFacts {
  static constexpr FactKey<std::int64_t> cells{"trapezoid.cells"};
  static constexpr FactKey<std::int64_t> channel_cells{"trapezoid.channel_cells"};
  static constexpr FactKey<double> funnel_length{"trapezoid.funnel_length"};
  static constexpr FactKey<std::int64_t> walls{"trapezoid.walls"};
  static constexpr FactKey<double> zigzag_length{"trapezoid.zigzag_length"};
  static constexpr FactKey<std::int64_t> sweep_deletions{"sweep.deletions"};
  static constexpr FactKey<std::int64_t> sweep_events{"sweep.events"};
  static constexpr FactKey<std::int64_t> sweep_insertions{"sweep.insertions"};
  static constexpr FactKey<std::int64_t> sweep_most_crossed{"sweep.most_crossed"};
};

// The Voronoi diagram's roadmap.
struct VoronoiFacts {
  static constexpr FactKey<double> bottleneck{"voronoi.bottleneck"};
  static constexpr FactKey<bool> narrows{"voronoi.narrows"};
  static constexpr FactKey<std::int64_t> parabolic_edges{"voronoi.parabolic_edges"};
  static constexpr FactKey<std::int64_t> sites{"voronoi.sites"};
};

}  // namespace polyplan
