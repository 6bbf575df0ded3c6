#pragma once
// A MovingAI scenario answered with Euclidean shortest paths (`polyplan scen`): one preprocessing
// of the map (roadmaps/euclidean_shortest_paths.hpp), every query answered by N threads, compared
// with reference lengths where given, as the JSON the program prints:
//
//   {"queries": [{"index", "found", "length" (null), "us", "reference"?, "mismatch"?}, ...],
//    "summary": {"queries", "threads", "mean_us", "median_us", "batch_seconds", "preprocess_seconds",
//                "index_mb", "peak_memory_mb", "distance_table", "hub_labels", "label_entries",
//                "roadmap_vertices", "roadmap_edges", "mismatches"?, "max_difference"?}}
//
// The program and Python's polyplan.scen call this one function.
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace polyplan {

struct ScenarioBudget {
  unsigned threads = 0;                            // 0: one per core
  std::size_t table_mb = 1024;                     // the distance table's and hub labels' largest size
  std::function<void(std::size_t done)> progress;  // after each query, from the thread that answered it
  std::function<void(const std::string&)> warn;    // a remark for people (threads that could not start)
};

// --threads and --table-mb of the program, threads= and table_mb= of Python.
OptionTable<ScenarioBudget> scenario_budget_table();

// `reference`: none, or one optional length per query (a negative length: the reference finds no path);
// a length that differs by more than 1e-9 relative is a mismatch.
nlohmann::json answer_scenarios(const GridMap& map, const std::vector<ScenarioQuery>& queries,
                                const std::optional<std::vector<std::optional<double>>>& reference,
                                const ScenarioBudget& budget);

}  // namespace polyplan
