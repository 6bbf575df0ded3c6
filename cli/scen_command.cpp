// polyplan scen MAP.map SCEN.scen [--reference REF.csv] [--json -] [--threads N]: every query of a
// MovingAI scenario file, answered from one preprocessing (roadmaps/euclidean_shortest_paths.hpp)
// by N threads, compared with reference lengths.
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/roadmaps/euclidean_shortest_paths.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

#include <sys/resource.h>

namespace polyplan::cli {
namespace {

using Clock = std::chrono::steady_clock;

// --threads and --table-mb.
struct ScenBudget {
  unsigned threads = 0;  // every core
  std::size_t table_mb = 1024;
};
OptionTable<ScenBudget> scen_budget_table() {
  OptionTable<ScenBudget> table;
  return table
      .add("threads", &ScenBudget::threads,
           "threads answering the queries, sharing one preprocessing (0: one per core)", in_range(0, 256))
      .add("table-mb", &ScenBudget::table_mb,
           "largest corner-to-corner distance table, and hub labels, to build, in MB (else queries search the corner "
           "graph)",
           in_range(0, 1 << 20));
}

struct ScenOptions {
  std::string map;
  std::string scenarios;
  std::string reference;
  std::string json;
  std::unique_ptr<CommandOptions<ScenBudget>> budget;
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

int run_scen(const ScenOptions& options) {
  // Every input is read (and any error reported, alone on stderr) before the long work starts.
  const ScenBudget budget = options.budget->parse();
  const auto started = Clock::now();
  const GridMap map = read_movingai_map(options.map);
  const auto scenarios = read_scenarios(options.scenarios);
  check_scenarios_match(scenarios, map.width, map.height, map.source, options.scenarios);
  std::vector<std::optional<double>> reference;
  if (!options.reference.empty()) reference = read_reference_lengths(options.reference, scenarios.size());
  const unsigned threads = budget.threads ? budget.threads : std::max(1u, std::thread::hardware_concurrency());
  std::fprintf(stderr, "building the corner graph and its distance table or hub labels for %s (%dx%d)...\n",
               options.map.c_str(), map.width, map.height);
  const EuclideanShortestPaths paths(
      map, {.table_bytes = budget.table_mb << 20, .label_bytes = budget.table_mb << 20, .threads = threads});
  const double preprocess = seconds_since(started);

  const auto batch = Clock::now();
  std::vector<std::pair<IntegerPoint, IntegerPoint>> asked;
  for (const ScenarioQuery& q : scenarios) asked.push_back({{q.start_x, q.start_y}, {q.goal_x, q.goal_y}});
  Progress progress("queries");
  bool short_of_threads = false;
  const std::vector<TimedPathAnswer> answers = answer_all(
      paths, asked, threads, [&](std::size_t done) { progress.update(done, asked.size()); }, &short_of_threads);
  if (short_of_threads || paths.short_of_threads())
    std::fprintf(stderr,
                 "warning: not all of the %u threads asked could start (the system's limits); the work went "
                 "on with those that did\n",
                 threads);
  const double batch_seconds = seconds_since(batch);

  nlohmann::json queries = nlohmann::json::array();
  std::vector<double> micros;
  std::size_t mismatches = 0;
  double max_difference = 0;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const EuclideanPathAnswer& plan = answers[i].answer;
    micros.push_back(answers[i].us);
    nlohmann::json item{{"index", i},
                        {"found", plan.found},
                        {"length", plan.found ? nlohmann::json(plan.length) : nlohmann::json(nullptr)},
                        {"us", answers[i].us}};
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
  }
  std::vector<double> sorted = micros;
  std::sort(sorted.begin(), sorted.end());
  double mean = 0;
  for (double us : micros) mean += us;
  mean = micros.empty() ? 0 : mean / micros.size();
  const double median = sorted.empty() ? 0 : sorted[sorted.size() / 2];
  nlohmann::json summary{{"queries", scenarios.size()},
                         {"threads", threads},
                         {"mean_us", mean},
                         {"median_us", median},
                         {"batch_seconds", batch_seconds},
                         {"preprocess_seconds", preprocess},
                         {"index_mb", static_cast<double>(paths.memory_bytes()) / (1 << 20)},
                         {"peak_memory_mb", peak_memory_mb()},
                         {"distance_table", paths.has_table()},
                         {"hub_labels", paths.has_labels()},
                         {"label_entries", paths.label_entries()},
                         {"roadmap_vertices", paths.corner_count()},
                         {"roadmap_edges", paths.edge_count()}};
  if (!options.reference.empty()) {
    summary["mismatches"] = mismatches;
    summary["max_difference"] = max_difference;
  }
  if (!options.json.empty()) write_json({{"queries", queries}, {"summary", summary}}, options.json);
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
  options->budget = std::make_unique<CommandOptions<ScenBudget>>(*command, scen_budget_table());
  command->callback([options, &run] { run = [options] { return run_scen(*options); }; });
}

}  // namespace polyplan::cli
