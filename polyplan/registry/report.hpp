#pragma once
// The front door's answer to one query (docs/architecture.md "The front door"): any planner's
// report, whatever it plans over, with the query's and the planner's names. What a caller
// branches on — status, why_not, the path, its length and certificate, the facts — reads the
// same for every kind of problem; the typed report underneath serves pictures and the code of
// one kind.
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace polyplan {

namespace detail {
class SpaceWords;  // registry/detail/space_door.hpp
}  // namespace detail

// One expansion of a planner's graph search (QueryOptions::trace), with where its vertex is.
struct TracedExpansion {
  std::size_t step = 0, vertex = 0;
  std::vector<double> at;  // as a path row
  double g = 0, h = 0, f = 0;
  std::optional<std::size_t> backpointer;
  std::size_t open = 0;
};

using Rows = std::vector<std::vector<double>>;  // configurations as path rows

// What a query recorded for pictures (QueryOptions::record), apart from the answer: configurations
// as path rows.
struct Recording {
  std::string graph_kind;  // "roadmap", "tree"; empty when there is no graph
  Rows graph_vertices;
  std::vector<std::pair<std::size_t, std::size_t>> graph_edges;
  std::vector<std::string> graph_edge_kinds;  // PlanGraph::edge_kinds: empty, or one per edge
  Rows expanded;                              // where the search expanded, in order
  std::shared_ptr<const CellGrid> cells;      // null when the planner has none
  std::vector<Rows> decomposition;            // each convex cell's corners
};

class Report {
 public:
  // One alternative per kind of configuration a planner plans over.
  using Typed = std::variant<PlanReport<ExactPoint>, PlanReport<Pose>, PlanReport<JointAngles>, PlanReport<CarState>>;

  // `space`: what the door says of the space its planner plans in (registry/detail/space_door.hpp);
  // `columns`: the numbers of one configuration in path().
  Report(Typed typed, const detail::SpaceWords& space, std::size_t columns, std::string query, std::string planner);

  bool found() const;
  PlanStatus status() const;
  const std::string& why_not() const;  // empty when found
  double length() const;               // 0 when not found
  const Certificate& certificate() const;
  const Facts& facts() const;
  const std::vector<SolutionImprovement>& improvements() const;
  const std::string& query() const { return query_; }
  const std::string& planner() const { return planner_; }
  // The description of the space its planner plans in (Space::description).
  std::string_view space() const;

  // The path as the JSON's "path" prints it: one row per configuration ([x, y], [x, y, θ°],
  // joint angles), `path_columns()` numbers each.
  Rows path() const;
  std::size_t path_columns() const { return columns_; }
  // The path exactly, where its configurations are exact: [x, y] for points, [x, y, sin, cos] for
  // poses (the exact rotation); none for joint angles and a car's poses, which are doubles.
  std::optional<std::vector<std::vector<Rational>>> exact_path() const;
  // What the query recorded for pictures.
  Recording recording() const;
  // Every expansion of its graph search, when the query asked for them (QueryOptions::trace).
  std::vector<TracedExpansion> trace() const;
  // The JSON object `polyplan plan --json` prints for this query (plan/plan_json.hpp).
  nlohmann::json to_json() const;
  // That object without the answer's own keys (query, found, status, length, path, path_exact,
  // segments, why_not, certified, certified_by): the facts, nested, the clearance and
  // bottleneck, a planner's further paths.
  nlohmann::json facts_json() const;
  // The program's line for people: "start/goal: length 12.345678, 3 segment(s), ...".
  std::string summary() const;

  // An arm query's goal for the hand, which the pictures mark; none for the others.
  std::optional<WorkspaceGoal> target;

  const Typed& typed() const { return typed_; }
  Typed& typed() { return typed_; }

 private:
  Typed typed_;
  const detail::SpaceWords* space_;
  std::size_t columns_;
  std::string query_, planner_;
};

}  // namespace polyplan
