#include <polyplan/experiment/experiment_tables.hpp>

#include <polyplan/experiment/experiment_statistics.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace polyplan {
namespace {

// Four significant digits: costs and times of very different scales read alike.
std::string brief(double value) {
  if (!std::isfinite(value)) return "–";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string mean_and_spread(const ValueSummary& s) {
  if (s.finite == 0) return "–";
  return brief(s.mean) + " ± " + brief(s.stddev);
}

std::string options_text(const ExperimentPlanner& p) {
  std::string text = p.planner;
  for (const auto& [key, value] : p.options) text += " " + key + "=" + value;
  return text;
}

// At most `most` of the cost times, evenly picked and always the last.
std::vector<std::size_t> some_times(std::size_t count, std::size_t most) {
  std::vector<std::size_t> picked;
  if (count == 0) return picked;
  const std::size_t n = std::min(count, most);
  for (std::size_t i = 1; i <= n; ++i) picked.push_back((count * i + n - 1) / n - 1);
  return picked;
}

void write_cost_table(std::ostream& out, const Experiment& e, const std::vector<CellStatistics>& cells) {
  const auto times = some_times(e.cost_times.size(), 6);
  out << "\nBest cost by time (median over the runs; – while fewer than half have a solution):\n\n| planner |";
  for (std::size_t t : times) out << " " << brief(e.cost_times[t]) << " s |";
  out << "\n| --- |";
  for (std::size_t i = 0; i < times.size(); ++i) out << " ---: |";
  out << '\n';
  for (std::size_t planner = 0; planner < e.planners.size(); ++planner) {
    if (!e.planners[planner].anytime) continue;
    out << "| " << e.planners[planner].name << " |";
    for (std::size_t t : times) out << " " << brief(cells[planner].cost_at[t].median) << " |";
    out << '\n';
  }
}

}  // namespace

void write_experiment_tables(std::ostream& out, const Experiment& experiment, const ExperimentResults& results) {
  const auto statistics = experiment_statistics(experiment, results);
  out << "# " << experiment.name << "\n\n"
      << experiment.seeds.size() << " runs per planner entry and problem (seeds), " << brief(experiment.time_limit)
      << " s per run. Cost: the path's length over the solved runs; time: seconds per run.\n";
  if (results.runs.size() < experiment.cells())
    out << "\n**Incomplete:** " << experiment.cells() - results.runs.size() << " of " << experiment.cells()
        << " runs missing (the experiment was interrupted); the counts below are of the runs made.\n";
  bool any_anytime = false;
  for (const ExperimentPlanner& p : experiment.planners) any_anytime = any_anytime || p.anytime;
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem) {
    const ExperimentProblem& p = experiment.problems[problem];
    out << "\n## " << p.name << "\n\n" << p.file << ", query " << p.query << "\n\n";
    out << "| planner | options | success | cost (mean ± std) | cost (median) | time s (mean ± std) | time s (median) "
           "| first solution s (median) |\n";
    out << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (std::size_t planner = 0; planner < experiment.planners.size(); ++planner) {
      const CellStatistics& s = statistics[problem][planner];
      out << "| " << experiment.planners[planner].name << " | " << options_text(experiment.planners[planner]) << " | "
          << s.solved << "/" << s.runs << " | " << mean_and_spread(s.length) << " | "
          << (s.length.count ? brief(s.length.median) : "–") << " | " << mean_and_spread(s.time) << " | "
          << (s.time.count ? brief(s.time.median) : "–") << " | "
          << (s.first_solution.count ? brief(s.first_solution.median) : "–") << " |\n";
    }
    if (any_anytime && !experiment.cost_times.empty()) write_cost_table(out, experiment, statistics[problem]);
  }
}

}  // namespace polyplan
