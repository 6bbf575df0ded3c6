#pragma once
// A plan as Python holds it, and the bindings of the module's parts.
#include "problems.hpp"

#include <polyplan/plan/planner_options.hpp>
#include <polyplan/registry/report.hpp>

#include <pybind11/pybind11.h>
#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::python {

// A query's answer as Python holds it: the front door's report and the World or Arm it was
// planned in (kept alive for pictures).
struct PlanResult {
  Report report;
  pybind11::object problem;
  // The options it was planned with that differ from the planner's defaults, as the registry
  // names them (goal-bias), for labels.
  OptionValues options;

  // What the query recorded, converted once for the attributes that read it (graph, expanded,
  // cells, decomposition).
  const Recording& recorded() const {
    if (!recording) recording = report.recording();
    return *recording;
  }
  mutable std::optional<Recording> recording;
};

void bind_plans(pybind11::module_& m);
void bind_planners(pybind11::module_& m);
void bind_replan(pybind11::module_& m);
void bind_potential(pybind11::module_& m);
void bind_search(pybind11::module_& m);
void bind_steer(pybind11::module_& m);
void bind_space(pybind11::module_& m);
void bind_ik(pybind11::module_& m);
void bind_experiment(pybind11::module_& m);
void bind_scen(pybind11::module_& m);
void bind_check(pybind11::module_& m);

// A JSON value as Python's json.loads reads it (dicts, lists, numbers, strings).
pybind11::object from_json(const nlohmann::json& value);

}  // namespace polyplan::python
