#include <polyplan/sampling/lazy_prm_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/sampling/detail/roadmap_planner.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <algorithm>

namespace polyplan {
namespace {

constexpr std::size_t first_batch = 10;  // milestones drawn before the second search

template <class Space>
class LazyPrmPlanner final : public detail::RoadmapPlanner<Space> {
  using Base = detail::RoadmapPlanner<Space>;
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

 public:
  LazyPrmPlanner(std::unique_ptr<SamplingSpace<Space>> space, const LazyPrmOptions& options)
      : Base("lazyprm", std::move(space), options, options.k, options.roadmap_size) {}

 private:
  // A milestone joined to its nearest milestones by edges not yet certified.
  std::size_t add_milestone(const Configuration& configuration, std::span<const double> at = {}) {
    return roadmap_.add(configuration, at, [](std::size_t) { return detail::Join::uncertified; });
  }

  // Certifies the path's unchecked edges from the start on (both ways in a space that is not
  // symmetric: the edge serves later queries either way); removes the first that is not free.
  // False, with nothing removed, when the time limit stops it: the edges certified stay so.
  bool certify(const std::vector<std::size_t>& path, std::size_t& removed, SamplingBudget& budget) {
    auto& graph = roadmap_.graph();
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      if (budget.out_of_time()) return false;
      const auto [e, exists] = boost::edge(path[i], path[i + 1], graph);
      if (graph[e].certified) continue;
      if (!this->edge_free(roadmap_.nodes(), path[i], path[i + 1])) {
        boost::remove_edge(e, graph);
        ++removed;
        return false;
      }
      graph[e].certified = true;
    }
    return true;
  }

  auto search(std::size_t from, std::size_t to) { return roadmap_.search(from, to, SearchOptions{Search::astar}); }

  Attempt solve(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget, Facts& facts,
                bool record) override {
    // A prebuilt roadmap is certified as it is built, and so are the query's joins to it: nothing
    // is left to certify lazily.
    if (this->prebuilt())
      return this->solve_prebuilt(query, goals, budget, facts, record,
                                  [&](std::size_t from, std::size_t to) { return search(from, to); });
    auto& space = this->space();
    const std::size_t start = add_milestone(space.start(query));
    std::vector<std::size_t> goal_milestones;
    for (const Configuration& goal : goals) goal_milestones.push_back(add_milestone(goal));
    std::vector<double> at(space.dimension());

    std::size_t searches = 0, removed = 0;
    std::vector<std::size_t> path;
    while (path.empty() && !budget.spent()) {
      searches += goal_milestones.size();
      // The cheapest path to any goal over the edges there are: certified, it is the answer.
      const auto result =
          roadmap_.cheapest(start, goal_milestones, [&](std::size_t from, std::size_t to) { return search(from, to); });
      if (result.found) {
        if (certify(result.path, removed, budget)) path = result.path;
        continue;
      }
      // Small at first — an easy problem is solved by a dozen milestones (OMPL's LazyPRM solves the
      // small arms with 10 to 12) —, then half the roadmap again: searches stay O(log n).
      const std::size_t batch = std::max<std::size_t>(first_batch, roadmap_.size() / 2);
      for (std::size_t i = 0; i < batch && budget.next(); ++i) {
        const Configuration sample = this->draw(at);
        if (this->state_free(sample)) add_milestone(sample, at);
      }
    }

    Attempt attempt;
    facts.set(RoadmapFacts::vertices, roadmap_.size());
    facts.set(RoadmapFacts::edges, roadmap_.edges());
    facts.set(SamplingFacts::searches, searches);
    facts.set(SamplingFacts::edges_removed, removed);
    if (record) attempt.graph = roadmap_.picture();
    if (path.empty()) {
      attempt.why_not = "no path of certified edges joined start and goal within " + budget.limit_reached();
      return attempt;
    }
    for (std::size_t v : path) attempt.path.push_back(roadmap_.nodes()[v]);
    this->found(budget, this->length(attempt.path));
    return attempt;
  }

  using Base::roadmap_;
};

}  // namespace

template <class Space>
PlannerEntry<Space> lazy_prm_planner_entry(SamplingSpaceFactory<Space> make_space) {
  OptionTable<LazyPrmOptions> table;
  table.add("k", &LazyPrmOptions::k, "neighbours each milestone is joined to (0: e(1 + 1/d) log n)", at_least(0));
  add_roadmap_size_option(table);
  add_sampling_options(table);
  return make_sampling_entry<Space, LazyPrmOptions>(
      "lazyprm", "lazy PRM: edges certified only when the shortest path wants them, kept across queries",
      std::move(table), std::move(make_space),
      [](std::unique_ptr<SamplingSpace<Space>> space, const LazyPrmOptions& options) {
        return std::make_unique<LazyPrmPlanner<Space>>(std::move(space), options);
      });
}

template PlannerEntry<TranslatingRobot> lazy_prm_planner_entry(SamplingSpaceFactory<TranslatingRobot>);
template PlannerEntry<PlanarArm> lazy_prm_planner_entry(SamplingSpaceFactory<PlanarArm>);
template PlannerEntry<SteeredCar> lazy_prm_planner_entry(SamplingSpaceFactory<SteeredCar>);
template PlannerEntry<RoundRobot> lazy_prm_planner_entry(SamplingSpaceFactory<RoundRobot>);

}  // namespace polyplan
