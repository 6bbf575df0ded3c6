#include <polyplan/car/car_rrt_planner.hpp>

#include <polyplan/car/car_facts.hpp>
#include <polyplan/car/car_planner.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include <polyplan/sampling/sampling_space.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace polyplan {
namespace {

// A node whose steering curve to the goal is at most this many turning radii long tries it.
constexpr double kConnectRadii = 4;

class CarRrtPlanner final : public CarPlanner {
 public:
  CarRrtPlanner(const World& world, const CarRrtOptions& options) : CarPlanner(world), options_(options) {
    if (options_.dt < 0 || !std::isfinite(options_.dt))
      throw std::invalid_argument("dt must be positive (0: a third of the turning radius)");
    if (!(options_.goal_bias >= 0 && options_.goal_bias <= 1))
      throw std::invalid_argument("goal-bias must lie in [0, 1]");
    if (!(options_.time > 0) || options_.iterations == 0)
      throw std::invalid_argument("time and iterations must be positive");
    if (options_.dt == 0) options_.dt = radius() / 3;
    if (options_.goal_tolerance < 0) options_.goal_tolerance = radius() / 10;
    box_ = car_sampling_box(world);
    for (const int gear : reverse() ? std::vector<int>{1, -1} : std::vector<int>{1})
      for (const Steer steer : {Steer::left, Steer::straight, Steer::right})
        controls_.push_back({steer, gear, options_.dt});
  }

 private:
  bool reaches_goal(const CarPose& end, const CarPose& goal) const override {
    return CarPlanner::reaches_goal(end, goal) || miss(end, goal) <= options_.goal_tolerance;
  }
  double miss(const CarPose& end, const CarPose& goal) const {
    return std::max(std::hypot(end.x - goal.x, end.y - goal.y),
                    radius() * std::abs(std::remainder(end.theta - goal.theta, 2 * pi)));
  }

  // The node nearest to `to` by the steering distance; the Euclidean distance bounds it from
  // below, so a node farther than the best so far in the plane is never measured.
  std::size_t nearest(const std::vector<CarState>& nodes, const CarPose& to) const {
    std::size_t best = 0;
    double best_distance = HUGE_VAL;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (std::hypot(nodes[i].pose.x - to.x, nodes[i].pose.y - to.y) >= best_distance) continue;
      const double d = steering_distance(nodes[i].pose, to);
      if (d < best_distance) best_distance = d, best = i;
    }
    return best;
  }

