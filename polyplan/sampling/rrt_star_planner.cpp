#include <polyplan/sampling/rrt_star_planner.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace polyplan {
namespace {

// The measure of the metric's unit ball in d dimensions: π^(d/2) / Γ(d/2 + 1) (Euclidean), 2^d / d! (the torus's sum of
// turns).
double unit_ball(SamplingMetric metric, std::size_t d) {
  const double n = static_cast<double>(d);
  if (metric == SamplingMetric::euclidean) return std::pow(std::numbers::pi, n / 2) / std::tgamma(n / 2 + 1);
  return std::pow(2.0, n) / std::tgamma(n + 1);
}

template <class Space>
class RrtStarPlanner final : public SamplingPlanner<Space> {
  using Base = SamplingPlanner<Space>;
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

 public:
  RrtStarPlanner(std::unique_ptr<SamplingSpace<Space>> space, const RrtStarOptions& options)
      : Base("rrtstar", std::move(space), options), options_(options),
        step_(extension_step(options, this->space().extent())) {
    const double d = static_cast<double>(this->space().dimension());
    k_factor_ = std::numbers::e * (1 + 1 / d);
    gamma_ = 2 * std::pow((1 + 1 / d) * this->space().volume() /
                              unit_ball(this->space().metric(), this->space().dimension()),
                          1 / d);
  }

 private:
  struct Node {
    double cost = 0;  // the tree's path length from the root
    std::vector<std::size_t> children;
  };

  void neighbours_of(const SamplingTree<Space>& tree, std::span<const double> at, std::vector<std::size_t>& out) const {
    const double n = static_cast<double>(tree.size());
    if (options_.rewire == Rewiring::k_nearest) {
      // Only those within one extension (as OMPL's RRT* does): a farther one is rarely a cheaper
      // parent, and certifying a long motion costs the most.
      const std::size_t k = options_.k ? options_.k : static_cast<std::size_t>(std::ceil(k_factor_ * std::log(n + 1)));
      tree.nodes().nearest(at, k, out);
      if (step_ > 0)
        out.erase(
            std::remove_if(out.begin(), out.end(),
                           [&](std::size_t id) { return this->distance(tree.nodes().coordinates(id), at) > step_; }),
            out.end());
      return;
    }
    double r = gamma_ * std::pow(std::log(n + 1) / (n + 1), 1 / static_cast<double>(this->space().dimension()));
    if (step_ > 0) r = std::min(r, step_);
    tree.nodes().within(at, r, out);
  }

  // A new parent for `child` (its cost falls by `saving`): the subtree's costs fall with it.
  void reparent(SamplingTree<Space>& tree, std::vector<Node>& nodes, std::size_t child, std::size_t parent,
                double cost) {
    auto& siblings = nodes[tree.parent(child)].children;
    siblings.erase(std::find(siblings.begin(), siblings.end(), child));
    tree.set_parent(child, parent);
    nodes[parent].children.push_back(child);
    const double saving = nodes[child].cost - cost;
    std::vector<std::size_t> stack{child};
    while (!stack.empty()) {
      const std::size_t id = stack.back();
      stack.pop_back();
      nodes[id].cost -= saving;
      stack.insert(stack.end(), nodes[id].children.begin(), nodes[id].children.end());
    }
  }

  // Whether the motion from the new node `id` to its neighbour `n` is free: the reversed verdict on
  // n → id when the choice of parent decided it and the space is symmetric, otherwise certified.
  bool rewire_free(const SamplingTree<Space>& tree, const std::vector<std::pair<std::size_t, bool>>& verdicts,
                   std::size_t id, std::size_t n) {
    if (this->space().symmetric())
      for (const auto& [decided, free] : verdicts)
        if (decided == n) return free;
    return this->motion_free(tree.nodes(), id, n);
  }

