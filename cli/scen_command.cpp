// polyplan scen MAP.map SCEN.scen [--reference REF.csv] [--json -]: every query of a MovingAI
// scenario file, answered from one visibility graph, compared with reference lengths.
#include "cli/command.hpp"
#include "cli/progress.hpp"

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace polyplan::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct ScenOptions {
  std::string map;
  std::string scenarios;
  std::string reference;
  std::string json;
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int run_scen(const ScenOptions& options) {
  // Every input is read (and any error reported, alone on stderr) before the long work starts.
  const auto started = Clock::now();
  const GridMap map = read_movingai_map(options.map);
  const auto scenarios = read_scenarios(options.scenarios);
  check_scenarios_match(scenarios, map.width, map.height, map.source, options.scenarios);
  std::vector<std::optional<double>> reference;
  if (!options.reference.empty()) reference = read_reference_lengths(options.reference, scenarios.size());
  std::fprintf(stderr, "building the visibility graph of %s (%dx%d)...\n", options.map.c_str(), map.width, map.height);
  const CSpace cspace(world_from_grid(map));
  VisibilityGraph graph(cspace);
  const double preprocess = seconds_since(started);

  nlohmann::json queries = nlohmann::json::array();
  std::vector<double> micros;
  std::size_t mismatches = 0;
  double max_difference = 0;
  Progress progress("queries");
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const ScenarioQuery& q = scenarios[i];
    const ExactPoint start{q.start_x, q.start_y}, goal{q.goal_x, q.goal_y};
    const auto t = Clock::now();
    const PlanReport<ExactPoint> plan = graph.plan(Query{start, goal, "scenario " + std::to_string(i)});
    const double us = seconds_since(t) * 1e6;
    micros.push_back(us);
    nlohmann::json item{{"index", i}, {"found", plan.found}, {"length", plan.found ? nlohmann::json(plan.length) : nlohmann::json(nullptr)}, {"us", us}};
    if (i < reference.size() && reference[i]) {
      const double expected = *reference[i];
      item["reference"] = expected;
      const bool expected_found = expected >= 0;
      const double difference = plan.found && expected_found ? std::abs(plan.length - expected) : 0;
      if (plan.found && expected_found) max_difference = std::max(max_difference, difference);
      if (plan.found != expected_found || difference > 1e-9 * std::max(1.0, expected)) {
        ++mismatches;
        item["mismatch"] = true;
      }
    }
    queries.push_back(item);
    progress.update(i + 1, scenarios.size());
  }
  std::vector<double> sorted = micros;
  std::sort(sorted.begin(), sorted.end());
  double mean = 0;
  for (double us : micros) mean += us;
  mean = micros.empty() ? 0 : mean / micros.size();
  const double median = sorted.empty() ? 0 : sorted[sorted.size() / 2];
  nlohmann::json summary{{"queries", scenarios.size()},
                         {"mean_us", mean},
                         {"median_us", median},
                         {"preprocess_seconds", preprocess},
                         {"roadmap_vertices", graph.corner_count()},
                         {"roadmap_edges", boost::num_edges(graph.roadmap())}};
  if (!options.reference.empty()) {
    summary["mismatches"] = mismatches;
    summary["max_difference"] = max_difference;
  }
  if (!options.json.empty()) write_json({{"queries", queries}, {"summary", summary}}, options.json);
  if (options.json != "-") {
    std::printf("%8s %6s %14s %14s %10s\n", "index", "found", "length", "reference", "us");
    for (const auto& item : queries)
      std::printf("%8zu %6s %14.6f %14s %10.1f%s\n", item["index"].get<std::size_t>(), item["found"].get<bool>() ? "yes" : "no",
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
  command->callback([options, &run] { run = [options] { return run_scen(*options); }; });
}

}  // namespace polyplan::cli
