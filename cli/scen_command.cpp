// polyplan scen MAP.map SCEN.scen [--reference REF.csv] [--json -] [--threads N]: every query of a
// MovingAI scenario file, answered from one preprocessing (roadmaps/euclidean_shortest_paths.hpp)
// by N threads, compared with reference lengths.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/registry/scenario_answers.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace polyplan::cli {
namespace {

struct ScenOptions {
  std::string map;
  std::string scenarios;
  std::string reference;
  std::string json;
  std::unique_ptr<CommandOptions<ScenarioBudget>> budget;
};

int run_scen(const ScenOptions& options) {
  // Every input is read (and any error reported, alone on stderr) before the long work starts.
  ScenarioBudget budget = options.budget->parse();
  const GridMap map = read_movingai_map(options.map);
  const auto scenarios = read_scenarios(options.scenarios);
  check_scenarios_match(scenarios, map.width, map.height, map.source, options.scenarios);
  std::optional<std::vector<std::optional<double>>> reference;
  if (!options.reference.empty()) reference = read_reference_lengths(options.reference, scenarios.size());
  std::fprintf(stderr, "building the corner graph and its distance table or hub labels for %s (%dx%d)...\n",
               options.map.c_str(), map.width, map.height);
  Progress progress("queries");
  budget.progress = [&](std::size_t done) { progress.update(done, scenarios.size()); };
  budget.warn = [](const std::string& warning) { std::fprintf(stderr, "warning: %s\n", warning.c_str()); };
  const nlohmann::json answered = answer_scenarios(map, scenarios, reference, budget);
  const nlohmann::json& queries = answered["queries"];
  const nlohmann::json& summary = answered["summary"];
  if (!options.json.empty()) write_json(answered, options.json);
  if (options.json != "-") {
    std::printf("%8s %6s %14s %14s %10s\n", "index", "found", "length", "reference", "us");
    for (const auto& item : queries)
      std::printf("%8zu %6s %14.6f %14s %10.1f%s\n", item["index"].get<std::size_t>(),
                  item["found"].get<bool>() ? "yes" : "no",
                  item["found"].get<bool>() ? item["length"].get<double>() : -1.0,
                  item.contains("reference") ? std::to_string(item["reference"].get<double>()).c_str() : "-",
                  item["us"].get<double>(), item.contains("mismatch") ? "  MISMATCH" : "");
    std::cout << "summary: " << summary.dump() << '\n';
  }
  return ok;
}

}  // namespace

void add_scen_command(CLI::App& app, Action& run) {
  auto options = std::make_shared<ScenOptions>();
  CLI::App* command = app.add_subcommand("scen", "Answer a MovingAI scenario file with Euclidean shortest paths");
  command->add_option("map", options->map, "MovingAI map (.map)")->required();
  command->add_option("scenarios", options->scenarios, "MovingAI scenarios (.scen)")->required();
  command->add_option("--reference", options->reference, "Reference lengths (index,length CSV) to compare with");
  command->add_option("--json", options->json, "Write the results as JSON to this file ('-' for standard output)");
  options->budget = std::make_unique<CommandOptions<ScenarioBudget>>(*command, scenario_budget_table());
  command->callback([options, &run] { run = [options] { return run_scen(*options); }; });
}

}  // namespace polyplan::cli
