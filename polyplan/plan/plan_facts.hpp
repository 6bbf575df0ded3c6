#pragma once
// The facts every planner shares, by key (plan/fact_key.hpp): each names the JSON key it
// is printed as and fixes its value's type.
#include <polyplan/plan/fact_key.hpp>

#include <cstdint>
#include <string>

namespace polyplan {

// What every planner may say of a query.
struct QueryFacts {
  static constexpr FactKey<double> seconds{"query_seconds"};
  static constexpr FactKey<std::string> stopped_by{"stopped_by"};
  static constexpr FactKey<std::string> note{"note"};
};

// The graph a planner built once (or, for a planner without one, its kind).
struct RoadmapFacts {
  static constexpr FactKey<std::string> kind{"roadmap.kind"};
  static constexpr FactKey<std::int64_t> vertices{"roadmap.vertices"};
  static constexpr FactKey<std::int64_t> edges{"roadmap.edges"};
  static constexpr FactKey<double> seconds{"roadmap.seconds"};
  // A visibility graph's edges between corners by kind (PlanGraph::edge_kinds).
  static constexpr FactKey<std::int64_t> supporting_edges{"roadmap.supporting_edges"};
  static constexpr FactKey<std::int64_t> separating_edges{"roadmap.separating_edges"};
  static constexpr FactKey<std::int64_t> other_edges{"roadmap.other_edges"};
};

// The graph search of a query.
struct SearchFacts {
  static constexpr FactKey<std::string> algorithm{"search.algorithm"};
  static constexpr FactKey<std::int64_t> expanded{"search.expanded"};
  static constexpr FactKey<std::int64_t> generated{"search.generated"};
  static constexpr FactKey<double> seconds{"search.seconds"};
  static constexpr FactKey<std::int64_t> path_edges{"search.path_edges"};
  static constexpr FactKey<std::int64_t> heap_operations{"search.heap_operations"};
  static constexpr FactKey<std::int64_t> analytic_tries{"search.analytic_tries"};
};

// A query with several goals (an arm's hand at a point): which one the path reached.
struct GoalFacts {
  static constexpr FactKey<std::int64_t> candidates{"goal.candidates"};
  static constexpr FactKey<std::int64_t> reached{"goal.reached"};
  static constexpr FactKey<double> error{"goal.error"};
  static constexpr FactKey<std::int64_t> solutions{"goal.solutions"};
};

}  // namespace polyplan
