#include <polyplan/registry/grid_scenario_answers.hpp>

#include <polyplan/grids/movingai_grid.hpp>
#include <polyplan/plan/grid_options.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/registry/replan_json.hpp>

#include <nlohmann/json.hpp>

namespace polyplan {
namespace {

using nlohmann::json;

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

json length_or_null(bool found, double length) { return found ? json(length) : json(nullptr); }

}  // namespace

OptionTable<GridScenarioSearch> grid_scenario_table() {
  OptionTable<GridScenarioSearch> table;
  add_search_options(table, &GridScenarioSearch::search, "search",
                     {{"astar", Search::astar}, {"dijkstra", Search::dijkstra}, {"wastar", Search::wastar}});
  return add_grid_conventions(
      table, [](auto& o) -> auto& { return o.grid; });
}

json answer_grid_scenarios(const GridMap& map, const std::vector<ScenarioQuery>& scenarios,
                           const std::string& scenario_file, const GridScenarioSearch& options) {
  const SearchOptions& search = options.search;
  const Stopwatch preprocessing;
  check_scenarios_fit(map, scenarios, scenario_file);
  MovingAiGridSearch grid(map, options.grid);
  const double preprocess = preprocessing.seconds();
  const bool weighted = search.algorithm == Search::wastar;

  json queries = json::array();
  std::vector<double> micros, expanded;
  std::size_t mismatches = 0, bound_violations = 0;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const SearchResult<GridCell> r = grid.search(scenarios[i], search);
    const OctileExpectation expected = octile_expectation(scenarios[i]);
    const bool mismatch = !matches(expected, r.found, r.cost);
    mismatches += mismatch;
    micros.push_back(r.seconds * 1e6);
    expanded.push_back(static_cast<double>(r.expanded));
    json item{{"index", i},
              {"found", r.found},
              {"length", length_or_null(r.found, r.cost)},
              {"expected", length_or_null(expected.found, expected.length)},
              {"expanded", r.expanded},
              {"us", micros.back()},
              {"mismatch", mismatch}};
    if (weighted) {
      // The file's length is the optimum rounded: the optimum is at most length + tolerance.
      const bool bound_ok = r.found == expected.found &&
                            (!r.found || r.cost <= search.weight * (expected.length + expected.tolerance) + 1e-9);
      bound_violations += !bound_ok;
      item["bound_ok"] = bound_ok;
    }
    queries.push_back(std::move(item));
    if (options.progress) options.progress(i + 1, scenarios.size());
  }

  json summary{{"queries", scenarios.size()},
               {"mismatches", mismatches},
               {"mean_us", mean(micros)},
               {"mean_expanded", mean(expanded)},
               {"search", std::string(to_string(search.algorithm))},
               {"preprocess_seconds", preprocess}};
  if (options.grid != GridConventions{}) {
    summary["grid"] = grid_conventions_json(options.grid);
    summary["grid_note"] =
        "the scenario file's lengths are the benchmark grid's (8-connected, no corner cutting, sqrt2)";
  }
  if (weighted) {
    summary["weight"] = search.weight;
    summary["reopen"] = search.reopen;
    summary["bound_violations"] = bound_violations;
    summary["note"] =
        "weighted A* is not expected to match the optimal lengths; bound_violations counts costs above "
        "weight x the file's length";
  }
  return {{"queries", queries}, {"summary", summary}};
}

}  // namespace polyplan
