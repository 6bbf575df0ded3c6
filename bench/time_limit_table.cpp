// Whether the planners keep their time limits (issue 48: RRT* asked for 1 s ran 1.08–1.30 s):
// `polyplan plan FILE --planner P --time T --iterations 1000000000` on worlds, arms and cars (the
// replanning planners, which have no iteration limit, on a fine raster), each
// run a process of its own, measured from outside as the issue measured it (wall time from fork to
// exit), beside the query's own clock (query_seconds, from the JSON answer: the wall time less
// reading the world and building its configuration space; of a world of several queries, the
// longest query). The iteration limit is set out of
// reach so that the time limit is what stops every planner that does not stop at its first
// solution; the limits asked of those (prm, lazyprm, rrt, rrtconnect, car-rrt, hybrid-astar) are
// short enough that most runs are stopped by them.
//
// A plain program, not Google Benchmark: it times whole planning runs of the command-line program.
// Usage: time_limit_table [--program BIN] [--runs 5]
//   --program BIN   the polyplan to measure (default: this build's), e.g. an earlier build
#include "spawn_quiet.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Run {
  double wall = 0, query = 0;
  std::string stopped_by;
};

// One run of `program args... --json FILE`, its wall time from fork to exit.
Run run(const std::string& program, std::vector<std::string> args) {
  const std::string json = "/tmp/time_limit_table_" + std::to_string(getpid()) + ".json";
  std::remove(json.c_str());
  args.insert(args.begin(), program);
  args.insert(args.end(), {"--json", json});
  const auto began = std::chrono::steady_clock::now();
  const pid_t child = polyplan::bench::spawn_quiet(args, [] {});
  int status = 0;
  waitpid(child, &status, 0);
  Run result;
  result.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  std::ifstream in(json);
  auto answers = nlohmann::json::parse(in, nullptr, false);
  if (answers.is_object()) answers = nlohmann::json::array({answers});
  if (answers.is_array())  // a world of several queries: the longest query
    for (const auto& answer : answers)
      if (answer.value("query_seconds", 0.0) >= result.query) {
        result.query = answer.value("query_seconds", 0.0);
        result.stopped_by = answer.value("stopped_by", std::string(answer.value("found", false) ? "solution" : "?"));
      }
  std::remove(json.c_str());
  return result;
}

struct Case {
  std::string planner, file;
  double seconds;
  std::vector<std::string> extra = {};
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Wall time of planners asked for a time limit: min and max over runs, one process per run"};
  std::string program = POLYPLAN_CLI;
  int runs = 5;
  app.add_option("--program", program, "the polyplan program to measure");
  app.add_option("--runs", runs, "runs per case")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  const std::string worlds = std::string(POLYPLAN_DATA_DIR) + "/worlds/",
                    arms = std::string(POLYPLAN_DATA_DIR) + "/arms/";
  const std::vector<Case> cases{
      {"rrtstar", worlds + "maze.json", 1},
      {"rrtstar", worlds + "office.json", 1},
      {"prm", worlds + "maze.json", 0.02},
      {"lazyprm", worlds + "maze.json", 0.02},
      {"rrt", worlds + "maze.json", 0.02},
      {"rrtconnect", worlds + "maze.json", 0.02},
      {"rrtstar", arms + "six_link_forest.json", 1},
      {"prm", arms + "six_link_forest.json", 0.2},
      {"lazyprm", arms + "six_link_forest.json", 0.2},
      {"rrt", arms + "six_link_forest.json", 0.2},
      {"rrtconnect", arms + "six_link_forest.json", 0.05},
      {"rrtstar", worlds + "car_parallel_parking.json", 1},
      {"prm", worlds + "car_parallel_parking.json", 0.2},
      {"hybrid-astar", worlds + "car_parallel_parking.json", 0.05},
      {"car-rrt", worlds + "car_parallel_parking.json", 0.05},
      {"dstar-lite", worlds + "maze.json", 0.1, {"--resolution", "1000"}},
      {"lpastar", worlds + "maze.json", 0.1, {"--resolution", "1000"}},
      {"repeated-astar", worlds + "maze.json", 0.1, {"--resolution", "1000"}},
  };
  std::printf(
      "`%s plan FILE --planner P --time T --iterations 1000000000`, %d runs each: wall time (process) and\n"
      "query_seconds (the planner's own clock), min / max, in seconds\n\n",
      program.c_str(), runs);
  std::printf("| planner | problem | asked | wall min | wall max | query min | query max | stopped by |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", c.seconds);
    std::vector<Run> measured;
    std::vector<std::string> args{"plan", c.file, "--planner", c.planner, "--time", seconds};
    if (c.planner != "dstar-lite" && c.planner != "lpastar" && c.planner != "repeated-astar")
      args.insert(args.end(), {"--iterations", "1000000000"});  // the replanning planners have none
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    for (int i = 0; i < runs; ++i) measured.push_back(run(program, args));
    const auto [wall_min, wall_max] = std::minmax_element(measured.begin(), measured.end(),
                                                          [](const Run& a, const Run& b) { return a.wall < b.wall; });
    const auto [query_min, query_max] = std::minmax_element(
        measured.begin(), measured.end(), [](const Run& a, const Run& b) { return a.query < b.query; });
    std::string stopped;
    for (const Run& r : measured)
      if (stopped.find(r.stopped_by) == std::string::npos) stopped += (stopped.empty() ? "" : ", ") + r.stopped_by;
    std::string name = c.file.substr(c.file.rfind('/', c.file.rfind('/') - 1) + 1);
    for (const std::string& e : c.extra) name += " " + e;
    std::printf("| %s | %s | %s | %.3f | %.3f | %.3f | %.3f | %s |\n", c.planner.c_str(), name.c_str(), seconds,
                wall_min->wall, wall_max->wall, query_min->query, query_max->query, stopped.c_str());
    std::fflush(stdout);
  }
  return 0;
}