  Attempt search(const CarPose& start, const CarPose& goal, Facts& facts, bool record) override {
    const Stopwatch clock;
    random_.seed(options_.seed);
    std::vector<CarState> nodes{{start, {}}};
    std::vector<std::size_t> parents{0};
    std::size_t iterations = 0, controls_tried = 0, connections_tried = 0;
    Attempt attempt;
    std::optional<std::vector<CarState>> connection;  // from the reached node to the goal exactly
    const auto tell = [&](std::optional<std::size_t> reached) {
      facts.set(SamplingFacts::tree_size, nodes.size());
      facts.set(SamplingFacts::iterations, iterations);
      facts.set(CarFacts::controls_tried, controls_tried);
      facts.set(CarFacts::connections_tried, connections_tried);
      facts.set(SamplingFacts::seed, options_.seed);
      facts.set(SearchFacts::seconds, clock.seconds());
      if (reached) {
        std::vector<CarState> path;
        for (std::size_t id = *reached;; id = parents[id]) {
          path.push_back(nodes[id]);
          if (id == 0) break;
        }
        attempt.path.assign(path.rbegin(), path.rend());
        if (connection) attempt.path.insert(attempt.path.end(), connection->begin(), connection->end());
        else facts.set(CarFacts::goal_miss, miss(attempt.path.back().pose, goal));
      }
      if (record) {
        auto graph = std::make_shared<PlanGraph<CarState>>();
        graph->kind = "tree";
        graph->vertices = nodes;
        for (std::size_t i = 1; i < nodes.size(); ++i) graph->edges.emplace_back(parents[i], i);
        attempt.graph = std::move(graph);
      }
      return attempt;
    };
    if (steering_distance(start, goal) <= kConnectRadii * radius() &&
        (connection = certified_states(start, steering_path(start, goal), goal)))
      return tell(0);
    if (miss(start, goal) <= options_.goal_tolerance) return tell(0);
    while (iterations < options_.iterations) {
      if (query_seconds() >= options_.time) break;
      ++iterations;
      const CarPose sample =
          uniform01(random_) < options_.goal_bias
              ? goal
              : CarPose{box_.xmin + uniform01(random_) * (box_.xmax - box_.xmin),
                        box_.ymin + uniform01(random_) * (box_.ymax - box_.ymin), (2 * uniform01(random_) - 1) * pi};
      const std::size_t from = nearest(nodes, sample);
      std::optional<CarState> chosen;
      double chosen_distance = HUGE_VAL;
      for (const SteeringSegment& control : controls_) {
        const CarPose end = drive(nodes[from].pose, control, radius(), control.length);
        const double d = steering_distance(end, sample);
        if (d >= chosen_distance) continue;
        ++controls_tried;
        if (!collision().segment_is_free(nodes[from].pose, control)) continue;
        chosen = CarState{end, control};
        chosen_distance = d;
      }
      if (!chosen) continue;
      nodes.push_back(*chosen);
      parents.push_back(from);
      if (steering_distance(chosen->pose, goal) <= kConnectRadii * radius()) {
        ++connections_tried;
        connection = certified_states(chosen->pose, steering_path(chosen->pose, goal), goal);
        if (connection) return tell(nodes.size() - 1);
      }
      if (miss(chosen->pose, goal) <= options_.goal_tolerance) return tell(nodes.size() - 1);
    }
    const bool timed_out = iterations < options_.iterations;
    facts.set(QueryFacts::stopped_by, timed_out ? "time limit" : "iteration limit");
    attempt.failure = PlanStatus::limit;
    attempt.why_not = std::string("the ") +
                      (timed_out ? "time limit (" + std::to_string(options_.time) + " s)"
                                 : "iteration limit (" + std::to_string(options_.iterations) + ")") +
                      " ended the search before the tree came within the goal tolerance";
    return tell(std::nullopt);
  }

  CarRrtOptions options_;
  CarSamplingBox box_;
  std::vector<SteeringSegment> controls_;
  SamplingRandom
      random_;  // sampling/sampling_space.hpp's, made into doubles by its uniform01: one seed, one path everywhere
};

}  // namespace

PlannerEntry<SteeredCar> car_rrt_planner_entry() {
  OptionTable<CarRrtOptions> table;
  table
      .add("dt", &CarRrtOptions::dt, "length driven by one control at unit speed (0: a third of the turning radius)",
           at_least(0))
      .add("goal-bias", &CarRrtOptions::goal_bias, "probability of sampling the goal", in_range(0, 1))
      .add("goal-tolerance", &CarRrtOptions::goal_tolerance,
           "how near the goal a node ends the search: position, and heading times the radius (negative: a tenth of the "
           "turning radius)",
           at_least(0))
      .add("seed", &CarRrtOptions::seed, "the random numbers' seed: one seed, one path")
      .add("time", &CarRrtOptions::time, "time limit per query, seconds", above(0))
      .add("iterations", &CarRrtOptions::iterations, "iteration limit per query", at_least(1));
  return make_planner_entry<SteeredCar, CarRrtOptions>(
      "car-rrt",
      "RRT with controls: forward/backward at full lock or straight for dt, nearest by the steering distance",
      std::move(table), [](const World& world, const CarRrtOptions& options) -> std::unique_ptr<Planner<SteeredCar>> {
        return std::make_unique<CarRrtPlanner>(world, options);
      });
}

}  // namespace polyplan
