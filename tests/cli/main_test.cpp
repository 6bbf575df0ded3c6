// The polyplan program's own usage: help exits 0, unknown commands and options exit 2.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>

using namespace polyplan::test;
namespace fs = std::filesystem;

TEST(Usage, HelpExitsZeroAndUnknownOptionsExitTwo) {
  EXPECT_EQ(run_polyplan("--help").exit_code, 0);
  EXPECT_EQ(run_polyplan("cspace --help").exit_code, 0);
  EXPECT_EQ(run_polyplan("check --help").exit_code, 0);
  EXPECT_EQ(run_polyplan("cspace").exit_code, 2);
  EXPECT_EQ(run_polyplan("cspace " + world("maze.json") + " --frobnicate").exit_code, 2);
  EXPECT_EQ(run_polyplan("teleport").exit_code, 2);
}
