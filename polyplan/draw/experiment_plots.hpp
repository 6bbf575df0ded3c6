#pragma once
// The pictures of an experiment (`polyplan benchmark`), one set per problem, ready for a report:
// the success rate against time per planner entry; the median best cost against time with its
// quartile band, for anytime planners (RRT*); box plots of the time and of the length per planner
// entry (Tukey's whiskers: 1.5 interquartile ranges; the runs beyond them as dots). Colours are
// the theme's path palette, one per planner entry, the same in every picture of an experiment.
#include <polyplan/draw/svg.hpp>
#include <polyplan/experiment/experiment.hpp>
#include <polyplan/experiment/experiment_statistics.hpp>

#include <optional>

namespace polyplan {

// Of `statistics` (experiment_statistics(...)[problem]): the share of runs solved by each time.
svg::Drawing success_rate_plot(const Experiment& experiment, std::size_t problem,
                               const std::vector<CellStatistics>& statistics);

// The median and the quartiles of the best cost at each of the experiment's cost_times, for the
// anytime planner entries; none when the experiment has none (or no cost_times).
std::optional<svg::Drawing> cost_over_time_plot(const Experiment& experiment, std::size_t problem,
                                                const std::vector<CellStatistics>& statistics);

enum class BoxPlotOf { time, length };
// A box per planner entry: every run's time, or the solved runs' lengths.
svg::Drawing box_plot(const Experiment& experiment, std::size_t problem, const std::vector<CellStatistics>& statistics,
                      BoxPlotOf of);

}  // namespace polyplan
