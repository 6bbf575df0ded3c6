#pragma once
// One run of an experiment as a JSON record that reads back to the same run, bit for bit: what a
// cluster's worker sends back (python/polyplan/cluster.py) and what a results folder's runs.jsonl
// keeps, one line per run, so that an interrupted experiment can resume with its missing runs only.
//
//   {"problem": "office", "planner": "rrt-bias0.2", "seed": 1, "status": "solved", "solved": true,
//    "why_not": "", "seconds": 0.0123, "setup_seconds": 0.001, "length": 57.2,
//    "improvements": [[0.011, 60.1], [0.0123, 57.2]],
//    "facts": [["roadmap.vertices", "count", 412], ["stopped_by", "word", "time"], ...]}
//
// Unlike results.json's records (experiment_results.hpp), nothing is derived and the facts keep
// their order and their types: a measure of 3.0 stays a measure, an infinite one is "inf".
#include <polyplan/experiment/experiment.hpp>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace polyplan {

// `run` as a record, its cell named by its problem's and planner entry's names.
nlohmann::json run_record(const ExperimentRun& run, const std::string& problem, const std::string& planner);

// The run a record holds, its cell found by name in `experiment`. InputError "<where>: <field>:
// <what is wrong>" for a record that is not one, or that names a problem, planner entry or seed
// the experiment does not have.
ExperimentRun run_from_record(const Experiment& experiment, const nlohmann::json& record, const std::string& where);

// The runs in cell order (problem, planner entry, seed), the first of two for one cell kept:
// results for the writers, with the cells that have no run missing (an interrupted experiment).
std::vector<ExperimentRun> runs_in_cell_order(const Experiment& experiment, std::vector<ExperimentRun> runs);

}  // namespace polyplan
