// polyplan grid MAP.map SCEN.scen [--search astar|dijkstra|wastar] [--weight W] [--json -]: every
// query of a MovingAI scenario file answered on the 8-connected grid (the benchmark's own octile
// problem, no corner cutting), compared with the file's optimal lengths.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/grids/movingai_grid.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace polyplan::cli {
namespace {

// The search: only those whose lengths the file's optimal ones can judge, optimal ones and
// weighted A* with its bound.
struct GridSearch {
  SearchOptions search;
};
OptionTable<GridSearch> grid_search_table() {
  OptionTable<GridSearch> table;
  return add_search_options(table, &GridSearch::search, "search",
                            {{"astar", Search::astar}, {"dijkstra", Search::dijkstra}, {"wastar", Search::wastar}});
}

struct GridOptions {
  std::string map;
  std::string scenarios;
  std::string json;
  std::unique_ptr<CommandOptions<GridSearch>> search;  // --search, --weight
};

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

nlohmann::json length_or_null(bool found, double length) {
  return found ? nlohmann::json(length) : nlohmann::json(nullptr);
}

int run_grid(const GridOptions& options) {
  // Every input is read and checked (any error reported, alone on stderr) before the long work.
  const SearchOptions search = options.search->parse().search;
  const auto started = std::chrono::steady_clock::now();
  const GridMap map = read_movingai_map(options.map);
  const auto scenarios = read_scenarios(options.scenarios);
  check_scenarios_fit(map, scenarios, options.scenarios);
  MovingAiGridSearch grid(map);
  const double preprocess = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const bool weighted = search.algorithm == Search::wastar;

  nlohmann::json queries = nlohmann::json::array();
  std::vector<double> micros, expanded;
  std::size_t mismatches = 0, bound_violations = 0;
  Progress progress("queries");
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const SearchResult<GridCell> r = grid.search(scenarios[i], search);
    const OctileExpectation expected = octile_expectation(scenarios[i]);
    const bool mismatch = !matches(expected, r.found, r.cost);
    mismatches += mismatch;
    micros.push_back(r.seconds * 1e6);
    expanded.push_back(static_cast<double>(r.expanded));
    nlohmann::json item{{"index", i},
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
    progress.update(i + 1, scenarios.size());
  }

  nlohmann::json summary{{"queries", scenarios.size()},
                         {"mismatches", mismatches},
                         {"mean_us", mean(micros)},
                         {"mean_expanded", mean(expanded)},
                         {"search", std::string(to_string(search.algorithm))},
                         {"preprocess_seconds", preprocess}};
  if (weighted) {
    summary["weight"] = search.weight;
    summary["bound_violations"] = bound_violations;
    summary["note"] =
        "weighted A* is not expected to match the optimal lengths; bound_violations counts costs above "
        "weight x the file's length";
  }
  if (!options.json.empty()) write_json({{"queries", queries}, {"summary", summary}}, options.json);
  if (options.json != "-") {
    std::printf("%8s %6s %14s %14s %10s %10s\n", "index", "found", "length", "expected", "expanded", "us");
    for (const auto& item : queries) {
      const auto number = [](const nlohmann::json& v) {
        return v.is_null() ? std::string("-") : std::to_string(v.get<double>());
      };
      const char* flag = item["mismatch"].get<bool>()
                             ? (weighted ? (item["bound_ok"].get<bool>() ? "  differs" : "  OVER BOUND") : "  MISMATCH")
                             : "";
      std::printf("%8zu %6s %14s %14s %10zu %10.1f%s\n", item["index"].get<std::size_t>(),
                  item["found"].get<bool>() ? "yes" : "no", number(item["length"]).c_str(),
                  number(item["expected"]).c_str(), item["expanded"].get<std::size_t>(), item["us"].get<double>(),
                  flag);
    }
    std::cout << "summary: " << summary.dump() << '\n';
  }
  return ok;
}

}  // namespace

void add_grid_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<GridOptions>();
  CLI::App* command =
      app.add_subcommand("grid", "Answer a MovingAI scenario file on the 8-connected grid (octile lengths)");
  command->add_option("map", options->map, "MovingAI map (.map)")->required();
  command->add_option("scenarios", options->scenarios, "MovingAI scenarios (.scen)")->required();
  options->search = std::make_unique<CommandOptions<GridSearch>>(*command, grid_search_table());
  command->add_option("--json", options->json, "Write the results as JSON to this file ('-' for standard output)");
  command->callback([options, &run] { run = [options] { return run_grid(*options); }; });
}

}  // namespace polyplan::cli
