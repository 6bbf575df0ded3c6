#include <polyplan/experiment/experiment_problem.hpp>

#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/registry/any_planner.hpp>

#include <algorithm>
#include <stdexcept>

namespace polyplan {
namespace {

std::size_t query_index(const Problem& problem, const std::string& name) {
  const std::vector<std::string> names = problem.query_names();
  const auto at = std::find(names.begin(), names.end(), name);
  if (at == names.end())
    throw std::logic_error(problem.source() + ": no query named " + name + " (the experiment's reader checks it)");
  return static_cast<std::size_t>(at - names.begin());
}

void record(const Report& report, ExperimentRun& run) {
  run.status = report.status();
  run.solved = report.found();
  run.why_not = report.why_not();
  run.length = report.length();
  run.facts = report.facts();
  run.improvements.clear();
  if (!report.found()) return;
  run.improvements = report.improvements();
  // A planner that answers once has its one solution when its query ends.
  if (run.improvements.empty()) run.improvements.push_back({run.seconds, run.length});
}

}  // namespace

void run_once(const Problem& problem, const std::string& planner, const OptionValues& options, const std::string& query,
              ExperimentRun& run) {
  const std::size_t asked = query_index(problem, query);
  const Stopwatch setup;
  const auto built = make_planner(planner, problem, options);
  run.setup_seconds = setup.seconds();
  const Stopwatch asking;
  const Report report = built->plan(asked);
  run.seconds = asking.seconds();
  record(report, run);
}

ExperimentRun run_cell(const Problem& problem, const ExperimentPlanner& entry, const std::string& query,
                       std::uint64_t seed, double time_limit) {
  ExperimentRun run;
  run.seed = seed;
  try {
    const std::vector<OptionInfo>& known = planner_for(entry.planner, problem).options;
    run_once(problem, entry.planner, options_for_run(entry.options, known, seed, time_limit), query, run);
  } catch (const std::exception& e) {
    mark_failed(run, std::string("the run failed: ") + e.what());
  }
  return run;
}

void mark_failed(ExperimentRun& run, const std::string& why) {
  run.status = PlanStatus::not_found;
  run.solved = false;
  run.improvements.clear();
  run.why_not = why;
}

OptionValues options_for_run(const OptionValues& options, const std::vector<OptionInfo>& known, std::uint64_t seed,
                             double time_limit) {
  OptionValues values = options;
  const auto has = [&](const char* name) {
    return std::any_of(known.begin(), known.end(), [&](const OptionInfo& o) { return o.name == name; });
  };
  if (has("seed")) values.emplace_back("seed", std::to_string(seed));
  if (has("time")) values.emplace_back("time", detail::show_number(time_limit));
  return values;
}

}  // namespace polyplan
