// Euclidean shortest paths on the MovingAI maps: the engine of `polyplan scen`
// (roadmaps/euclidean_shortest_paths.hpp) against Polyanya (Cui, Harabor, Grastien 2017), the peer
// in ../shared/peers/polyanya, on the same scenario files in one run (docs/euclidean_race.md).
//
// Polyanya is built from its folder into the build tree (`make fast`, its own flags) the first
// time, and run as its README says: scenariorunner MESH SCEN prints each query's µs (locating start
// and goal included, loading the mesh excluded) and length. polyplan's queries are timed the same
// way, one at a time on one thread, in file order; both means are the minimum over --runs runs.
// Then the whole file once more on every core against one thread (the batch speed-up of
// `scen --threads`). Lengths are compared query by query: equal within 1e-9 relative, or shorter
// where Polyanya, at a pinch point, tries one gap only (its README); never longer.
//
// With --tradeoff it measures instead what each index costs and buys on every map (the issue's
// "how close to Euclidean Hub Labelling" table): no index (an A* over the corners), hub labels of
// the corner graph, and the full corner-to-corner table, each within 1 GB: build seconds (the
// graph and the per-point corners included), index MB and mean µs per query on one thread.
//
// A plain program, not Google Benchmark: it drives the peer's own runner and times whole files.
// Usage: euclidean_race [--maps arena,den312d,...] [--runs 2] [--tradeoff]
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/roadmaps/euclidean_shortest_paths.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace polyplan;
namespace fs = std::filesystem;

struct PeerRun {
  double mean_us = 0;
  std::vector<double> lengths;  // -1: no path
};

std::string polyanya_runner() {
  const fs::path build = fs::path(POLYPLAN_BENCH_BUILD_DIR) / "polyanya";
  const fs::path runner = build / "bin" / "scenariorunner";
  if (fs::exists(runner)) return runner.string();
  std::fprintf(stderr, "building Polyanya from %s into %s...\n", POLYPLAN_PEERS_DIR "/polyanya", build.c_str());
  fs::remove_all(build);
  fs::copy(fs::path(POLYPLAN_PEERS_DIR) / "polyanya", build, fs::copy_options::recursive);
  const std::string command =
      "make -C '" + build.string() + "' fast -j2 > '" + (build / "build.log").string() + "' 2>&1";
  if (std::system(command.c_str()) != 0 || !fs::exists(runner))
    throw std::runtime_error("building Polyanya failed: see " + (build / "build.log").string());
  return runner.string();
}

PeerRun run_polyanya(const std::string& runner, const std::string& mesh, const std::string& scenarios) {
  const std::string command = "'" + runner + "' '" + mesh + "' '" + scenarios + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  PeerRun run;
  char line[512];
  double total = 0;
  while (std::fgets(line, sizeof line, pipe)) {
    // index;micro;successor_calls;generated;pushed;popped;pruned_post_pop;length;gridcost
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ';');) fields.push_back(field);
    if (fields.size() < 9 || fields[0] == "index") continue;
    total += std::stod(fields[1]);
    run.lengths.push_back(std::stod(fields[7]));
  }
  if (pclose(pipe) != 0 || run.lengths.empty()) throw std::runtime_error("Polyanya failed on " + scenarios);
  run.mean_us = total / static_cast<double>(run.lengths.size());
  return run;
}

using Queries = std::vector<std::pair<IntegerPoint, IntegerPoint>>;

Queries asked(const std::vector<ScenarioQuery>& scenarios) {
  Queries queries;
  for (const ScenarioQuery& q : scenarios) queries.push_back({{q.start_x, q.start_y}, {q.goal_x, q.goal_y}});
  return queries;
}

// Seconds for the whole file on `threads` threads sharing `paths`.
double batch_seconds(const EuclideanShortestPaths& paths, const Queries& queries, unsigned threads) {
  const Stopwatch clock;
  answer_all(paths, queries, threads);
  return clock.seconds();
}

// Mean µs per query on one thread, the file once in order (each query timed alone, as Polyanya's
// runner times its own); the answers land in `answers` when given.
double mean_query_us(const EuclideanShortestPaths& paths, const Queries& queries,
                     std::vector<TimedPathAnswer>* answers = nullptr) {
  std::vector<TimedPathAnswer> timed = answer_all(paths, queries, 1);
  double total = 0;
  for (const TimedPathAnswer& t : timed) total += t.us;
  if (answers) *answers = std::move(timed);
  return total / static_cast<double>(queries.size());
}

