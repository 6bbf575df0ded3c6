#include <polyplan/sampling/prm_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/sampling/detail/roadmap_planner.hpp>

#include <numeric>

namespace polyplan {
namespace {

template <class Space>
class PrmPlanner final : public detail::RoadmapPlanner<Space> {
  using Base = detail::RoadmapPlanner<Space>;
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

 public:
  PrmPlanner(std::unique_ptr<SamplingSpace<Space>> space, const PrmOptions& options)
      : Base("prm", std::move(space), options, options.k, options.roadmap_size), options_(options) {}

 private:
  std::size_t component(std::size_t id) {
    while (components_[id] != id) id = components_[id] = components_[components_[id]];  // path halving
    return id;
  }

  // A milestone joined to its nearest milestones by every motion certified free (`at`: its
  // coordinates, or none to have the space give them) — both ways in a space that is not
  // symmetric, since the roadmap's edges serve either way.
  // Past the time limit (`budget`: none for the query's own milestones, which join all theirs)
  // a drawn milestone joins no more neighbours: each join certifies a motion.
  std::size_t add_milestone(const Configuration& configuration, std::span<const double> at = {},
                            SamplingBudget* budget = nullptr) {
    const std::size_t id = roadmap_.size();
    components_.push_back(id);
    return roadmap_.add(configuration, at, [&](std::size_t n) {
      if (budget && budget->out_of_time()) return detail::Join::none;
      if (!this->edge_free(roadmap_.nodes(), n, id)) return detail::Join::none;
      components_[component(n)] = component(id);
      return detail::Join::certified;
    });
  }

  // The milestones of `goals` in the component of `start`.
  std::vector<std::size_t> joined_to(std::size_t start, const std::vector<std::size_t>& goals) {
    std::vector<std::size_t> joined;
    for (std::size_t goal : goals)
      if (component(goal) == component(start)) joined.push_back(goal);
    return joined;
  }

  // The roadmap's cheapest path from → to, by the planner's search.
  auto search(std::size_t from, std::size_t to) {
    return options_.bidirectional ? roadmap_.search_both_ways(from, to) : roadmap_.search(from, to, options_.search);
  }

  Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget, Facts& facts,
                bool record) override {
    facts.set(SearchFacts::algorithm, options_.bidirectional ? std::string("bidirectional dijkstra")
                                                             : std::string(to_string(options_.search.algorithm)));
    if (this->prebuilt())
      return this->solve_prebuilt(query, goals, budget, facts, record,
                                  [&](std::size_t from, std::size_t to) { return search(from, to); });
    auto& space = this->space();
    const std::size_t start = add_milestone(space.start(query));
    std::vector<std::size_t> goal_milestones;
    for (const Configuration& goal : goals) goal_milestones.push_back(add_milestone(goal));
    std::vector<double> at(space.dimension());
    while (joined_to(start, goal_milestones).empty() && budget.next()) {
      const Configuration sample = this->draw(at);
      if (this->state_free(sample)) add_milestone(sample, at, &budget);
    }

    Attempt attempt;
    const auto finish = [&] {
      facts.set(RoadmapFacts::vertices, roadmap_.size());
      facts.set(RoadmapFacts::edges, roadmap_.edges());
      if (record) attempt.graph = roadmap_.picture();
      return std::move(attempt);
    };
    const std::vector<std::size_t> joined = joined_to(start, goal_milestones);
    if (joined.empty()) {
      attempt.why_not = "start and goal were not joined in the roadmap within " + budget.limit_reached();
      return finish();
    }
    const auto result =
        roadmap_.cheapest(start, joined, [&](std::size_t from, std::size_t to) { return search(from, to); });
    facts.set(SearchFacts::expanded, result.expanded);
    for (std::size_t v : result.path) attempt.path.push_back(roadmap_.nodes()[v]);
    this->found(budget, this->length(attempt.path));
    return finish();
  }

  using Base::roadmap_;
  PrmOptions options_;
  std::vector<std::size_t> components_;  // union-find parents
};

}  // namespace

template <class Space>
PlannerEntry<Space> prm_planner_entry(SamplingSpaceFactory<Space> make_space) {
  OptionTable<PrmOptions> table;
  table.add("k", &PrmOptions::k, "neighbours each milestone is joined to (0: e(1 + 1/d) log n)", at_least(0));
  add_search_options(table, &PrmOptions::search);
  table.add("bidirectional", &PrmOptions::bidirectional, "search the roadmap with bidirectional Dijkstra instead");
  add_roadmap_size_option(table);
  add_sampling_options(table);
  return make_sampling_entry<Space, PrmOptions>(
      "prm", "probabilistic roadmap (k nearest), kept across queries, certified motions", std::move(table),
      std::move(make_space), [](std::unique_ptr<SamplingSpace<Space>> space, const PrmOptions& options) {
        return std::make_unique<PrmPlanner<Space>>(std::move(space), options);
      });
}

template PlannerEntry<TranslatingRobot> prm_planner_entry(SamplingSpaceFactory<TranslatingRobot>);
template PlannerEntry<PlanarArm> prm_planner_entry(SamplingSpaceFactory<PlanarArm>);
template PlannerEntry<SteeredCar> prm_planner_entry(SamplingSpaceFactory<SteeredCar>);
template PlannerEntry<RoundRobot> prm_planner_entry(SamplingSpaceFactory<RoundRobot>);

}  // namespace polyplan
