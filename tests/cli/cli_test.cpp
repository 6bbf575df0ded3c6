// The polyplan program run as a user runs it: exit codes, one-line errors, JSON output.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using namespace polyplan::test;

std::string world(const std::string& name) { return "'" + kSource + "/data/worlds/" + name + "'"; }
std::string path_file(const std::string& name) { return "'" + kSource + "/tests/data/paths/" + name + "'"; }

struct BadFile {
  std::string file, expected;
};

std::vector<BadFile> bad_corpus() {
  std::vector<BadFile> corpus;
  std::ifstream in(kSource + "/tests/data/bad/expected.tsv");
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
    corpus.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return corpus;
}

}  // namespace

TEST(BadInput, CorpusIsLargeEnough) { EXPECT_GE(bad_corpus().size(), 20u); }

TEST(BadInput, EveryFileExitsTwoWithOneLineNamingTheProblem) {
  for (const BadFile& bad : bad_corpus()) {
    SCOPED_TRACE(bad.file);
    const CliRun run = run_polyplan("cspace '" + kSource + "/tests/data/bad/" + bad.file + "'");
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(bad.expected), std::string::npos) << "expected \"" << bad.expected << "\" in: " << run.err;
    EXPECT_NE(run.err.find(bad.file), std::string::npos) << "the message should name the file: " << run.err;
  }
}

TEST(Cspace, EveryShippedWorldBuilds) {
  std::size_t worlds = 0;
  for (const auto& entry : fs::directory_iterator(kSource + "/data/worlds")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++worlds;
    const CliRun run = run_polyplan("cspace '" + entry.path().string() + "' --json -");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto summary = nlohmann::json::parse(run.out);
    EXPECT_GE(summary["free_components"].size(), 1u);
    EXPECT_GE(summary["seconds"].get<double>(), 0.0);
  }
  EXPECT_GE(worlds, 7u);
}

TEST(Cspace, ExactFitCorridorSplitsTheFreeSpace) {
  // The exact fit leaves two rooms; one billionth more joins them through the corridor.
  const auto exact = nlohmann::json::parse(run_polyplan("cspace " + world("corridor_exact.json") + " --json -").out);
  const auto wide = nlohmann::json::parse(run_polyplan("cspace " + world("corridor_wide.json") + " --json -").out);
  EXPECT_EQ(exact["free_components"].size(), 2u);
  EXPECT_EQ(wide["free_components"].size(), 1u);
}

TEST(Cspace, AreasAreExactRationals) {
  const auto summary = nlohmann::json::parse(run_polyplan("cspace " + world("touching_corners.json") + " --json -").out);
  ASSERT_EQ(summary["free_components"].size(), 2u);
  for (const auto& c : summary["free_components"]) {
    EXPECT_EQ(c["area"], "4");
    EXPECT_EQ(c["area_double"], 4.0);
  }
}

TEST(Cspace, WritesAnSvgAndATable) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_office.svg";
  const CliRun run = run_polyplan("cspace " + world("office.json") + " --svg '" + svg.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("free component"), std::string::npos) << run.out;
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
  fs::remove(svg);
}

TEST(Check, ExitCodesFollowTheVerdict) {
  struct Case {
    const char *world, *path;
    int exit_code;
  } cases[] = {
      {"touching_corners.json", "touching_corners_through_pinch.json", 1},
      {"touching_corners.json", "touching_corners_touch_and_back.json", 0},
      {"corridor_exact.json", "corridor_exact_through.json", 1},
      {"corridor_wide.json", "corridor_wide_through.json", 0},
      {"maze.json", "maze_solution.json", 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.world) + " " + c.path);
    const CliRun run = run_polyplan("check " + world(c.world) + " " + path_file(c.path) + " --json -");
    EXPECT_EQ(run.exit_code, c.exit_code) << run.out << run.err;
    const auto verdict = nlohmann::json::parse(run.out);
    EXPECT_EQ(verdict["valid"].get<bool>(), c.exit_code == 0);
    EXPECT_EQ(verdict["reason"].get<std::string>().empty(), c.exit_code == 0);
  }
}

TEST(Check, BadPathFileExitsTwo) {
  const fs::path bad = fs::temp_directory_path() / "polyplan_cli_test_bad_path.json";
  std::ofstream(bad) << R"({"path": [[0, 0], [1, "x"]]})";
  const CliRun run = run_polyplan("check " + world("maze.json") + " '" + bad.string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("path[1][1]: not a number"), std::string::npos) << run.err;
  fs::remove(bad);
}