void tradeoff(const std::vector<std::string>& maps, const std::string& data) {
  constexpr std::size_t gigabyte = std::size_t{1} << 30;
  struct Index {
    const char* name;
    EuclideanShortestPathsOptions options;
  };
  const Index indexes[] = {{"A*", {.table_bytes = 0, .label_bytes = 0}},
                           {"hub labels", {.table_bytes = 0, .label_bytes = gigabyte}},
                           {"table", {.table_bytes = gigabyte, .label_bytes = 0}}};
  std::printf("| map | corners | index | build s | index MB | µs per query |\n|---|---|---|---|---|---|\n");
  for (const std::string& name : maps) {
    const GridMap map = read_movingai_map(data + "/maps/" + name + ".map");
    const Queries queries = asked(read_scenarios(data + "/scenarios/" + name + ".map.scen"));
    for (const Index& index : indexes) {
      const Stopwatch building;
      const EuclideanShortestPaths paths(map, index.options);
      const double build = building.seconds();
      const bool built = std::string(index.name) == "A*" || paths.has_table() || paths.has_labels();
      if (!built) {
        std::printf("| %s | %zu | %s | — | — | not built (%s) |\n", name.c_str(), paths.corner_count(), index.name,
                    std::string(index.name) == "table" ? "over 1 GB" : "mean degree over 16");
        continue;
      }
      std::printf("| %s | %zu | %s | %.2f | %.1f | %.1f |\n", name.c_str(), paths.corner_count(), index.name, build,
                  static_cast<double>(paths.memory_bytes()) / (1 << 20), mean_query_us(paths, queries));
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("polyplan scen's Euclidean shortest paths against Polyanya on the MovingAI maps");
  std::vector<std::string> maps{"arena",   "den312d", "lak303d",     "brc202d",       "orz103d",
                                "hrt201n", "ost003d", "maze512-1-0", "random512-10-0"};
  int runs = 2;
  app.add_option("--maps", maps, "Maps of ../shared/benchmarks/movingai")->delimiter(',');
  app.add_option("--runs", runs, "Runs of each file; the minimum mean counts")->check(CLI::Range(1, 100));
  bool measure_tradeoff = false;
  app.add_flag("--tradeoff", measure_tradeoff,
               "Measure each index (none, hub labels, table) instead of racing Polyanya");
  CLI11_PARSE(app, argc, argv);

  const std::string data = POLYPLAN_BENCHMARK_DIR, meshes = POLYPLAN_PEERS_DIR "/polyanya/meshes";
  if (measure_tradeoff) {
    tradeoff(maps, data);
    return 0;
  }
  const std::string runner = polyanya_runner();
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::printf(
      "| map | queries | Polyanya µs | polyplan µs | ratio | preprocess s | index MB | corner distances | %u-thread "
      "speed-up | "
      "lengths equal | shorter (pinch) | longer |\n",
      cores);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& name : maps) {
    const std::string scen = data + "/scenarios/" + name + ".map.scen";
    const Queries queries = asked(read_scenarios(scen));
    PeerRun peer;
    for (int r = 0; r < runs; ++r) {
      PeerRun run = run_polyanya(runner, meshes + "/" + name + "-merged.mesh", scen);
      if (r == 0 || run.mean_us < peer.mean_us) peer = std::move(run);
    }

    const GridMap map = read_movingai_map(data + "/maps/" + name + ".map");
    const Stopwatch building;
    const EuclideanShortestPaths paths(map);
    const double preprocess = building.seconds();
    std::vector<TimedPathAnswer> answers;
    double best_mean = mean_query_us(paths, queries, &answers);  // the first run, right after building
    for (int r = 1; r < runs; ++r) best_mean = std::min(best_mean, mean_query_us(paths, queries));
    const double one = batch_seconds(paths, queries, 1), all = batch_seconds(paths, queries, cores);

    std::size_t equal = 0, shorter = 0, longer = 0;
    for (std::size_t i = 0; i < queries.size() && i < peer.lengths.size(); ++i) {
      const double theirs = peer.lengths[i], ours = answers[i].answer.found ? answers[i].answer.length : -1;
      if ((theirs < 0) != (ours < 0) || ours > theirs + 1e-9 * std::max(1.0, theirs)) ++longer;
      else if (ours < theirs - 1e-9 * std::max(1.0, theirs)) ++shorter;
      else ++equal;
    }
    std::printf("| %s | %zu | %.1f | %.1f | %.2f | %.2f | %.1f | %s | %.2f | %zu | %zu | %zu |\n", name.c_str(),
                queries.size(), peer.mean_us, best_mean, best_mean / peer.mean_us, preprocess,
                static_cast<double>(paths.memory_bytes()) / (1 << 20),
                paths.has_table()    ? "table"
                : paths.has_labels() ? "hub labels"
                                     : "A*",
                one / all, equal, shorter, longer);
    std::fflush(stdout);
  }
}
