// polyplan.Experiment's compiled half: an experiment read from a file or from text (the reader of
// `polyplan benchmark`), run on threads (its runner), its results as results.json's dict and
// written as the program writes them. python/polyplan/experiment.py is the Python half.
#include "exact_values.hpp"
#include "plans.hpp"

#include <polyplan/draw/experiment_outputs.hpp>
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_results.hpp>
#include <polyplan/experiment/experiment_runner.hpp>

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <thread>

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
      .def_property_readonly("planners", [](const Experiment& e) {
        std::vector<std::string> names;
        for (const auto& p : e.planners) names.push_back(p.name);
        return names;
      });
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
  m.def("_run_experiment", &run, py::arg("experiment"), py::arg("threads"), py::arg("seeds"), py::arg("time_limit"),
        py::arg("progress"));
}

}  // namespace polyplan::python