TEST(Usage, HelpExitsZeroAndUnknownOptionsExitTwo) {
  EXPECT_EQ(run_polyplan("--help").exit_code, 0);
  EXPECT_EQ(run_polyplan("cspace --help").exit_code, 0);
  EXPECT_EQ(run_polyplan("check --help").exit_code, 0);
  EXPECT_EQ(run_polyplan("cspace").exit_code, 2);
  EXPECT_EQ(run_polyplan("cspace " + world("maze.json") + " --frobnicate").exit_code, 2);
  EXPECT_EQ(run_polyplan("teleport").exit_code, 2);
}

TEST(Plan, PrintsDesignsJsonWithExactPath) {
  const CliRun run = run_polyplan("plan " + world("decimal.json") + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto plans = nlohmann::json::parse(run.out);
  ASSERT_TRUE(plans.is_array());  // start/goal and one query
  ASSERT_EQ(plans.size(), 2u);
  const auto& first = plans[0];
  EXPECT_TRUE(first["found"].get<bool>());
  EXPECT_DOUBLE_EQ(first["length"].get<double>(), std::sqrt(117.0));
  EXPECT_EQ(first["path_exact"][0], nlohmann::json::array({"7/10", "23/10"}));
  EXPECT_EQ(first["path_exact"].back(), nlohmann::json::array({"97/10", "83/10"}));
  EXPECT_EQ(first["path"][0][0].get<double>(), 0.7);
  EXPECT_EQ(first["roadmap"]["kind"], "visibility");
  EXPECT_EQ(first["search"]["algorithm"], "astar");
}

TEST(Plan, OneQueryIsAnObjectAndNoPathIsAnAnswer) {
  const CliRun run = run_polyplan("plan " + world("touching_corners.json") + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto plan = nlohmann::json::parse(run.out);
  ASSERT_TRUE(plan.is_object());
  EXPECT_FALSE(plan["found"].get<bool>());
  EXPECT_TRUE(plan["length"].is_null());
}

TEST(Plan, EverySearchAndTheFullGraph) {
  for (const char* search : {"astar", "dijkstra", "bfs", "dfs", "greedy", "wastar --weight 2"}) {
    SCOPED_TRACE(search);
    const CliRun run = run_polyplan("plan " + world("maze.json") + " --roadmap visibility-full --search " + search + " --json -");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto plan = nlohmann::json::parse(run.out);
    EXPECT_TRUE(plan["found"].get<bool>());
    EXPECT_EQ(plan["roadmap"]["kind"], "visibility-full");
    EXPECT_EQ(plan["search"]["algorithm"], std::string(search).substr(0, std::string(search).find(' ')));
  }
  EXPECT_EQ(run_polyplan("plan " + world("maze.json") + " --search teleport").exit_code, 2);
  EXPECT_EQ(run_polyplan("plan " + world("maze.json") + " --search wastar --weight 0.5").exit_code, 2);
}

TEST(Plan, DrawsRoadmapAndPath) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_plan.svg";
  const CliRun run = run_polyplan("plan " + world("seed004.json") + " --svg '" + svg.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("roadmap edges"), std::string::npos);
  EXPECT_NE(picture.find("path"), std::string::npos);
  fs::remove(svg);
}

TEST(Scen, ArenaMatchesTheReference) {
  const std::string data = std::string(POLYPLAN_SOURCE_DIR "/data/movingai");
  const CliRun run = run_polyplan("scen '" + data + "/maps/arena.map' '" + data + "/scenarios/arena.map.scen' --reference '" + data +
                              "/reference/arena.csv' --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = nlohmann::json::parse(run.out);
  EXPECT_EQ(out["summary"]["queries"], 160);
  EXPECT_EQ(out["summary"]["mismatches"], 0);
  EXPECT_LT(out["summary"]["max_difference"].get<double>(), 1e-9);
  EXPECT_EQ(out["queries"].size(), 160u);
  EXPECT_NE(run.err.find("queries: 160/160"), std::string::npos);  // progress on stderr
}

TEST(Scen, BadInputIsOneLineAndExitTwo) {
  const std::string data = std::string(POLYPLAN_SOURCE_DIR "/data/movingai");
  const CliRun run = run_polyplan("scen '" + data + "/maps/arena.map' no_such.scen");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("no_such.scen: cannot open file"), std::string::npos) << run.err;
}
