// polyplan grid MAP.map SCEN.scen [--search astar|dijkstra|wastar] [--weight W] [--json -]: every
// query of a MovingAI scenario file answered on the 8-connected grid (the benchmark's own octile
// problem, no corner cutting), compared with the file's optimal lengths.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/registry/grid_scenario_answers.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace polyplan::cli {
namespace {

struct GridOptions {
  std::string map;
  std::string scenarios;
  std::string json;
  std::unique_ptr<CommandOptions<GridScenarioSearch>> search;  // --search, --weight
};

int run_grid(const GridOptions& options) {
  // Every input is read and checked (any error reported, alone on stderr) before the long work.
  GridScenarioSearch search = options.search->parse();
  const GridMap map = read_movingai_map(options.map);
  const auto scenarios = read_scenarios(options.scenarios);
  Progress progress("queries");
  search.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
  const nlohmann::json answered = answer_grid_scenarios(map, scenarios, options.scenarios, search);
  const nlohmann::json& queries = answered["queries"];
  const nlohmann::json& summary = answered["summary"];
  const bool weighted = search.search.algorithm == Search::wastar;
  if (!options.json.empty()) write_json(answered, options.json);
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
  options->search = std::make_unique<CommandOptions<GridScenarioSearch>>(*command, grid_scenario_table());
  command->add_option("--json", options->json, "Write the results as JSON to this file ('-' for standard output)");
  command->callback([options, &run] { run = [options] { return run_grid(*options); }; });
}

}  // namespace polyplan::cli
