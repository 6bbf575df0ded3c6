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
#include <vector>

namespace polyplan {

// How a plot maps values onto one of its axes: [lo, hi] linearly (lo < hi), or logarithmically
// (then 0 < lo < hi). Times that span decades go on a log axis, where a linear one would crowd every run
// but the slowest against zero; every plot below maps its axes through this one struct.
struct PlotAxis {
  double lo = 0, hi = 1;
  bool log = false;

  // Where `value` falls from lo (0) to hi (1). A log axis has nothing at or below zero (a run of
  // 0 s): a value under lo sits at its low end.
  double to_unit(double value) const;
  // Round values in [lo, hi] to mark: 1, 2 or 5 times a power of ten, about six of them, on a
  // linear axis; on a log axis the powers of ten, and 2 and 5 times them too when it spans fewer
  // than three decades (linear steps when even those leave fewer than three marks).
  std::vector<double> ticks() const;
};

// Of `statistics` (experiment_statistics(...)[problem]): the share of runs solved by each time. The
// time axis is logarithmic when the first solutions span more than a decade or all come before a
// tenth of the time limit; it then ends at the last of them, as a linear axis does when they come
// before half the limit.
svg::Drawing success_rate_plot(const Experiment& experiment, std::size_t problem,
                               const std::vector<CellStatistics>& statistics);

// The median and the quartiles of the best cost at each of the experiment's cost_times, for the
// anytime planner entries; none when the experiment has none (or no cost_times).
// The time axis is logarithmic when the cost_times span more than a decade.
std::optional<svg::Drawing> cost_over_time_plot(const Experiment& experiment, std::size_t problem,
                                                const std::vector<CellStatistics>& statistics);

enum class BoxPlotOf { time, length };
// A box per planner entry: every run's time, or the solved runs' lengths. The frame fits the
// whiskers and outliers (from zero only when zero is close to them); times that span more than a
// decade go on a log axis.
svg::Drawing box_plot(const Experiment& experiment, std::size_t problem, const std::vector<CellStatistics>& statistics,
                      BoxPlotOf of);

}  // namespace polyplan
