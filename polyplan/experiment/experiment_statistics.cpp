#include <polyplan/experiment/experiment_statistics.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan {
namespace {

double quantile(const std::vector<double>& sorted, double p) {
  const double at = p * static_cast<double>(sorted.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double a = sorted[below], b = sorted[above];
  if (a == b || at == static_cast<double>(below)) return a;  // also keeps infinities out of inf − inf
  return a + (b - a) * (at - static_cast<double>(below));
}

}  // namespace

ValueSummary summarize(std::vector<double> values) {
  ValueSummary s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0;
  for (double v : values)
    if (std::isfinite(v)) sum += v, ++s.finite;
  s.mean = s.finite ? sum / static_cast<double>(s.finite) : std::numeric_limits<double>::infinity();
  double squares = 0;
  for (double v : values)
    if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
  s.stddev = s.finite > 1 ? std::sqrt(squares / static_cast<double>(s.finite - 1)) : 0;
  s.min = values.front(), s.max = values.back();
  s.q1 = quantile(values, 0.25), s.median = quantile(values, 0.5), s.q3 = quantile(values, 0.75);
  const double reach = 1.5 * (s.q3 - s.q1);
  s.whisker_low = s.q1, s.whisker_high = s.q3;
  for (double v : values) {
    if (v >= s.q1 - reach && v <= s.q3 + reach) {
      s.whisker_low = std::min(s.whisker_low, v);
      s.whisker_high = std::max(s.whisker_high, v);
    } else {
      s.outliers.push_back(v);
    }
  }
  return s;
}

std::vector<std::vector<CellStatistics>> experiment_statistics(const Experiment& experiment,
                                                               const ExperimentResults& results) {
  std::vector<std::vector<const ExperimentRun*>> runs(experiment.problems.size() * experiment.planners.size());
  for (const ExperimentRun& run : results.runs)
    runs[run.problem * experiment.planners.size() + run.planner].push_back(&run);

  std::vector<std::vector<CellStatistics>> statistics(experiment.problems.size(),
                                                      std::vector<CellStatistics>(experiment.planners.size()));
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem)
    for (std::size_t planner = 0; planner < experiment.planners.size(); ++planner) {
      const auto& cell = runs[problem * experiment.planners.size() + planner];
      CellStatistics& s = statistics[problem][planner];
      s.runs = cell.size();
      std::vector<double> times, lengths, firsts;
      for (const ExperimentRun* run : cell) {
        times.push_back(run->seconds);
        s.first_solutions.push_back(run->first_solution_seconds());
        if (!run->solved) continue;
        ++s.solved;
        lengths.push_back(run->length);
        firsts.push_back(run->first_solution_seconds());
      }
      std::sort(s.first_solutions.begin(), s.first_solutions.end());
      s.success_rate = s.runs ? static_cast<double>(s.solved) / static_cast<double>(s.runs) : 0;
      s.time = summarize(times);
      s.length = summarize(lengths);
      s.first_solution = summarize(firsts);
      for (double t : experiment.cost_times) {
        std::vector<double> costs;
        std::size_t solved = 0;
        for (const ExperimentRun* run : cell) {
          costs.push_back(run->cost_at(t));
          solved += run->first_solution_seconds() <= t;
        }
        s.cost_at.push_back(summarize(costs));
        s.solved_at.push_back(s.runs ? static_cast<double>(solved) / static_cast<double>(s.runs) : 0);
      }
    }
  return statistics;
}

}  // namespace polyplan
