// polyplan.scen and polyplan.grid: a MovingAI scenario answered with Euclidean shortest paths
// (polyplan scen: the map as a file or an occupancy grid, the queries as a .scen file or an (N, 4)
// array) or on the map's 8-connected grid (polyplan grid, against the file's optimal lengths), as
// the dicts the program prints with --json -, with the lengths as numpy arrays beside them.
#include "exact_values.hpp"
#include "keyword_options.hpp"
#include "occupancy_grid.hpp"
#include "plans.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/input_limits.hpp>
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
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(given);
  } catch (const py::error_already_set& e) {  // ragged lists, objects numpy cannot read
    throw InputError("scen: scenarios: expected a .scen file's path or an (N, 4) integer array, got " +
                     type_name(given) + " that numpy cannot read as an array (" + e.what() + ")");
  }
  const char kind = a.ndim() == 2 ? a.dtype().kind() : '?';
  if ((a.ndim() != 2 || a.shape(1) != 4) || (kind != 'i' && kind != 'u'))
    throw InputError(
        "scen: scenarios: expected a .scen file's path or an (N, 4) integer array of (start_x, start_y, "
        "goal_x, goal_y), got " +
        type_name(given) + " of shape " + std::string(py::str(a.attr("shape"))) + " and dtype " +
        std::string(py::str(a.dtype())));
  if (static_cast<std::size_t>(a.shape(0)) > limits::scenario_queries)
    throw InputError("scen: scenarios: " + std::to_string(a.shape(0)) + " queries, more than the supported " +
                     std::to_string(limits::scenario_queries));
  // Each coordinate within the map (x to its width, y to its height), checked in the array's own
  // type, before a conversion could wrap a huge value round into range.
  const py::module_ np = py::module_::import("numpy");
  const py::object bounds = np.attr("array")(py::make_tuple(map.width, map.height, map.width, map.height));
  const py::object outside =
      np.attr("argwhere")(np.attr("logical_or")(np.attr("less")(a, 0), np.attr("greater")(a, bounds)));
  if (py::len(outside) > 0) {
    const py::object at = outside[py::int_(0)];
    throw InputError("scen: scenarios[" + std::string(py::str(at[py::int_(0)])) +
                     "]: " + std::string(py::str(a[py::make_tuple(at[py::int_(0)], at[py::int_(1)])])) +
                     " is outside the " + std::to_string(map.width) + " x " + std::to_string(map.height) + " map");
  }
  const py::array_t<std::int64_t> rows = a.attr("astype")("int64");
  const auto v = rows.unchecked<2>();
  std::vector<ScenarioQuery> queries;
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    queries.push_back({0, map.width, map.height, int(v(i, 0)), int(v(i, 1)), int(v(i, 2)), int(v(i, 3)), 0.0, {}, 0});
  return queries;
}

// A reference CSV (index,length), or one length per query (None or NaN: none; negative: no path).
std::optional<std::vector<std::optional<double>>> reference_of(const py::object& given, std::size_t queries) {
  if (given.is_none()) return std::nullopt;
  if (is_path(given)) return read_reference_lengths(path_of(given, "scen: reference"), queries);
  const bool sequence = (py::isinstance<py::sequence>(given) || py::isinstance<py::array>(given)) &&
                        !py::isinstance<py::bytes>(given) && !PyByteArray_Check(given.ptr());
  if (!sequence || (py::isinstance<py::array>(given) && py::reinterpret_borrow<py::array>(given).ndim() != 1))
    throw InputError(
        "scen: reference: expected a CSV file's path or one length per query (a list or a 1-d array), got " +
        type_name(given));
  if (py::len(given) != queries)
    throw InputError("scen: reference: " + std::to_string(py::len(given)) + " lengths for " + std::to_string(queries) +
                     " queries");
  std::vector<std::optional<double>> lengths;
  for (const py::handle item : py::iter(given)) {
    const bool nan = PyFloat_Check(item.ptr()) && std::isnan(PyFloat_AsDouble(item.ptr()));  // numpy's float64 too
    if (item.is_none() || nan) lengths.emplace_back();
    else lengths.emplace_back(finite_number(item, "scen: reference[" + std::to_string(lengths.size()) + "]"));
  }
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
scenarios: the .scen file's path. Options: search ("astar", "dijkstra", "wastar"), weight and
reopen (for wastar). Returns the program's dict ("queries", "summary") with "length" (float64, NaN where no
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
