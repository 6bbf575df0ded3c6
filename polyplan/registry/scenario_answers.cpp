#include <polyplan/registry/scenario_answers.hpp>

#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/roadmaps/euclidean_shortest_paths.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

#include <sys/resource.h>

namespace polyplan {
namespace {

using nlohmann::json;

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// The answers with their reference lengths; counts the mismatches and the largest difference.
json query_list(const std::vector<TimedPathAnswer>& answers, const std::vector<std::optional<double>>& reference,
                std::size_t& mismatches, double& max_difference) {
  json queries = json::array();
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const EuclideanPathAnswer& plan = answers[i].answer;
    json item{{"index", i},
              {"found", plan.found},
              {"length", plan.found ? json(plan.length) : json(nullptr)},
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
  return queries;
}

}  // namespace

OptionTable<ScenarioBudget> scenario_budget_table() {
  OptionTable<ScenarioBudget> table;
  return table
      .add("threads", &ScenarioBudget::threads,
           "threads answering the queries, sharing one preprocessing (0: one per core)", in_range(0, 256))
      .add("table-mb", &ScenarioBudget::table_mb,
           "largest corner-to-corner distance table, and hub labels, to build, in MB (else queries search the corner "
           "graph)",
           in_range(0, 1 << 20));
}

json answer_scenarios(const GridMap& map, const std::vector<ScenarioQuery>& scenarios,
                      const std::optional<std::vector<std::optional<double>>>& reference, const ScenarioBudget& given) {
  ScenarioBudget budget = given;
  if (!budget.threads) budget.threads = std::max(1u, std::thread::hardware_concurrency());
  const Stopwatch preprocessing;
  const EuclideanShortestPaths paths(
      map, {.table_bytes = budget.table_mb << 20, .label_bytes = budget.table_mb << 20, .threads = budget.threads});
  const double preprocess = preprocessing.seconds();

  const Stopwatch batch;
  std::vector<std::pair<IntegerPoint, IntegerPoint>> asked;
  for (const ScenarioQuery& q : scenarios) asked.push_back({{q.start_x, q.start_y}, {q.goal_x, q.goal_y}});
  bool short_of_threads = false;
  const std::vector<TimedPathAnswer> answers =
      answer_all(paths, asked, budget.threads, budget.progress, &short_of_threads);
  if ((short_of_threads || paths.short_of_threads()) && budget.warn)
    budget.warn(
        "not all of the " + std::to_string(budget.threads) +
        " threads asked could start (the system's limits on threads and memory); the work went on with those that did");
  const double batch_seconds = batch.seconds();

  std::size_t mismatches = 0;
  double max_difference = 0;
  json queries =
      query_list(answers, reference.value_or(std::vector<std::optional<double>>{}), mismatches, max_difference);
  std::vector<double> micros;
  for (const TimedPathAnswer& a : answers) micros.push_back(a.us);
  std::sort(micros.begin(), micros.end());
  double mean = 0;
  for (double us : micros) mean += us;
  mean = micros.empty() ? 0 : mean / static_cast<double>(micros.size());
  json summary{{"queries", scenarios.size()},
               {"threads", budget.threads},
               {"mean_us", mean},
               {"median_us", micros.empty() ? 0 : micros[micros.size() / 2]},
               {"batch_seconds", batch_seconds},
               {"preprocess_seconds", preprocess},
               {"index_mb", static_cast<double>(paths.memory_bytes()) / (1 << 20)},
               {"peak_memory_mb", peak_memory_mb()},
               {"distance_table", paths.has_table()},
               {"hub_labels", paths.has_labels()},
               {"label_entries", paths.label_entries()},
               {"roadmap_vertices", paths.corner_count()},
               {"roadmap_edges", paths.edge_count()}};
  if (reference) {
    summary["mismatches"] = mismatches;
    summary["max_difference"] = max_difference;
  }
  return {{"queries", queries}, {"summary", summary}};
}

}  // namespace polyplan
