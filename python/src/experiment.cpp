// polyplan.Experiment's compiled half: an experiment read from a file or from text (the reader of
// `polyplan benchmark`), run on threads (its runner), its results as results.json's dict and
// written as the program writes them; and for a cluster (python/polyplan/cluster.py), its cells
// one by one, each run giving a record (experiment/experiment_run_record.hpp), and results made
// from the records gathered. python/polyplan/experiment.py is the Python half.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/draw/experiment_outputs.hpp>
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_problem.hpp>
#include <polyplan/experiment/experiment_results.hpp>
#include <polyplan/experiment/experiment_run_record.hpp>
#include <polyplan/experiment/experiment_runner.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/problem.hpp>

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <memory>
#include <thread>
#include <tuple>

namespace py = pybind11;

namespace polyplan::python {
namespace {

// An experiment run: what was asked and what its runs gave, for the writers.
struct ExperimentOutcome {
  Experiment experiment;
  ExperimentResults results;
};

// `progress(done, total)` called from the runner's threads, one call at a time, with the GIL taken
// for it; an exception it raises is reported as unraisable rather than lost in a thread.
ExperimentProgress python_progress(const py::object& progress) {
  if (progress.is_none()) return {};
  return [progress](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire held;
    try {
      progress(done, total);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("polyplan.Experiment.run: progress");
    }
  };
}

ExperimentOutcome run(const Experiment& given, unsigned threads, std::size_t seeds, double time_limit,
                      const py::object& progress) {
  ExperimentOutcome out{given, {}};
  scale_experiment(out.experiment, seeds, time_limit);
  const unsigned used = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  const ExperimentProgress report = python_progress(progress);
  py::gil_scoped_release released;
  out.results = run_experiment(out.experiment, used, report);
  return out;
}

Experiment scaled(const Experiment& given, std::size_t seeds, double time_limit) {
  Experiment out = given;
  scale_experiment(out, seeds, time_limit);
  return out;
}

// One cell as a task needs it: (problem, file, query, planner entry, planner, options, seed,
// time limit), in cell order.
using CellTask =
    std::tuple<std::string, std::string, std::string, std::string, std::string, OptionValues, std::uint64_t, double>;
std::vector<CellTask> cell_tasks(const Experiment& e) {
  std::vector<CellTask> cells;
  for (const ExperimentProblem& p : e.problems)
    for (const ExperimentPlanner& entry : e.planners)
      for (std::uint64_t seed : e.seeds)
        cells.emplace_back(p.name, p.file, p.query, entry.name, entry.planner, entry.options, seed, e.time_limit);
  return cells;
}

// A problem parsed from its text, kept for the thread's next runs on it (a worker runs many cells
// of one problem); a thread's own, as the runner's threads keep theirs. A few problems at most.
const Problem& problem_of(const std::string& text, const std::string& source) {
  thread_local std::map<std::pair<std::string, std::string>, std::unique_ptr<Problem>> kept;
  const auto key = std::make_pair(source, text);
  auto found = kept.find(key);
  if (found == kept.end()) {
    if (kept.size() >= 8) kept.clear();
    std::vector<std::string> warnings;  // unknown fields are not the experiment's concern
    found = kept.emplace(key, std::make_unique<Problem>(Problem::parse(text, source, &warnings))).first;
    found->second->prepare();
  }
  return *found->second;
}

// A cell's run as its record's JSON text; a problem that cannot be read gives a failed run.
std::string run_cell_record(const std::string& text, const std::string& source, const std::string& problem,
                            const std::string& query, const std::string& entry_name, const std::string& planner,
                            const OptionValues& options, std::uint64_t seed, double time_limit) {
  py::gil_scoped_release released;
  const ExperimentPlanner entry{entry_name, planner, options, false};
  ExperimentRun run;
  try {
    run = run_cell(problem_of(text, source), entry, query, seed, time_limit);
  } catch (const std::exception& e) {
    run.seed = seed;
    mark_failed(run, std::string("the run failed: ") + e.what());
  }
  return run_record(run, problem, entry_name).dump();
}

std::string failed_record(const std::string& problem, const std::string& entry, std::uint64_t seed,
                          const std::string& why) {
  ExperimentRun run;
  run.seed = seed;
  mark_failed(run, why);
  return run_record(run, problem, entry).dump();
}

// Results from records (text, where it came from for messages), in cell order.
ExperimentOutcome outcome_of(const Experiment& e, const std::vector<std::pair<std::string, std::string>>& records,
                             double total_seconds, unsigned threads, const std::string& started_at,
                             const std::string& host) {
  std::vector<ExperimentRun> runs;
  for (const auto& [text, where] : records) {
    const nlohmann::json record = nlohmann::json::parse(text, nullptr, false);
    if (record.is_discarded()) throw InputError(where + ": not JSON");
    runs.push_back(run_from_record(e, record, where));
  }
  ExperimentResults results{runs_in_cell_order(e, std::move(runs)), total_seconds, threads, started_at, host};
  return {e, std::move(results)};
}

}  // namespace

void bind_experiment(py::module_& m) {
  py::class_<Experiment>(m, "_ExperimentSpec", "An experiment as read (polyplan.Experiment holds one).")
      .def_property_readonly("name", [](const Experiment& e) { return e.name; })
      .def_property_readonly("runs", [](const Experiment& e) { return e.cells(); })
      .def_property_readonly("seeds", [](const Experiment& e) { return e.seeds; })
      .def_property_readonly("time_limit", [](const Experiment& e) { return e.time_limit; })
      .def_property_readonly("problems",
                             [](const Experiment& e) {
                               std::vector<std::string> names;
                               for (const auto& p : e.problems) names.push_back(p.name);
                               return names;
                             })
      .def_property_readonly("planners",
                             [](const Experiment& e) {
                               std::vector<std::string> names;
                               for (const auto& p : e.planners) names.push_back(p.name);
                               return names;
                             })
      .def("json", [](const Experiment& e) { return from_json(experiment_json(e)); })
      .def("scaled", &scaled, py::arg("seeds"), py::arg("time_limit"))
      .def("cells", &cell_tasks);
  m.def("_read_experiment",
        [](const py::object& path) { return read_experiment(path_of(path, "Experiment.from_file")); });
  m.def("_parse_experiment", &parse_experiment);

  py::class_<ExperimentOutcome>(m, "_ExperimentOutcome", "An experiment's runs (polyplan.Results holds one).")
      .def("json",
           [](const ExperimentOutcome& o) { return from_json(experiment_results_json(o.experiment, o.results)); })
      .def("write", [](const ExperimentOutcome& o, const py::object& folder) {
        const std::string path = path_of(folder, "Results.write: folder");
        py::gil_scoped_release released;
        return write_experiment_outputs(path, o.experiment, o.results);
      });
  m.def("_run_cell", &run_cell_record);
  m.def("_failed_record", &failed_record);
  m.def("_file_name_part", &file_name_part);
  m.def("_experiment_outcome", &outcome_of);
  m.def("_run_experiment", &run, py::arg("experiment"), py::arg("threads"), py::arg("seeds"), py::arg("time_limit"),
        py::arg("progress"));
}

}  // namespace polyplan::python
