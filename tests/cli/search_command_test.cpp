// polyplan search, run as a user runs it: the course's graph-search homework's graphs searched with each method, the
// summary line, the JSON, the trace as JSON lines, the picture and its animation, and one-line errors for bad graphs
// (naming the vertex) and bad options. Also plan's --trace for the graph planners.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

using namespace polyplan::test;
namespace fs = std::filesystem;

namespace {

std::string graph(const std::string& name) { return "'" + kSource + "/data/graphs/" + name + "'"; }

std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(nlohmann::json::parse(line));
  return out;
}

// A bad graph file in a temporary folder.
std::string bad_graph(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("polyplan_search_test_" + name);
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(Search, PrintsTheSummaryLine) {
  const CliRun run = run_polyplan("search " + graph("small.json") + " --start 0 --goal 6");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "astar: path 0 1 4 6, cost 5, expanded 6 of 7 generated\n");
}

TEST(Search, JsonHasPathCostCountsAndExpansionOrder) {
  const CliRun run = run_polyplan("search " + graph("grid_medium.json") + " --start 0 --goal 37 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto r = nlohmann::json::parse(run.out);
  EXPECT_EQ(r["found"], true);
  EXPECT_EQ(r["method"], "astar");
  EXPECT_EQ(r["path"], nlohmann::json::parse("[0, 8, 15, 20, 25, 26, 27, 21, 16, 10, 11, 12, 13, 18, 23, 30, 37]"));
  EXPECT_NEAR(r["cost"].get<double>(), 14 + 2 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(r["expanded"], 33);
  ASSERT_EQ(r["expansion_order"].size(), 33u);
  EXPECT_EQ(r["expansion_order"][0], 0);
  EXPECT_EQ(r["expansion_order"].back(), 37);
  ASSERT_EQ(r["expansions"].size(), 33u);
  EXPECT_EQ(r["expansions"][0]["vertex"], 0);
  EXPECT_GE(r["generated"].get<int>(), 33);
}

TEST(Search, EveryMethodAnswers) {
  for (const char* method : {"astar", "dijkstra", "bfs", "dfs", "greedy", "wastar --weight 2"}) {
    const CliRun run =
        run_polyplan("search " + graph("grid_medium.json") + " --start 0 --goal 37 --json - --method " + method);
    ASSERT_EQ(run.exit_code, 0) << method << ": " << run.err;
    const auto r = nlohmann::json::parse(run.out);
    EXPECT_EQ(r["found"], true) << method;
    EXPECT_GE(r["cost"].get<double>(), 14 + 2 * std::sqrt(2.0) - 1e-9) << method;
    EXPECT_EQ(r["method"], std::string(method).substr(0, std::string(method).find(' ')));
  }
}

// The course's names: uniform-cost is Dijkstra, expansion for expansion; weighted A* says whether it reopened.
TEST(Search, UniformCostIsDijkstraAndWeightedAStarSaysWhetherItReopens) {
  const auto json_of = [](const std::string& options) {
    const CliRun run = run_polyplan("search " + graph("grid_medium.json") + " --start 0 --goal 37 --json - " + options);
    EXPECT_EQ(run.exit_code, 0) << options << ": " << run.err;
    return nlohmann::json::parse(run.out);
  };
  const auto uniform = json_of("--method uniform-cost"), dijkstra = json_of("--method dijkstra");
  EXPECT_EQ(uniform["method"], "dijkstra");
  EXPECT_EQ(uniform["expansion_order"], dijkstra["expansion_order"]);
  EXPECT_EQ(uniform["cost"], dijkstra["cost"]);
  EXPECT_EQ(json_of("--method wastar --weight 3")["reopen"], false);
  const auto reopening = json_of("--method wastar --weight 3 --reopen");
  EXPECT_EQ(reopening["reopen"], true);
  EXPECT_LE(reopening["cost"].get<double>(), 3 * dijkstra["cost"].get<double>());
}

TEST(Search, NoPathIsAnAnswer) {
  // 2 → 5 is one-way in small.json, and nothing leads out of an isolated vertex.
  const std::string lonely = bad_graph("lonely.json", R"([{"x": [0, 0], "neighbors": [], "neighbors_cost": []},
    {"x": [1, 0], "neighbors": [0], "neighbors_cost": [1]}])");
  const CliRun run = run_polyplan("search '" + lonely + "' --start 0 --goal 1 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto r = nlohmann::json::parse(run.out);
  EXPECT_EQ(r["found"], false);
  EXPECT_EQ(r["cost"], nullptr);
  EXPECT_EQ(r["path"], nlohmann::json::array());
  EXPECT_EQ(run_polyplan("search '" + lonely + "' --start 0 --goal 1").out,
            "astar: no path, expanded 1 of 1 generated\n");
  fs::remove(lonely);
}

TEST(Search, TraceHasOneLinePerExpansion) {
  const CliRun run = run_polyplan("search " + graph("small.json") + " --start 0 --goal 6 --trace -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto lines = json_lines(run.out);
  ASSERT_EQ(lines.size(), 6u);
  const std::vector<int> order{0, 1, 2, 4, 3, 6};
  for (std::size_t k = 0; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k]["step"], k + 1);
    EXPECT_EQ(lines[k]["vertex"], order[k]);
    EXPECT_DOUBLE_EQ(lines[k]["f"].get<double>(), lines[k]["g"].get<double>() + lines[k]["h"].get<double>());
  }
  EXPECT_EQ(run.out.substr(0, run.out.find('\n')),
            R"({"step":1,"vertex":0,"g":0.0,"h":4.0,"f":4.0,"backpointer":null,"open":0})");
  EXPECT_EQ(lines[1]["backpointer"], 0);
  EXPECT_EQ(lines[1]["open"], 1);  // 2 waits
  EXPECT_EQ(lines.back()["g"], 5.0);
  EXPECT_EQ(lines.back()["backpointer"], 4);

  const fs::path file = fs::temp_directory_path() / "polyplan_search_trace.jsonl";
  const CliRun to_file =
      run_polyplan("search " + graph("small.json") + " --start 0 --goal 6 --trace '" + file.string() + "'");
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  EXPECT_EQ(slurp(file), run.out);
  EXPECT_NE(to_file.out.find("astar: path 0 1 4 6"), std::string::npos);
  fs::remove(file);
}

TEST(Search, DrawsTheSearchAndItsAnimation) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_search_test.svg";
  const CliRun run = run_polyplan("search " + graph("grid_medium.json") + " --start 0 --goal 37 --svg '" +
                                  svg.string() + "' --labels --backpointers --edge-weights --heuristic");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("picture: " + svg.string()), std::string::npos);
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("expanded (33)"), std::string::npos);
  EXPECT_NE(picture.find("backpointer"), std::string::npos);
  EXPECT_EQ(picture.find("<animate"), std::string::npos);

  const CliRun animated = run_polyplan("search " + graph("grid_medium.json") + " --start 0 --goal 37 --svg '" +
                                       svg.string() + "' --animate");
  ASSERT_EQ(animated.exit_code, 0) << animated.err;
  const std::string frames = slurp(svg);
  std::size_t expanded = 0;
  for (auto pos = frames.find("<circle class=\"expanded\""); pos != std::string::npos;
       pos = frames.find("<circle class=\"expanded\"", pos + 1))
    ++expanded;
  EXPECT_EQ(expanded, 33u);
  fs::remove(svg);
}

