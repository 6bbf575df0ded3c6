// polyplan grid: the MovingAI octile benchmark from the command line (JSON keys, mismatches, the
// weighted-A* bound, bad input as one line and exit 2).
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

using polyplan::test::CliRun;
namespace cli = polyplan::test;  // cli::run_polyplan(ARGUMENTS) runs the program
namespace fs = std::filesystem;

const std::string& kData = polyplan::test::kMovingAi;
const std::string kArena = "'" + kData + "/maps/arena.map' '" + kData + "/scenarios/arena.map.scen'";

TEST(Grid, ArenaJsonHasEveryKeyAndNoMismatch) {
  const CliRun run = cli::run_polyplan("grid " + kArena + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = nlohmann::json::parse(run.out);
  const auto& summary = out["summary"];
  for (const char* key : {"queries", "mismatches", "mean_us", "mean_expanded"})
    EXPECT_TRUE(summary.contains(key)) << key;
  EXPECT_EQ(summary["queries"], 160);
  EXPECT_EQ(summary["mismatches"], 0);
  EXPECT_GT(summary["mean_expanded"].get<double>(), 1.0);
  EXPECT_GT(summary["mean_us"].get<double>(), 0.0);
  ASSERT_EQ(out["queries"].size(), 160u);
  for (const auto& q : out["queries"])
    for (const char* key : {"index", "found", "length", "expected", "expanded", "us"})
      ASSERT_TRUE(q.contains(key)) << key;
  // Line 2 of the file: (1, 11) to (1, 12), one straight step; line 4: (1, 13) to (4, 12), 2 + sqrt 2.
  EXPECT_EQ(out["queries"][0]["index"], 0);
  EXPECT_EQ(out["queries"][0]["length"].get<double>(), 1.0);
  EXPECT_EQ(out["queries"][0]["expected"].get<double>(), 1.0);
  EXPECT_EQ(out["queries"][0]["expanded"], 2);  // the start, then the goal
  EXPECT_NEAR(out["queries"][2]["length"].get<double>(), 2 + std::sqrt(2.0), 1e-12);
  EXPECT_NE(run.err.find("queries: 160/160"), std::string::npos) << run.err;  // progress on stderr
}

TEST(Grid, TableWithoutJsonAndWeightedAStarWithinItsBound) {
  const CliRun table = cli::run_polyplan("grid " + kArena + " --search dijkstra");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("expected"), std::string::npos);
  EXPECT_NE(table.out.find("summary: "), std::string::npos);
  EXPECT_EQ(table.out.find("MISMATCH"), std::string::npos) << table.out;

  const CliRun run = cli::run_polyplan("grid " + kArena + " --search wastar --weight 2 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = nlohmann::json::parse(run.out);
  EXPECT_EQ(out["summary"]["search"], "wastar");
  EXPECT_EQ(out["summary"]["bound_violations"], 0);
  EXPECT_TRUE(out["summary"].contains("note"));
  for (const auto& q : out["queries"]) {
    EXPECT_TRUE(q["bound_ok"].get<bool>());
    EXPECT_LE(q["length"].get<double>(), 2 * q["expected"].get<double>() + 1e-4);
  }
}

TEST(Grid, BadInputIsOneLineNamingTheFileAndExitTwo) {
  const fs::path scen = fs::temp_directory_path() / ("polyplan_grid_cli_test_" + std::to_string(::getpid()) + ".scen");
  const std::string arena_with_scen = "grid '" + kData + "/maps/arena.map' '" + scen.string() + "'";
  struct Case {
    std::string arguments, scen_query, expected;  // scen_query: the one query of the temporary file
  } cases[] = {
      {"grid '" + kData + "/maps/arena.map' '" + kData + "/scenarios/den312d.map.scen'", "",
       "den312d.map.scen: line 2: the query is for a 65x81 map, " + kData + "/maps/arena.map is 49x49"},
      {arena_with_scen, "0\tarena.map\t49\t49\t1\t0\t1\t12\t12",
       scen.string() + ": line 2: start (1, 0) is a blocked cell"},
      {arena_with_scen, "0\tarena.map\t49\t49\t1\t11\t1\t49\t38",
       scen.string() + ": line 2: goal (1, 49) is outside the 49x49 map"},
      {"grid " + kArena + " --search bfs", "", "--search bfs: expected one of astar|dijkstra|wastar"},
      {"grid " + kArena + " --search wastar --weight 0.5", "", "--weight 0.5: expected a number in [1, inf)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments + " " + c.scen_query);
    if (!c.scen_query.empty()) std::ofstream(scen) << "version 1\n" << c.scen_query << "\n";
    const CliRun run = cli::run_polyplan(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
    EXPECT_EQ(cli::lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected \"" << c.expected << "\" in: " << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
  fs::remove(scen);
}

}  // namespace
