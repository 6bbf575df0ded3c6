#include <polyplan/car/car_planner.hpp>

#include <polyplan/car/car_facts.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <stdexcept>
#include <utility>

namespace polyplan {

CarPlanner::CarPlanner(const World& world) : world_(world), collision_(world) {
  if (collision_.body_holds_reference_point()) holonomic_.emplace(world);
}

bool CarPlanner::reaches_goal(const CarPose& end, const CarPose& goal) const { return arrives(end, goal, radius()); }

PlanReport<CarState> CarPlanner::plan(const Query& query, const QueryOptions& options) {
  query_clock_ = Stopwatch();
  const std::size_t enclosures_before = collision_.enclosures_tested();
  PlanReport<CarState> report;
  const CarPose start = start_pose(query), goal = goal_pose(query);
  const auto finish = [&] {
    report.facts.set(CarFacts::certification_enclosures, collision_.enclosures_tested() - enclosures_before);
    report.facts.set(QueryFacts::seconds, query_seconds());
    return report;
  };
  if (auto why = car_query_not_free(collision_, query)) {
    report.fail(PlanStatus::invalid_query, std::move(*why));
    return finish();
  }
  if (auto why = car_query_unreachable(holonomic(), query)) {
    report.fail(PlanStatus::no_path, std::move(*why));
    return finish();
  }
  if (holonomic_) holonomic_->set_goal(query.goal);
  Attempt attempt;
  if (start == goal) attempt.path = {CarState{start, {}}};
  else attempt = search(start, goal, report.facts, options.record);
  report.recording.graph = std::move(attempt.graph);
  if (attempt.path.empty()) {
    report.fail(attempt.failure, attempt.why_not);
    return finish();
  }
  // The path proved once more, segment by segment, independently of how the search proved it.
  for (std::size_t i = 1; i < attempt.path.size(); ++i) {
    const CarState& from = attempt.path[i - 1];
    const CarState& to = attempt.path[i];
    if (!arrives(drive(from.pose, to.arrival, radius(), to.arrival.length), to.pose, radius()))
      throw std::logic_error("car planner: segment " + std::to_string(i) + " does not arrive at its pose " +
                             to_string(to.pose));
    if (!collision_.segment_is_free(from.pose, to.arrival)) {
      report.fail(PlanStatus::not_found, "the path's segment " + std::to_string(i) + " from " + to_string(from.pose) +
                                             " could not be certified free on its own");
      return finish();
    }
  }
  if (attempt.path.front().pose != start || !reaches_goal(attempt.path.back().pose, goal))
    throw std::logic_error("car planner: the path does not run from the query's start to its goal");
  report.path = std::move(attempt.path);
  report.length = 0;
  for (const CarState& s : report.path) report.length += s.arrival.length;
  report.certificate = {true, CarCollision::method};
  report.facts.set(CarFacts::gear_changes, gear_changes(report.path));
  report.succeed();
  return finish();
}

}  // namespace polyplan