  // The goal node the tree reaches most cheaply (the first of equals), if any goal is in the tree.
  static std::optional<std::size_t> cheapest_goal_node(const std::vector<std::optional<std::size_t>>& goal_nodes,
                                                       const std::vector<Node>& nodes) {
    std::optional<std::size_t> cheapest;
    for (const auto& node : goal_nodes)
      if (node && (!cheapest || nodes[*node].cost < nodes[*cheapest].cost)) cheapest = node;
    return cheapest;
  }

  Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget, Facts& facts,
                bool record) override {
    auto& space = this->space();
    const std::size_t d = space.dimension();
    const auto goals_at = this->coordinates_of(goals);
    std::vector<double> sample_at(d), new_at(d);
    auto& tree = this->template kept<SamplingTree<Space>>(space, space.start(query));
    auto& nodes = this->template kept<std::vector<Node>>(1);
    std::vector<std::optional<std::size_t>> goal_nodes(goals.size());  // goal i's node, once the tree reaches it
    if (const auto start_goal = this->goal_index(goals, space.start(query)))
      goal_nodes[*start_goal] = SamplingTree<Space>::root;
    double best = cheapest_goal_node(goal_nodes, nodes) ? 0 : std::numeric_limits<double>::infinity();
    std::size_t solutions = 0, rewired = 0;
    std::vector<std::size_t> near;
    std::vector<std::pair<double, std::size_t>> by_cost;  // (cost through the neighbour, neighbour)
    std::vector<std::pair<std::size_t, bool>> verdicts;   // (neighbour, whether neighbour → new node is free)

    while (best != 0 && budget.next()) {
      const auto sample = this->goal_biased(goals, goals_at, options_.goal_bias, sample_at);
      auto step = this->step_toward(tree, sample.configuration, sample.at, step_, new_at);
      if (step.stays) continue;
      const bool is_goal = sample.goal && step.reaches_target;
      const std::size_t nearest = step.from;
      Configuration& next = step.to;
      if (is_goal && goal_nodes[*sample.goal]) {
        // The goal is in the tree already: a cheaper parent for it, if a neighbour offers one.
        const std::size_t goal_node = *goal_nodes[*sample.goal];
        const auto goal_at = std::span<const double>(goals_at[*sample.goal]);
        neighbours_of(tree, goal_at, near);
        by_cost.clear();
        for (std::size_t n : near)
          if (n != goal_node)
            by_cost.emplace_back(nodes[n].cost + this->distance(tree.nodes().coordinates(n), goal_at), n);
        std::sort(by_cost.begin(), by_cost.end());
        for (const auto& [cost, n] : by_cost) {
          if (cost >= nodes[goal_node].cost || budget.out_of_time()) break;
          if (this->motion_free(tree.nodes(), n, goal_node)) {
            reparent(tree, nodes, goal_node, n, cost);
            ++rewired;
            break;
          }
        }
      } else {
        std::shared_ptr<const FreeRegion> region;
        if (!this->motion_free(tree, nearest, next, region)) continue;
        // The cheapest certified parent among the neighbours (the nearest one is certified already).
        neighbours_of(tree, new_at, near);
        by_cost.clear();
        for (std::size_t n : near)
          by_cost.emplace_back(nodes[n].cost + this->distance(tree.nodes().coordinates(n), new_at), n);
        std::sort(by_cost.begin(), by_cost.end());
        std::size_t parent = nearest;
        double cost = nodes[nearest].cost + this->distance(tree.nodes().coordinates(nearest), new_at);
        // The verdicts on the motions neighbour → new node decided here: rewiring's motions are
        // these reversed, and in a symmetric space they are not certified again (as OMPL's RRT*).
        verdicts.assign(1, {nearest, true});
        // The time limit may cut the choice (the nearest stays the parent) and the rewiring: each
        // certifies a motion per neighbour, dozens in an arm's space.
        for (const auto& [through, n] : by_cost) {
          if (through >= cost || budget.out_of_time()) break;
          const bool free = this->motion_free(tree.nodes(), n, next, region);
          verdicts.emplace_back(n, free);
          if (free) {
            parent = n, cost = through;
            break;
          }
        }
        const std::size_t id = tree.add(std::move(next), new_at, parent, std::move(region));
        nodes.push_back({cost, {}});
        nodes[parent].children.push_back(id);
        if (is_goal) goal_nodes[*sample.goal] = id;
        // Rewiring: each neighbour the new node reaches more cheaply takes it as its parent.
        for (const auto& [through, n] : by_cost) {
          if (budget.out_of_time()) break;
          if (n == parent || n == SamplingTree<Space>::root) continue;
          const double via = cost + this->distance(new_at, tree.nodes().coordinates(n));
          if (via < nodes[n].cost && rewire_free(tree, verdicts, id, n)) {
            reparent(tree, nodes, n, id, via);
            ++rewired;
          }
        }
      }
      if (const auto cheapest = cheapest_goal_node(goal_nodes, nodes); cheapest && nodes[*cheapest].cost < best) {
        best = nodes[*cheapest].cost;
        ++solutions;
        // The path's length as the report measures it (the tree's costs, updated by subtraction
        // as nodes are rewired, may differ from it in the last bits).
        this->found(budget, this->length(tree.path_from_root(*cheapest)));
      }
    }
    facts.set(SamplingFacts::tree_size, tree.size());
    facts.set(SamplingFacts::solutions, solutions);
    facts.set(SamplingFacts::rewired, rewired);
    facts.set(SamplingFacts::rewire, options_.rewire == Rewiring::k_nearest ? "k-nearest" : "radius");
    Attempt attempt;
    if (record) attempt.graph = SamplingTree<Space>::picture({&tree});
    const auto cheapest = cheapest_goal_node(goal_nodes, nodes);
    if (!cheapest) {
      attempt.why_not = "the tree did not reach the goal within " + budget.limit_reached();
      return attempt;
    }
    attempt.path = tree.path_from_root(*cheapest);
    return attempt;
  }

