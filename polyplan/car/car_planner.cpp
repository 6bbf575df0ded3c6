#include <polyplan/car/car_planner.hpp>

#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace polyplan {

CarPose start_pose(const Query& query) {
  return {to_double(query.start.x), to_double(query.start.y), query.start_theta.value_or(0) * pi / 180};
}
CarPose goal_pose(const Query& query) {
  return {to_double(query.goal.x), to_double(query.goal.y), query.goal_theta.value_or(0) * pi / 180};
}

std::string to_string(const CarPose& pose) {
  char text[96];
  std::snprintf(text, sizeof text, "[%.10g, %.10g, ", pose.x, pose.y);
  return text + angle_text(pose.theta * 180 / pi) + "]";
}

std::size_t gear_changes(const std::vector<CarState>& path) {
  std::size_t changes = 0;
  int gear = 0;
  for (const CarState& s : path) {
    if (s.arrival.length == 0) continue;
    if (gear != 0 && s.arrival.gear != gear) ++changes;
    gear = s.arrival.gear;
  }
  return changes;
}

namespace {

// How near a driven end must come to the pose it stands for: rounding of the curves' own
// arithmetic (their ends reach the goal to 1e-9), in lengths (heading errors times the radius).
bool arrives(const CarPose& end, const CarPose& at, double radius) {
  const double scale = 1e-9 * (1 + std::max({std::abs(at.x), std::abs(at.y), radius}));
  return std::hypot(end.x - at.x, end.y - at.y) <= scale && radius * std::abs(std::remainder(end.theta - at.theta, 2 * pi)) <= scale;
}

}  // namespace

CarPlanner::CarPlanner(const World& world) : world_(world), collision_(world) {
  if (collision_.body_holds_reference_point()) holonomic_.emplace(world);
}

bool CarPlanner::reaches_goal(const CarPose& end, const CarPose& goal) const { return arrives(end, goal, radius()); }

SteeringPath CarPlanner::steering_path(const CarPose& from, const CarPose& to) const {
  return reverse() ? shortest_reeds_shepp_path(from, to, radius()) : shortest_dubins_path(from, to, radius());
}

double CarPlanner::steering_distance(const CarPose& from, const CarPose& to) const {
  return reverse() ? reeds_shepp_distance(from, to, radius()) : dubins_distance(from, to, radius());
}

std::optional<std::vector<CarState>> CarPlanner::certified_states(const CarPose& from, const SteeringPath& path,
                                                                 const CarPose& to) const {
  std::vector<CarState> states;
  CarPose at = from;
  for (const SteeringSegment& segment : path.segments) {
    if (!collision_.segment_is_free(at, segment)) return std::nullopt;
    at = drive(at, segment, radius(), segment.length);
    states.push_back({at, segment});
  }
  if (!states.empty()) {  // the curve's end is `to` to its rounding (arrives()); the heading as the car turned
    CarPose& end = states.back().pose;
    end = {to.x, to.y, end.theta + std::remainder(to.theta - end.theta, 2 * pi)};
  }
  return states;
}

PlanReport<CarState> CarPlanner::plan(const Query& query, const QueryOptions& options) {
  const Stopwatch clock;
  const std::size_t enclosures_before = collision_.enclosures_tested();
  PlanReport<CarState> report;
  const CarPose start = start_pose(query), goal = goal_pose(query);
  const auto finish = [&] {
    report.facts.set("certification.enclosures", collision_.enclosures_tested() - enclosures_before);
    report.facts.set("query_seconds", clock.seconds());
    return report;
  };
  for (const auto& [what, pose] : {std::pair{"start", start}, std::pair{"goal", goal}})
    if (const auto hit = collision_.pose_blocked_by(pose)) {
      report.fail(PlanStatus::invalid_query, std::string("the ") + what + " " + to_string(pose) + " is not free: the car's body " +
                                                 (*hit == "the bounds" ? "leaves the bounds" : "meets " + *hit));
      return finish();
    }
  if (holonomic_ && holonomic_->separated(query.start, query.goal)) {
    report.fail(PlanStatus::no_path, "start and goal lie in different components of the free space of the car's reference point, "
                                     "which lies in its body: no motion of the car joins them");
    return finish();
  }
  if (holonomic_) holonomic_->set_goal(query.goal);
  Attempt attempt;
  if (start == goal) attempt.path = {CarState{start, {}}};
  else attempt = search(start, goal, report.facts, options.record);
  report.graph = std::move(attempt.graph);
  if (attempt.path.empty()) {
    report.fail(attempt.failure, attempt.why_not);
    return finish();
  }
  // The path proved once more, segment by segment, independently of how the search proved it.
  for (std::size_t i = 1; i < attempt.path.size(); ++i) {
    const CarState& from = attempt.path[i - 1];
    const CarState& to = attempt.path[i];
    if (!arrives(drive(from.pose, to.arrival, radius(), to.arrival.length), to.pose, radius()))
      throw std::logic_error("car planner: segment " + std::to_string(i) + " does not arrive at its pose " + to_string(to.pose));
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
  report.facts.set("gear_changes", gear_changes(report.path));
  report.succeed();
  return finish();
}

}  // namespace polyplan
