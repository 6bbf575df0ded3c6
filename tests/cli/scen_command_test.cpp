// polyplan scen, run as a user runs it: a MovingAI scenario file against the reference lengths.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>

using namespace polyplan::test;
namespace fs = std::filesystem;

TEST(Scen, ArenaMatchesTheReference) {
  const std::string& data = kMovingAi;
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
  const std::string& data = kMovingAi;
  const CliRun run = run_polyplan("scen '" + data + "/maps/arena.map' no_such.scen");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("no_such.scen: cannot open file"), std::string::npos) << run.err;
}
