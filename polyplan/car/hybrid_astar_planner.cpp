#include <polyplan/car/hybrid_astar_planner.hpp>

#include <polyplan/car/car_facts.hpp>
#include <polyplan/car/car_planner.hpp>
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/stopwatch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace polyplan {
namespace {

class HybridAStarPlanner final : public CarPlanner {
 public:
  HybridAStarPlanner(const World& world, const HybridAStarOptions& options) : CarPlanner(world), options_(options) {
    if (options_.headings < 4 || options_.headings > 3600)
      throw std::invalid_argument("headings must lie in [4, 3600]");
    if (options_.cell < 0 || !std::isfinite(options_.cell))
      throw std::invalid_argument("cell must be positive (0: a quarter turning radius)");
    if (options_.step < 0 || !std::isfinite(options_.step))
      throw std::invalid_argument("step must be positive (0: its default)");
    if (!(options_.reverse_cost >= 1) || !std::isfinite(options_.reverse_cost))
      throw std::invalid_argument("reverse-cost must be at least 1 (the heuristic bounds the length driven)");
    if (!(options_.time > 0) || options_.iterations == 0)
      throw std::invalid_argument("time and iterations must be positive");
    if (options_.analytic_every == 0) throw std::invalid_argument("analytic-every must be at least 1");
    if (options_.cell == 0) options_.cell = radius() / 4;
    if (options_.step == 0)
      options_.step =
          std::max(std::sqrt(2.0) * options_.cell, radius() * 2 * pi / static_cast<double>(options_.headings));
    if (options_.switch_cost < 0) options_.switch_cost = radius();
  }

 private:
  struct Node {
    CarState state;
    double g = 0;
    std::size_t parent = 0;
    std::uint64_t bin = 0;
  };

  std::uint64_t bin_of(const CarPose& p) const {
    const auto cell = [&](double v) {
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / options_.cell)) + (1 << 20)) &
             0x1fffff;
    };
    const double turns = p.theta / (2 * pi) * static_cast<double>(options_.headings);
    const auto h = static_cast<std::int64_t>(std::llround(turns)) % static_cast<std::int64_t>(options_.headings);
    const auto heading = static_cast<std::uint64_t>(h < 0 ? h + static_cast<std::int64_t>(options_.headings) : h);
    return (cell(p.x) << 43) | (cell(p.y) << 22) | heading;
  }

  double heuristic(const CarPose& p, const CarPose& goal) const {
    const double steering = steering_distance(p, goal);
    return holonomic() ? std::max(steering, holonomic()->lower_bound(p.x, p.y)) : steering;
  }

  double cost(const SteeringSegment& segment, const SteeringSegment& before) const {
    double c = segment.length * (segment.gear < 0 ? options_.reverse_cost : 1);
    if (before.length > 0 && before.gear != segment.gear) c += options_.switch_cost;
    return c;
  }

  std::vector<CarState> path_to(const std::vector<Node>& nodes, std::size_t id) const {
    std::vector<CarState> path;
    for (;; id = nodes[id].parent) {
      path.push_back(nodes[id].state);
      if (id == 0) break;
    }
    return {path.rbegin(), path.rend()};
  }

  Attempt search(const CarPose& start, const CarPose& goal, Facts& facts, bool record) override {
    const Stopwatch clock;
    std::vector<Node> nodes{{CarState{start, {}}, 0, 0, bin_of(start)}};
    std::unordered_map<std::uint64_t, std::size_t> best{{nodes[0].bin, 0}};
    std::unordered_set<std::uint64_t> closed;
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    open.push({heuristic(start, goal), 0});
    std::size_t expanded = 0, analytic_tries = 0;
    std::vector<SteeringSegment> primitives;
    for (const int gear : reverse() ? std::vector<int>{1, -1} : std::vector<int>{1})
      for (const Steer steer : {Steer::left, Steer::straight, Steer::right})
        primitives.push_back({steer, gear, options_.step});

    Attempt attempt;
    const auto tell = [&] {
      facts.set(SearchFacts::algorithm, "hybrid A*");
      facts.set(SearchFacts::expanded, expanded);
      facts.set(SearchFacts::generated, nodes.size());
      facts.set(SearchFacts::analytic_tries, analytic_tries);
      facts.set(SearchFacts::seconds, clock.seconds());
      facts.set(CarFacts::grid_cell, options_.cell);
      facts.set(CarFacts::grid_headings, options_.headings);
      facts.set(CarFacts::grid_step, options_.step);
      facts.set(CarFacts::heuristic, holonomic() ? "max(steering curve, point among obstacles)" : "steering curve");
      if (record) {
        auto graph = std::make_shared<PlanGraph<CarState>>();
        graph->kind = "search tree";
        for (const Node& n : nodes) graph->vertices.push_back(n.state);
        for (std::size_t i = 1; i < nodes.size(); ++i) graph->edges.emplace_back(nodes[i].parent, i);
        attempt.graph = std::move(graph);
      }
      return attempt;
    };
    while (!open.empty()) {
      if (expanded >= options_.iterations || query_seconds() >= options_.time) {
        const bool timed_out = expanded < options_.iterations;
        facts.set(QueryFacts::stopped_by, timed_out ? "time limit" : "iteration limit");
        attempt.failure = PlanStatus::limit;
        attempt.why_not =
            timed_out ? "the time limit (" + std::to_string(options_.time) + " s) ended the search"
                      : "the iteration limit (" + std::to_string(options_.iterations) + " expansions) ended the search";
        return tell();
      }
      const auto [f, id] = open.top();
      open.pop();
      const std::uint64_t bin = nodes[id].bin;
      if (best.at(bin) != id || !closed.insert(bin).second) continue;
      ++expanded;
      const CarState here = nodes[id].state;
      if ((expanded - 1) % options_.analytic_every == 0) {  // the first expansion and every analytic_every-th after it
        ++analytic_tries;
        if (auto rest = certified_states(here.pose, steering_path(here.pose, goal), goal)) {
          attempt.path = path_to(nodes, id);
          attempt.path.insert(attempt.path.end(), rest->begin(), rest->end());
          facts.set(
              CarFacts::cost, nodes[id].g + [&] {
                double c = 0;
                SteeringSegment before = here.arrival;
                for (const CarState& s : *rest) c += cost(s.arrival, before), before = s.arrival;
                return c;
              }());
          return tell();
        }
      }
      for (const SteeringSegment& primitive : primitives) {
        const CarPose next = drive(here.pose, primitive, radius(), primitive.length);
        const std::uint64_t next_bin = bin_of(next);
        if (closed.count(next_bin)) continue;
        const double g = nodes[id].g + cost(primitive, here.arrival);
        const auto known = best.find(next_bin);
        if (known != best.end() && nodes[known->second].g <= g) continue;
        if (!collision().segment_is_free(here.pose, primitive)) continue;
        nodes.push_back({CarState{next, primitive}, g, id, next_bin});
        best[next_bin] = nodes.size() - 1;
        open.push({g + heuristic(next, goal), nodes.size() - 1});
      }
    }
    attempt.failure = PlanStatus::not_found;
    attempt.why_not = "hybrid A* closed every reachable cell and heading bin (" + std::to_string(expanded) +
                      ") without reaching the goal: a finer cell or more headings may find a path";
    return tell();
  }

  HybridAStarOptions options_;
};

}  // namespace

