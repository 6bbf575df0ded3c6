#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <stdexcept>

namespace polyplan {
namespace {

template <class Space>
class RrtConnectPlanner final : public SamplingPlanner<Space> {
  using Base = SamplingPlanner<Space>;
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

 public:
  RrtConnectPlanner(std::unique_ptr<SamplingSpace<Space>> space, const RrtConnectOptions& options)
      : Base("rrtconnect", std::move(space), options) {
    if (!(options.step >= 0)) throw std::invalid_argument("step must be 0 (the default) or a positive distance");
    step_ = options.step > 0 ? options.step : this->space().extent() / 5;
  }

 private:
  enum class Grown { trapped, advanced, reached };

  // One step of `tree` toward `target` (its coordinates `to`) from the nearest node.
  Grown extend(SamplingTree<Space>& tree, const Configuration& target, std::span<const double> to,
               std::vector<double>& at, std::size_t& added) {
    auto step = this->step_toward(tree, target, to, step_, at);
    if (step.stays) {
      added = step.from;
      return Grown::reached;  // the target is a node already
    }
    std::shared_ptr<const FreeRegion> region;
    if (!this->motion_free(tree, step.from, step.to, region)) return Grown::trapped;
    added = tree.add(std::move(step.to), at, step.from, std::move(region));
    return step.reaches_target ? Grown::reached : Grown::advanced;
  }

  Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget, Facts& facts,
                bool record) override {
    auto& space = this->space();
    const std::size_t d = space.dimension();
    // The goal tree is a forest rooted at every goal (root i at goals[i]): whichever it meets the
    // start tree from is the goal reached.
    auto& from_start = this->template kept<SamplingTree<Space>>(space, space.start(query));
    auto& from_goal = this->template kept<SamplingTree<Space>>(space, goals, Toward::placed);
    SamplingTree<Space>*grow = &from_start, *other = &from_goal;
    std::vector<double> sample_at(d), new_at(d), step_at(d);

    Attempt attempt;
    std::optional<std::pair<std::size_t, std::size_t>> meeting;  // (start tree node, goal tree node)
    if (const auto start_goal = this->goal_index(goals, space.start(query)))
      meeting.emplace(SamplingTree<Space>::root, *start_goal);
    while (!meeting && budget.next()) {
      const Configuration sample = this->draw(sample_at);
      std::size_t added = 0;
      if (extend(*grow, sample, sample_at, new_at, added) != Grown::trapped) {
        // The other tree connects: steps toward the new node until it gets there or is stopped.
        const Configuration& target = (*grow).nodes()[added];
        std::size_t reached_by = 0;
        Grown connect = Grown::advanced;
        while (connect == Grown::advanced && !budget.spent())
          connect = extend(*other, target, new_at, step_at, reached_by);
        if (connect == Grown::reached)
          meeting = grow == &from_start ? std::pair{added, reached_by} : std::pair{reached_by, added};
      }
      std::swap(grow, other);
    }
    facts.set(SamplingFacts::tree_size, from_start.size() + from_goal.size());
    facts.set(SamplingFacts::start_tree_size, from_start.size());
    facts.set(SamplingFacts::goal_tree_size, from_goal.size());
    if (record) attempt.graph = SamplingTree<Space>::picture({&from_start, &from_goal});
    if (!meeting) {
      attempt.why_not = "the trees did not meet within " + budget.limit_reached();
      return attempt;
    }
    // The start tree's path to the meeting node, then the goal tree's from there (the same
    // configuration, taken once) back to the root of its tree, a goal.
    attempt.path = from_start.path_from_root(meeting->first);
    std::vector<Configuration> rest = from_goal.path_from_root(meeting->second);
    attempt.path.insert(attempt.path.end(), rest.rbegin() + 1, rest.rend());
    this->found(budget, this->length(attempt.path));
    return attempt;
  }

  double step_ = 0;
};

}  // namespace

template <class Space>
PlannerEntry<Space> rrt_connect_planner_entry(SamplingSpaceFactory<Space> make_space) {
  OptionTable<RrtConnectOptions> table;
  table.add("step", &RrtConnectOptions::step, "the farthest one extension goes (0: a fifth of the space's extent)",
            at_least(0));
  add_sampling_options(table);
  return make_sampling_entry<Space, RrtConnectOptions>(
      "rrtconnect", "two trees, from start and goal, that extend and connect, certified motions", std::move(table),
      std::move(make_space), [](std::unique_ptr<SamplingSpace<Space>> space, const RrtConnectOptions& options) {
        return std::make_unique<RrtConnectPlanner<Space>>(std::move(space), options);
      });
}

template PlannerEntry<TranslatingRobot> rrt_connect_planner_entry(SamplingSpaceFactory<TranslatingRobot>);
template PlannerEntry<PlanarArm> rrt_connect_planner_entry(SamplingSpaceFactory<PlanarArm>);
template PlannerEntry<SteeredCar> rrt_connect_planner_entry(SamplingSpaceFactory<SteeredCar>);
template PlannerEntry<RoundRobot> rrt_connect_planner_entry(SamplingSpaceFactory<RoundRobot>);

}  // namespace polyplan
