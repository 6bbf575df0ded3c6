#pragma once
// A MovingAI scenario answered on the map's 8-connected grid (`polyplan grid`): octile lengths, no
// corner cutting, each query searched with A*, Dijkstra or weighted A* and compared with the
// file's optimal length, as the JSON the program prints:
//
//   {"queries": [{"index", "found", "length", "expected", "expanded", "us", "mismatch", "bound_ok"?}, ...],
//    "summary": {"queries", "mismatches", "mean_us", "mean_expanded", "search", "preprocess_seconds",
//                "weight"?, "reopen"?, "bound_violations"?, "note"?}}
//
// The program and Python's polyplan.grid call this one function.
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/plan/planner_options.hpp>
#include <polyplan/search/grid_conventions.hpp>
#include <polyplan/search/search_result.hpp>

#include <nlohmann/json_fwd.hpp>

#include <functional>

namespace polyplan {

struct GridScenarioSearch {
  SearchOptions search;
  std::function<void(std::size_t done, std::size_t total)> progress;  // after each query
  GridConventions grid{};  // the benchmark's by default; others make the file's lengths moot
};

// --search and --weight of the program, search= and weight= of Python: the searches whose lengths
// the file's optimal ones can judge (astar, dijkstra) and weighted A* with its bound; and the grid
// conventions (--connectivity, --corner-cutting, --diagonal-cost), under which the file's lengths
// judge only the benchmark's grid (the summary says which grid was searched).
OptionTable<GridScenarioSearch> grid_scenario_table();

// InputError for queries that do not fit the map (movingai_grid.hpp's check_scenarios_fit).
nlohmann::json answer_grid_scenarios(const GridMap& map, const std::vector<ScenarioQuery>& queries,
                                     const std::string& scenario_file, const GridScenarioSearch& options);

}  // namespace polyplan
