#pragma once
// tables.md: one markdown table per problem, a row per planner entry, with the columns of the
// course reports (the course's sampling-planner homework): success, cost (the path's length: mean ± standard deviation
// and median, over the solved runs) and time (seconds per run: mean ± standard deviation and median; and the median
// time to the first solution). For anytime planners a second table gives the median best cost at a few of the
// experiment's cost_times.
#include <polyplan/experiment/experiment.hpp>

#include <iosfwd>

namespace polyplan {

void write_experiment_tables(std::ostream& out, const Experiment& experiment, const ExperimentResults& results);

}  // namespace polyplan
