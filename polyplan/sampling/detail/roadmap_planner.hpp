#pragma once
// What prm and lazyprm share: their roadmap (detail/sampled_roadmap.hpp) and, with roadmap-size N,
// the K-PRM built before any query — N free samples, each joined to its k nearest by certified
// edges (both ways in a space that is not symmetric), drawn from the seed's own stream so that one
// seed builds one roadmap — and the answer of a query on it: the start and goals joined to their k
// nearest milestones by certified edges (visitors: the roadmap does not grow), the roadmap
// searched, and not_found naming the components of start and goals when none is joined. Facts:
// roadmap.samples, roadmap.components beside roadmap.vertices and roadmap.edges (the roadmap's,
// without the query's joins). Private to the two planners' sources.
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/sampling/detail/sampled_roadmap.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <string>
#include <vector>

namespace polyplan::detail {

template <class Space>
class RoadmapPlanner : public SamplingPlanner<Space> {
  using Base = SamplingPlanner<Space>;

 protected:
  using typename Base::Attempt;
  using typename Base::Configuration;
  using typename Base::Query;

  // The build stops at `size` free samples, or at the limits' iterations (draws) or time.
  RoadmapPlanner(std::string name, std::unique_ptr<SamplingSpace<Space>> space, const SamplingLimits& limits,
                 std::size_t k, std::size_t size)
      : Base(std::move(name), std::move(space), limits), roadmap_(this->space(), k), prebuilt_(size > 0) {
    if (prebuilt_) build(size, limits);
  }

  bool prebuilt() const { return prebuilt_; }

  // A query answered on the prebuilt roadmap (see the header): search(start, goal) is the planner's
  // search over it.
  template <class SearchOne>
  Attempt solve_prebuilt(const Query& query, const std::vector<Configuration>& goals, SamplingBudget& budget,
                         Facts& facts, bool record, SearchOne search_one) {
    facts.set(RoadmapFacts::vertices, roadmap_.size());
    facts.set(RoadmapFacts::edges, roadmap_.edges());
    facts.set(SamplingFacts::roadmap_samples, roadmap_.size());
    facts.set(SamplingFacts::roadmap_components, components_);
    const Configuration start = this->space().start(query);
    Attempt attempt;
    if (this->goal_index(goals, start)) {  // no motion to make: the start is a goal
      attempt.path = {start};
      return attempt;
    }
    const std::size_t start_vertex = visit(start);
    std::vector<std::size_t> goal_vertices;
    for (const Configuration& goal : goals) goal_vertices.push_back(visit(goal));
    const auto result = roadmap_.cheapest(start_vertex, goal_vertices, search_one);
    facts.set(SearchFacts::expanded, result.expanded);
    if (record) attempt.graph = roadmap_.picture();
    if (result.found) {
      for (std::size_t v : result.path) attempt.path.push_back(roadmap_.configuration(v));
      this->found(budget, this->length(attempt.path));
    } else {
      attempt.status = PlanStatus::not_found;
      attempt.why_not = unjoined(start_vertex, goal_vertices);
    }
    roadmap_.leave();
    return attempt;
  }

  SampledRoadmap<Space> roadmap_;

 private:
  void build(std::size_t size, const SamplingLimits& limits) {
    this->seed_stream(0, "roadmap");
    SamplingBudget budget(limits);
    std::vector<double> at(this->space().dimension());
    while (roadmap_.size() < size && budget.next()) {
      const Configuration sample = this->draw(at);
      if (!this->state_free(sample)) continue;
      const std::size_t id = roadmap_.size();
      roadmap_.add(sample, at, [&](std::size_t n) {
        return this->edge_free(roadmap_.nodes(), n, id) ? Join::certified : Join::none;
      });
    }
    std::vector<std::size_t> component;
    components_ = roadmap_.components(component);
  }

  // A query's end joined to its nearest milestones by certified edges.
  std::size_t visit(const Configuration& configuration) {
    std::shared_ptr<const FreeRegion> region;
    return roadmap_.visit(configuration, [&](std::size_t n) {
      return this->edge_free(roadmap_.nodes(), n, configuration, region) ? Join::certified : Join::none;
    });
  }

  // Why no path: the components the start and goals lie in, numbered as the roadmap's are (a
  // number from components_ on: a component of its own, joined to no milestone).
  std::string unjoined(std::size_t start, const std::vector<std::size_t>& goals) const {
    std::vector<std::size_t> component;
    roadmap_.components(component);
    std::string goal_words;
    for (std::size_t goal : goals) goal_words += (goal_words.empty() ? "" : ", ") + std::to_string(component[goal]);
    return "the roadmap (" + std::to_string(roadmap_.size()) + " samples, " + std::to_string(components_) +
           " components) does not join start and goal: start in component " + std::to_string(component[start]) +
           ", goal" + (goals.size() > 1 ? "s" : "") + " in component " + goal_words + " (a number from " +
           std::to_string(components_) + " on: an end joined to no milestone)";
  }

  bool prebuilt_;
  std::size_t components_ = 0;  // the prebuilt roadmap's connected components
};

}  // namespace polyplan::detail
