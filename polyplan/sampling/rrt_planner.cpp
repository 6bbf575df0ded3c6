#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <cmath>
#include <stdexcept>

namespace polyplan {

double extension_step(const RrtOptions& options, double extent) {
  if (!(options.goal_bias >= 0 && options.goal_bias <= 1))
    throw std::invalid_argument("goal-bias must be a probability in [0, 1]");
  if (!(options.step >= 0)) throw std::invalid_argument("step must be 0 (the default) or a positive distance");
  if (options.extend == Extension::to_sample) return 0;
  return options.step > 0 ? options.step : extent / 5;
}

namespace {

template <class Space>
class RrtPlanner final : public SamplingPlanner<Space> {
  using Base = SamplingPlanner<Space>;
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

 public:
  RrtPlanner(std::unique_ptr<SamplingSpace<Space>> space, const RrtOptions& options)
      : Base("rrt", std::move(space), options), options_(options),
        step_(extension_step(options, this->space().extent())) {}

 private:
  Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget, Facts& facts,
                bool record) override {
    auto& space = this->space();
    const std::size_t d = space.dimension();
    const auto goals_at = this->coordinates_of(goals);
    std::vector<double> sample_at(d), new_at(d);
    auto& tree = this->template kept<SamplingTree<Space>>(space, space.start(query));

    Attempt attempt;
    std::size_t reached = SamplingTree<Space>::root;
    bool found = this->goal_index(goals, space.start(query)).has_value();
    while (!found && budget.next()) {
      const auto sample = this->goal_biased(goals, goals_at, options_.goal_bias, sample_at);
      auto step = this->step_toward(tree, sample.configuration, sample.at, step_, new_at);
      std::shared_ptr<const FreeRegion> region;
      if (step.stays || !this->motion_free(tree, step.from, step.to, region)) continue;
      reached = tree.add(std::move(step.to), new_at, step.from, std::move(region));
      found = sample.goal && step.reaches_target;  // at that goal exactly: step_toward gave the target itself
    }
    facts.set(SamplingFacts::tree_size, tree.size());
    if (record) attempt.graph = SamplingTree<Space>::picture({&tree});
    if (!found) {
      attempt.why_not = "the tree did not reach the goal within " + budget.limit_reached();
      return attempt;
    }
    attempt.path = tree.path_from_root(reached);
    this->found(budget, this->length(attempt.path));
    return attempt;
  }

  RrtOptions options_;
  double step_;
};

}  // namespace

template <class Space>
PlannerEntry<Space> rrt_planner_entry(SamplingSpaceFactory<Space> make_space) {
  OptionTable<RrtOptions> table;
  add_tree_options(table);
  add_sampling_options(table);
  return make_sampling_entry<Space, RrtOptions>(
      "rrt", "rapidly-exploring random tree (goal bias, extension E1 or E2), certified motions", std::move(table),
      std::move(make_space), [](std::unique_ptr<SamplingSpace<Space>> space, const RrtOptions& options) {
        return std::make_unique<RrtPlanner<Space>>(std::move(space), options);
      });
}

template PlannerEntry<TranslatingRobot> rrt_planner_entry(SamplingSpaceFactory<TranslatingRobot>);
template PlannerEntry<PlanarArm> rrt_planner_entry(SamplingSpaceFactory<PlanarArm>);
template PlannerEntry<SteeredCar> rrt_planner_entry(SamplingSpaceFactory<SteeredCar>);
template PlannerEntry<RoundRobot> rrt_planner_entry(SamplingSpaceFactory<RoundRobot>);

}  // namespace polyplan
