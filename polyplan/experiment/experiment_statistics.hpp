#pragma once
// What the tables and plots of an experiment say of each planner entry on each problem: success,
// time, length and the best cost over time, as counts, means, standard deviations and quartiles.
#include <polyplan/experiment/experiment.hpp>

#include <cstddef>
#include <vector>

namespace polyplan {

// Of a sample of values (infinities count in the quartiles, as runs that never got there; the
// mean and standard deviation are of the finite ones, `finite` of them).
struct ValueSummary {
  std::size_t count = 0, finite = 0;
  double mean = 0, stddev = 0;  // sample standard deviation (n − 1); 0 for fewer than two values
  double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;
  // Tukey's whiskers: the farthest values within 1.5 interquartile ranges of the box, and the
  // values beyond them.
  double whisker_low = 0, whisker_high = 0;
  std::vector<double> outliers;
};

// Quartiles by linear interpolation between order statistics (R's type 7, numpy's default).
ValueSummary summarize(std::vector<double> values);

// A planner entry on a problem.
struct CellStatistics {
  std::size_t runs = 0, solved = 0;
  double success_rate = 0;      // solved / runs
  ValueSummary time;            // seconds of every run
  ValueSummary length;          // of the solved runs
  ValueSummary first_solution;  // seconds to the first solution, of the solved runs
  // At each of the experiment's cost_times: the best cost by then over every run (+infinity for a
  // run without a solution yet), and the share of runs solved by then.
  std::vector<ValueSummary> cost_at;
  std::vector<double> solved_at;
  // Every run's first-solution time, sorted (+infinity for the unsolved): the success curve's steps.
  std::vector<double> first_solutions;
};

// statistics[problem][planner entry].
std::vector<std::vector<CellStatistics>> experiment_statistics(const Experiment& experiment,
                                                               const ExperimentResults& results);

}  // namespace polyplan