TEST(Search, RefusesBadGraphsAndOptionsInOneLine) {
  const std::string out_of_range = bad_graph("range.json", R"([{"x": [0, 0], "neighbors": [1], "neighbors_cost": [1]},
    {"x": [1, 0], "neighbors": [0, 9], "neighbors_cost": [1, 1]}])");
  const std::string negative =
      bad_graph("negative.json", R"([{"x": [0, 0], "neighbors": [0], "neighbors_cost": [-1]}])");
  const std::string lengths = bad_graph("lengths.json", R"([{"x": [0, 0], "neighbors": [0], "neighbors_cost": []}])");
  const std::string no_x = bad_graph("no_x.json", R"([{"neighbors": [], "neighbors_cost": []}])");
  const struct {
    std::string arguments;
    std::string expected;
  } cases[] = {
      {"search '" + out_of_range + "' --start 0 --goal 1",
       out_of_range + ": vertices[1].neighbors[1]: index 9 outside [0, 2)"},
      {"search '" + negative + "' --start 0 --goal 0", negative + ": vertices[0].neighbors_cost[0]: negative cost -1"},
      {"search '" + lengths + "' --start 0 --goal 0", lengths + ": vertices[0]: 1 neighbors but 0 neighbors_cost"},
      {"search '" + no_x + "' --start 0 --goal 0", no_x + ": vertices[0]: missing field \"x\""},
      {"search " + graph("small.json") + " --start 0 --goal 7", "--goal 7: not a vertex of"},
      {"search " + graph("small.json") + " --start 0 --goal 6 --method teleport",
       "--method teleport: expected one of astar|dijkstra|bfs|dfs|greedy|wastar|uniform-cost"},
      {"search " + graph("small.json") + " --start 0 --goal 6 --method wastar --weight 0.5",
       "--weight 0.5: expected a number in [1, inf)"},
      {"search " + graph("small.json") + " --start 0 --goal 6 --animate", "--animate: give --svg OUT.svg"},
      {"search " + graph("small.json") + " --start 0 --goal 6 --json - --trace -",
       "only one of them can go to standard output"},
      {"search /nonexistent.json --start 0 --goal 0", "/nonexistent.json: cannot open file"},
      {"search " + graph("small.json") + " --goal 6", "--start is required"},
  };
  for (const auto& c : cases) {
    const CliRun run = run_polyplan(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << c.arguments;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << c.arguments << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  for (const auto& file : {out_of_range, negative, lengths, no_x}) fs::remove(file);
}

// plan --trace: the graph planners' searches, one line per expansion with the vertex's position.
TEST(PlanTrace, GraphPlannersWriteEveryExpansion) {
  for (const char* planner : {"visibility", "trapezoid", "raster"}) {
    const CliRun json = run_polyplan("plan " + world("maze.json") + " --planner " + planner + " --json -");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto expanded = nlohmann::json::parse(json.out)["search"]["expanded"].get<std::size_t>();
    const CliRun run = run_polyplan("plan " + world("maze.json") + " --planner " + planner + " --trace -");
    ASSERT_EQ(run.exit_code, 0) << planner << ": " << run.err;
    const auto lines = json_lines(run.out);
    ASSERT_EQ(lines.size(), expanded) << planner;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      EXPECT_EQ(lines[k]["step"], k + 1);
      EXPECT_EQ(lines[k]["at"].size(), 2u);
      EXPECT_EQ(lines[k]["query"], "start/goal");
      EXPECT_NEAR(lines[k]["f"].get<double>(), lines[k]["g"].get<double>() + lines[k]["h"].get<double>(), 1e-9);
    }
    EXPECT_EQ(lines[0]["backpointer"], nullptr);
    EXPECT_EQ(lines[0]["g"], 0.0);
  }
  const CliRun sampling = run_polyplan("plan " + world("seed004.json") + " --planner rrt --trace /dev/null");
  EXPECT_EQ(sampling.exit_code, 0) << sampling.err;
  EXPECT_NE(sampling.err.find("warning: --trace: rrt ran no graph search"), std::string::npos) << sampling.err;
}
