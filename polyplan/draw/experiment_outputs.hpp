#pragma once
// Every file an experiment's results are written to (docs/benchmark.md), in one folder:
// results.log (OMPL's benchmark log), results.json, results.csv, tables.md, and per problem the
// pictures PROBLEM-success.svg, PROBLEM-cost.svg (anytime planners), PROBLEM-time.svg and
// PROBLEM-length.svg. `polyplan benchmark` and Python's Results.write write them alike.
#include <polyplan/experiment/experiment.hpp>

#include <string>
#include <vector>

namespace polyplan {

// Makes `folder` when it is missing; returns the files written, in the order above. InputError
// naming the folder or the file that cannot be written.
std::vector<std::string> write_experiment_outputs(const std::string& folder, const Experiment& experiment,
                                                  const ExperimentResults& results);

// A problem's name as part of a file name: letters, digits, '.', '-' and '_' kept, others '_'.
std::string file_name_part(const std::string& name);

}  // namespace polyplan
