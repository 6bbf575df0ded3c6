#pragma once
// An experiment's runs as JSON (results.json) and CSV (results.csv), one record per run:
//
//   {"experiment": {"name", "file", "time_limit", "seeds", "cost_times", "problems": [...], "planners": [...]},
//    "host", "started_at", "threads", "total_seconds", "complete": true, "missing_runs": 0, "log": "results.log",
//    "runs": [{"problem": "office", "planner": "rrt-bias0.2", "log_planner": "rrt-bias0.2@office",
//              "seed": 1, "solved": true, "status": "solved", "time": 0.0123, "setup_time": 0.001,
//              "length": 57.2, "first_solution_time": 0.011, "improvements": [[0.011, 60.1], ...],
//              "cost_at": [null, 57.2, ...], "why_not": "...", "facts": {...}}, ...],
//    "summary": [{"problem", "planner", "log_planner", "runs", "solved", "success_rate", "time": {...}, "length":
//    {...}}, ...]}
//
// "time" is the run's property "time" in results.log (the same double); "log_planner" is the
// planner the log files the run under; "cost_at" is the best length at each of cost_times (null
// before the first solution). The CSV has the same runs, one row each, with the numeric facts
// as columns (empty where a run has none). An interrupted experiment has runs missing: "complete"
// is false and "missing_runs" counts them.
#include <polyplan/experiment/experiment.hpp>

#include <nlohmann/json_fwd.hpp>

#include <iosfwd>

namespace polyplan {

// The "experiment" part alone: what was asked.
nlohmann::json experiment_json(const Experiment& experiment);

nlohmann::json experiment_results_json(const Experiment& experiment, const ExperimentResults& results);

void write_experiment_results_csv(std::ostream& out, const Experiment& experiment, const ExperimentResults& results);

}  // namespace polyplan