  RrtStarOptions options_;
  double step_;
  double k_factor_ = 0, gamma_ = 0;
};

}  // namespace

template <class Space>
PlannerEntry<Space> rrt_star_planner_entry(SamplingSpaceFactory<Space> make_space) {
  OptionTable<RrtStarOptions> table;
  table.add("rewire", &RrtStarOptions::rewire,
            "the neighbours a new node may take as parent and rewire: k nearest or within a radius",
            std::vector<std::pair<std::string, Rewiring>>{{"k", Rewiring::k_nearest}, {"radius", Rewiring::radius}});
  table.add("k", &RrtStarOptions::k,
            "rewire=k: the nearest neighbours a new node considers (0: ceil(e (1 + 1/d) log n), growing with the tree)",
            at_least(0));
  add_tree_options(table);
  add_sampling_options(table);
  PlannerEntry<Space> entry = make_sampling_entry<Space, RrtStarOptions>(
      "rrtstar",
      "RRT* (asymptotically optimal, anytime: improves until its time or iteration limit), certified motions",
      std::move(table), std::move(make_space),
      [](std::unique_ptr<SamplingSpace<Space>> space, const RrtStarOptions& options) {
        return std::make_unique<RrtStarPlanner<Space>>(std::move(space), options);
      });
  entry.anytime = true;
  return entry;
}

template PlannerEntry<TranslatingRobot> rrt_star_planner_entry(SamplingSpaceFactory<TranslatingRobot>);
template PlannerEntry<PlanarArm> rrt_star_planner_entry(SamplingSpaceFactory<PlanarArm>);
template PlannerEntry<SteeredCar> rrt_star_planner_entry(SamplingSpaceFactory<SteeredCar>);
template PlannerEntry<RoundRobot> rrt_star_planner_entry(SamplingSpaceFactory<RoundRobot>);

}  // namespace polyplan
