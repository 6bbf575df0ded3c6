#include <polyplan/sampling/sampling_planner.hpp>

#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace polyplan {

std::string SamplingBudget::limit_reached() const {
  if (timed_out_) return "the time limit (" + detail::show_number(seconds_) + " s)";
  return "the iteration limit (" + std::to_string(iterations_) + ")";
}

template <class Space>
SamplingPlanner<Space>::SamplingPlanner(std::string name, std::unique_ptr<SamplingSpace<Space>> space,
                                        SamplingLimits limits)
    : name_(std::move(name)), space_(std::move(space)), limits_(limits), random_(limits.seed) {
  if (!(limits_.time > 0) || !std::isfinite(limits_.time))
    throw std::invalid_argument("time must be a number of seconds above 0");
  if (limits_.iterations == 0) throw std::invalid_argument("iterations must be at least 1");
}

// std::seed_seq is specified bit for bit: one stream everywhere.
template <class Space>
void SamplingPlanner<Space>::seed_stream(std::uint64_t ordinal, std::string_view purpose) {
  std::vector<std::uint32_t> words{static_cast<std::uint32_t>(limits_.seed),
                                   static_cast<std::uint32_t>(limits_.seed >> 32), static_cast<std::uint32_t>(ordinal),
                                   static_cast<std::uint32_t>(ordinal >> 32)};
  for (const char c : name_) words.push_back(static_cast<unsigned char>(c));
  for (const char c : purpose) words.push_back(static_cast<unsigned char>(c));
  std::seed_seq stream(words.begin(), words.end());
  random_.seed(stream);
}

template <class Space>
auto SamplingPlanner<Space>::draw(std::span<double> coordinates) -> Configuration {
  ++samples_;
  space_->sample(random_, coordinates);
  return space_->configuration(coordinates);
}

template <class Space>
std::vector<std::vector<double>> SamplingPlanner<Space>::coordinates_of(
    const std::vector<Configuration>& configurations) const {
  std::vector<std::vector<double>> out(configurations.size(), std::vector<double>(space_->dimension()));
  for (std::size_t i = 0; i < configurations.size(); ++i) space_->coordinates(configurations[i], out[i]);
  return out;
}

template <class Space>
auto SamplingPlanner<Space>::goal_biased(const std::vector<Configuration>& goals,
                                         const std::vector<std::vector<double>>& goals_at, double goal_bias,
                                         std::span<double> drawn_at) -> Sample {
  if (uniform01(random_) < goal_bias) {
    // A single goal draws no number to be chosen, so that its random stream (and every seed's
    // path) is what it was before goal sets. The remainder's bias, below 2^-60, does not matter.
    const std::size_t goal = goals.size() > 1 ? static_cast<std::size_t>(random_() % goals.size()) : 0;
    return {goals[goal], goals_at[goal], goal};
  }
  Configuration drawn = draw(drawn_at);
  return {std::move(drawn), drawn_at, std::nullopt};
}

template <class Space>
double SamplingPlanner<Space>::length(const std::vector<Configuration>& path) const {
  const std::size_t d = space_->dimension();
  std::vector<double> a(d), b(d);
  double sum = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    space_->coordinates(path[i], a);
    space_->coordinates(path[i + 1], b);
    sum += distance(a, b);
  }
  return sum;
}

// Shortcuts between random points of the path (OMPL's shortcutPath): two lengths along it drawn
// at random give two configurations on two different motions; when the motion between them is
// certified free, and so are the motions onto them from the configuration before the first and
// from the second to the one after (a configuration computed on a motion lies on it only up to
// rounding), they replace what lies between, if that is shorter. Then each configuration between
// two whose motion is certified free goes. The length never grows. Each step leaves a path of
// certified motions, so the time limit may stop it after any.
template <class Space>
auto SamplingPlanner<Space>::shortcut(std::vector<Configuration> path, SamplingBudget& budget)
    -> std::vector<Configuration> {
  const std::size_t d = space_->dimension();
  std::vector<double> a(d), b(d), first_at(d), second_at(d);
  std::vector<double> along;  // along[k]: the length from the start to path[k]
  const auto measure = [&] {
    along.assign(1, 0.0);
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      space_->coordinates(path[k], a);
      space_->coordinates(path[k + 1], b);
      along.push_back(along.back() + distance(a, b));
    }
  };
  // The configuration at length s along the path: on the motion path[k] → path[k + 1].
  const auto at = [&](double s, std::vector<double>& out) {
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(along.begin(), along.end(), s) - along.begin()) - 1, path.size() - 2);
    space_->coordinates(path[k], a);
    space_->coordinates(path[k + 1], b);
    const double span = along[k + 1] - along[k];
    space_->interpolate(a, b, span > 0 ? (s - along[k]) / span : 0, out);
    return k;
  };

  const std::size_t attempts = 4 * path.size() + 20;
  measure();
  for (std::size_t attempt = 0; attempt < attempts && path.size() > 2 && !budget.out_of_time(); ++attempt) {
    double s1 = uniform01(random_) * along.back(), s2 = uniform01(random_) * along.back();
    if (s1 > s2) std::swap(s1, s2);
    const std::size_t i = at(s1, first_at), j = at(s2, second_at);
    if (i == j) continue;
    space_->coordinates(path[i], a);
    space_->coordinates(path[j + 1], b);
    const double now = along[j + 1] - along[i];
    const double then = distance(a, first_at) + distance(first_at, second_at) + distance(second_at, b);
    if (!(then < now * (1 - 1e-12))) continue;
    const Configuration first = space_->configuration(first_at), second = space_->configuration(second_at);
    if (!motion_free(first, second) || !motion_free(path[i], first) || !motion_free(second, path[j + 1])) continue;
    std::vector<Configuration> shorter(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i + 1));
    shorter.push_back(first);
    shorter.push_back(second);
    shorter.insert(shorter.end(), path.begin() + static_cast<std::ptrdiff_t>(j + 1), path.end());
    path = std::move(shorter);
    measure();
  }
  for (std::size_t k = 1; k + 1 < path.size() && !budget.out_of_time();)
    if (motion_free(path[k - 1], path[k + 1])) path.erase(path.begin() + static_cast<std::ptrdiff_t>(k));
    else ++k;
  return path;
}