PlannerEntry<SteeredCar> hybrid_astar_planner_entry() {
  OptionTable<HybridAStarOptions> table;
  table.add("headings", &HybridAStarOptions::headings, "heading bins of the closed set", in_range(4, 3600))
      .add("cell", &HybridAStarOptions::cell, "width of the closed set's cells (0: a quarter of the turning radius)",
           at_least(0))
      .add("step", &HybridAStarOptions::step,
           "length of a motion primitive (0: the larger of 1.41 cells and one heading bin's arc)", at_least(0))
      .add("reverse-cost", &HybridAStarOptions::reverse_cost, "cost per unit driven backward (forward: 1)", at_least(1))
      .add("switch-cost", &HybridAStarOptions::switch_cost, "cost of a gear change (negative: one turning radius)")
      .add("analytic-every", &HybridAStarOptions::analytic_every,
           "try the steering curve to the goal every this many expansions", at_least(1))
      .add("time", &HybridAStarOptions::time, "time limit per query, seconds", above(0))
      .add("iterations", &HybridAStarOptions::iterations, "expansion limit per query", at_least(1));
  return make_planner_entry<SteeredCar, HybridAStarOptions>(
      "hybrid-astar",
      "hybrid A*: heading-binned grid, arcs and straights, steering-curve heuristic and analytic expansion",
      std::move(table),
      [](const World& world, const HybridAStarOptions& options) -> std::unique_ptr<Planner<SteeredCar>> {
        return std::make_unique<HybridAStarPlanner>(world, options);
      });
}

}  // namespace polyplan
