// polyplan.scen and polyplan.grid: a MovingAI scenario answered with Euclidean shortest paths
// (polyplan scen: the map as a file or an occupancy grid, the queries as a .scen file or an (N, 4)
// array) or on the map's 8-connected grid (polyplan grid, against the file's optimal lengths), as
// the dicts the program prints with --json -, with the lengths as numpy arrays beside them.
#include "exact_values.hpp"
#include "keyword_options.hpp"
#include "occupancy_grid.hpp"
#include "plans.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/grid_scenario_answers.hpp>
#include <polyplan/registry/scenario_answers.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace py = pybind11;

namespace polyplan::python {
namespace {

bool is_path(const py::handle& value) { return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"); }

// A .scen file (checked against the map), or rows (start_x, start_y, goal_x, goal_y) of integers.
std::vector<ScenarioQuery> queries_of(const py::object& given, const GridMap& map) {
  if (is_path(given)) {
    const std::string path = path_of(given, "scen: scenarios");
    std::vector<ScenarioQuery> queries = read_scenarios(path);
    check_scenarios_match(queries, map.width, map.height, map.source, path);
    return queries;
  }
  const py::array a = py::module_::import("numpy").attr("asarray")(given);
  const char kind = a.ndim() == 2 ? a.dtype().kind() : '?';
  if ((a.ndim() != 2 || a.shape(1) != 4) || (kind != 'i' && kind != 'u'))
    throw InputError(
        "scen: scenarios: expected a .scen file's path or an (N, 4) integer array of (start_x, start_y, "
        "goal_x, goal_y), got " +
        type_name(given) + " of shape " + std::string(py::str(a.attr("shape"))) + " and dtype " +
        std::string(py::str(a.dtype())));
  const py::array_t<std::int64_t> rows = a.attr("astype")("int64");
  const auto v = rows.unchecked<2>();
  std::vector<ScenarioQuery> queries;
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    for (py::ssize_t k = 0; k < 4; ++k)
      if (v(i, k) < 0 || v(i, k) > (k % 2 ? map.height : map.width))
        throw InputError("scen: scenarios[" + std::to_string(i) + "]: " + std::to_string(v(i, k)) + " is outside the " +
                         std::to_string(map.width) + " x " + std::to_string(map.height) + " map");
    queries.push_back({0, map.width, map.height, int(v(i, 0)), int(v(i, 1)), int(v(i, 2)), int(v(i, 3))});
  }
  return queries;
}

// A reference CSV (index,length), or one length per query (None or NaN: none; negative: no path).
std::optional<std::vector<std::optional<double>>> reference_of(const py::object& given, std::size_t queries) {
  if (given.is_none()) return std::nullopt;
  if (is_path(given)) return read_reference_lengths(path_of(given, "scen: reference"), queries);
  std::vector<std::optional<double>> lengths;
  const py::object real = py::module_::import("numbers").attr("Real");
  for (const py::handle item : py::iter(given)) {
    const bool none =
        item.is_none() ||
        (py::isinstance(item, real) && std::isnan(py::float_(py::reinterpret_borrow<py::object>(item)).cast<double>()));
    lengths.push_back(none ? std::nullopt : std::optional<double>(finite_number(item, "scen: reference")));
  }
  if (lengths.size() != queries)
    throw InputError("scen: reference: " + std::to_string(lengths.size()) + " lengths for " + std::to_string(queries) +
                     " queries");
  return lengths;
}

// The program's JSON as Python's dict, with the queries' lengths as a float64 array (NaN where
// none) and their `found` as bools beside it.
py::dict with_length_arrays(const nlohmann::json& answered) {
  py::dict out = from_json(answered);
  const nlohmann::json& queries = answered["queries"];
  py::array_t<double> length(static_cast<py::ssize_t>(queries.size()));
  py::array_t<bool> found(static_cast<py::ssize_t>(queries.size()));
  for (std::size_t i = 0; i < queries.size(); ++i) {
    found.mutable_at(i) = queries[i]["found"].get<bool>();
    length.mutable_at(i) =
        queries[i]["found"].get<bool>() ? queries[i]["length"].get<double>() : std::numeric_limits<double>::quiet_NaN();
  }
  out["length"] = length;
  out["found"] = found;
  return out;
}

py::dict grid(const py::object& map_given, const py::object& scenarios, const py::kwargs& options) {
  const GridScenarioSearch search = keyword_command_options(grid_scenario_table(), "grid", options);
  const GridMap map = grid_map_of(map_given, "grid: map");
  if (!is_path(scenarios))
    throw InputError(
        "grid: scenarios: expected a .scen file's path (its optimal lengths are what the answers are "
        "compared with), got " +
        type_name(scenarios));
  const std::string file = path_of(scenarios, "grid: scenarios");
  const std::vector<ScenarioQuery> queries = read_scenarios(file);
  const nlohmann::json answered = [&] {
    py::gil_scoped_release released;
    return answer_grid_scenarios(map, queries, file, search);
  }();
  return with_length_arrays(answered);
}

py::dict scen(const py::object& map_given, const py::object& scenarios, const py::object& reference,
              const py::kwargs& options) {
  const ScenarioBudget budget = keyword_command_options(scenario_budget_table(), "scen", options);
  const GridMap map = grid_map_of(map_given, "scen: map");
  const std::vector<ScenarioQuery> queries = queries_of(scenarios, map);
  const auto lengths = reference_of(reference, queries.size());
  const nlohmann::json answered = [&] {
    py::gil_scoped_release released;
    return answer_scenarios(map, queries, lengths, budget);
  }();
  return with_length_arrays(answered);
}

}  // namespace

void bind_scen(py::module_& m) {
  m.def("grid", &grid, py::arg("map"), py::arg("scenarios"),
        R"(Every query of a MovingAI scenario file answered on the map's 8-connected grid (octile lengths, no
corner cutting) and compared with the file's optimal lengths, as `polyplan grid` does. map: a .map
file's path or an occupancy grid [row, column], True where blocked (of the file's size);
scenarios: the .scen file's path. Options: search ("astar", "dijkstra", "wastar"), weight (for
wastar). Returns the program's dict ("queries", "summary") with "length" (float64, NaN where no
path) and "found" (bool) arrays.)");
  m.def("scen", &scen, py::arg("map"), py::arg("scenarios"), py::arg("reference") = py::none(),
        R"(Every query of a MovingAI scenario answered with its Euclidean shortest path (any-angle, among
the map's blocked cells; the corners of cells are the vertices), from one preprocessing of the
map, as `polyplan scen` does. map: a .map file's path or an occupancy grid [row, column], True
where blocked; scenarios: a .scen file's path or an (N, 4) integer array (start_x, start_y,
goal_x, goal_y); reference: a CSV of index,length or one length per query (None: none) to compare
with. Options: threads (0: one per core), table_mb (1024). Returns the program's dict ("queries",
"summary") with "length" (float64, NaN where no path) and "found" (bool) arrays.)");
}

}  // namespace polyplan::python