template <class Space>
auto SamplingPlanner<Space>::plan(const Query& query, const QueryOptions& options) -> PlanReport<Configuration> {
  kept_.clear();  // the last query's search, freed before this one's clock starts
  // Each query draws from its own random stream, fixed by the seed, the planner's name and the
  // query's ordinal: carried over from the query before, the stream would depend on where a time
  // limit cut that query, and the same input would not give the same answer; and without the name,
  // planners given one seed draw the same first samples and fail together (rrt and rrtstar did on
  // six_link_forest's seeds 3 and 4).
  seed_stream(queries_asked_++);
  SamplingBudget budget(limits_);
  PlanReport<Configuration> report;
  samples_ = motions_checked_ = 0;
  improvements_.clear();
  Facts& facts = report.facts;
  facts.set(RoadmapFacts::kind, name_);
  facts.set(SamplingFacts::seed, limits_.seed);
  const auto finish = [&] {
    facts.set(SamplingFacts::samples, samples_);
    facts.set(SamplingFacts::motions_checked, motions_checked_);
    facts.set(QueryFacts::seconds, budget.seconds());
    return std::move(report);
  };
  if (auto why = space_->query_not_free(query)) {
    report.fail(PlanStatus::invalid_query, *why);
    return finish();
  }
  if (auto why = space_->no_path(query)) {
    report.fail(PlanStatus::no_path, *why);
    return finish();
  }
  if (auto why = space_->no_goal_found(query)) {
    report.fail(PlanStatus::not_found, *why);
    return finish();
  }

  const std::vector<Configuration> goals = space_->goals(query);
  if (goals.empty()) throw std::logic_error("a sampling space gave a query it accepted no goal to reach");
  if (goals.size() > 1) facts.set(GoalFacts::candidates, goals.size());

  Attempt attempt = solve(query, goals, budget, facts, options.record);
  facts.set(SamplingFacts::iterations, budget.used());
  facts.set(QueryFacts::stopped_by, budget.stopped_by());
  report.recording.graph = std::move(attempt.graph);
  if (attempt.path.empty()) {
    report.fail(attempt.status, std::move(attempt.why_not));
    return finish();
  }
  const std::optional<std::size_t> reached = goal_index(goals, attempt.path.back());
  if (!(attempt.path.front() == space_->start(query)) || !reached)
    throw std::logic_error("a sampling planner's path does not run from the query's start to one of its goals");
  if (attempt.path.size() == 1) attempt.path.push_back(goals[*reached]);  // the start is a goal: one motion of length 0
  if (goals.size() > 1) facts.set(GoalFacts::reached, *reached);
  facts.set(SamplingFacts::first_solution_seconds,
            improvements_.empty() ? budget.seconds() : improvements_.front().seconds);
  facts.set(SamplingFacts::raw_length, length(attempt.path));
  std::vector<Configuration> path =
      limits_.shortcut ? shortcut(std::move(attempt.path), budget) : std::move(attempt.path);
  facts.set(QueryFacts::stopped_by, budget.stopped_by());  // the time limit may have cut the shortcutting

  // Every motion was certified as the planner made it; certified once more as returned, so that
  // no assembly of tree halves or shortcut can slip an unchecked motion into the answer.
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!space_->motion_is_free(path[i], path[i + 1]))
      throw std::logic_error("a sampling planner's path has a motion that is not certified free");
  // A planner that joins certified motions at a pinch point finds no path there, whatever its
  // motions say: an honest not_found, never a path that crosses a zero-width place.
  if (auto why = space_->why_path_invalid(path)) {
    report.fail(PlanStatus::not_found, "the path found is not a valid motion: " + *why);
    return finish();
  }
  report.succeed();
  report.length = length(path);
  report.improvements = improvements_;
  // The shortcut path is one more improvement, had when the query ends.
  if (report.improvements.empty() || report.length < report.improvements.back().length)
    report.improvements.push_back({budget.seconds(), report.length});
  report.path = space_->reported_path(std::move(path), facts);
  report.certificate = {true, space_->certificate_method() + ", every motion certified again on the returned path"};
  return finish();
}

template class SamplingPlanner<TranslatingRobot>;
template class SamplingPlanner<PlanarArm>;
template class SamplingPlanner<SteeredCar>;
template class SamplingPlanner<RoundRobot>;

}  // namespace polyplan
