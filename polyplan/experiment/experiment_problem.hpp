#pragma once
// One run of an experiment: a registry planner built through the front door for a problem and
// asked one of its queries, timed (registry/any_planner.hpp). The runner gives each thread its own
// Problem: planners and the exact numbers under them are not shared between threads.
#include <polyplan/experiment/experiment.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/registry/problem.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace polyplan {

// `planner` built for `problem` with `options`, then asked the query named `query` once. Fills
// every field of `run` but its indices and seed.
void run_once(const Problem& problem, const std::string& planner, const OptionValues& options, const std::string& query,
              ExperimentRun& run);

// One cell's run: the planner entry built for `problem` with the run's seed and time limit, and
// asked `query` once. A planner that throws (a bug, not an answer) gives a failed run (not found,
// its message in why_not), so that one run cannot lose a long experiment.
ExperimentRun run_cell(const Problem& problem, const ExperimentPlanner& entry, const std::string& query,
                       std::uint64_t seed, double time_limit);

// A run that failed before it could answer: not found, `why` in why_not.
void mark_failed(ExperimentRun& run, const std::string& why);

// `options` with the experiment's seed and time limit as the planner's "seed" and "time" options,
// for the planners that have them.
OptionValues options_for_run(const OptionValues& options, const std::vector<OptionInfo>& known, std::uint64_t seed,
                             double time_limit);

}  // namespace polyplan
