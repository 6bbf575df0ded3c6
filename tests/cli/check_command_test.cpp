// polyplan check, run as a user runs it: exit 0 for a valid path, 1 for one that is not, 2 for bad input.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace polyplan::test;
namespace fs = std::filesystem;

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
