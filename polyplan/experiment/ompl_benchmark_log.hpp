#pragma once
// An experiment's results in OMPL's benchmark log format: the text ompl::tools::Benchmark's
// saveResultsToStream writes and OMPL's scripts/ompl_benchmark_statistics.py reads into the SQLite
// database that Planner Arena (plannerarena.org) shows. The script reads one experiment per file,
// so the whole experiment is one log:
//
//   polyplan version 0.1.0                       (the script's "version" column: "polyplan 0.1.0")
//   Experiment NAME
//   0 experiment properties
//   Running on HOST
//   Starting at 2026-12-05T19:55:02
//   <<<|
//   the experiment in words: file, problems, planner entries, seeds, limits
//   |>>>
//   1 is the random seed                         (the first seed; each run's is its "seed" property)
//   10 seconds per run
//   0 MB per run
//   3 runs per planner                           (one per seed)
//   42.5 seconds spent to collect the data
//   2 enum types
//   status|Unknown status|Invalid start|...|Abort          (OMPL 1.5's PlannerStatus, in its order)
//   polyplan_status|solved|no_path|not_found|limit|invalid_query|local_minimum
//   4 planners                                   (one per problem × planner entry: ENTRY@PROBLEM)
//   rrt-bias0.2@office
//   5 common properties                          (the entry's options, planner, problem, file, query)
//   goal-bias = 0.2 ...
//   N properties for each run                    ("time REAL", "solved BOOLEAN", "status ENUM", ... and
//   ...                                           every numeric fact, "roadmap.vertices" as "roadmap vertices INTEGER")
//   3 runs
//   0.0123; 1; 6; ...;                           (values in the properties' order, "; " after each; empty when missing)
//   2 progress properties for each run           (anytime planners only: the best cost at each cost time)
//   best cost REAL
//   time REAL
//   3 runs
//   inf,0.5,;57.2,1,;...;
//   .
//
// One planner per (problem, entry), not one per entry with the problem as a run property: every
// statistic of the log (Planner Arena's box plots, its cost-over-time curves) is over one
// planner's runs, and runs on different problems do not mix (their lengths are not comparable).
// Numbers are written with 17 significant digits, which SQLite reads back as the same double (it
// misreads some shorter texts by an ulp), so that the database holds exactly the times and lengths
// of results.json.
#include <polyplan/experiment/experiment.hpp>

#include <iosfwd>
#include <string>

namespace polyplan {

// "ENTRY@PROBLEM", whitespace made '_' (the script reads a planner's name as one line).
std::string ompl_planner_name(const Experiment& experiment, std::size_t problem, std::size_t planner);

// A property's or fact's name as the script makes it a column: "roadmap.vertices" and
// "roadmap vertices" are both "roadmap_vertices"; SQL's reserved words get "_value" added.
std::string ompl_column_name(const std::string& name);

void write_ompl_benchmark_log(std::ostream& out, const Experiment& experiment, const ExperimentResults& results);

}  // namespace polyplan
