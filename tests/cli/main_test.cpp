// The polyplan program's own usage: help exits 0, unknown commands and options exit 2.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include <sys/wait.h>
#include <unistd.h>

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

// Exit 3 means a bug in polyplan; nothing a user types may reach it. Each of these is the user's
// input and exits 2 with one line that names what is wrong.
TEST(Usage, EveryMistakeOnTheCommandLineIsOneLineAndExitTwo) {
  const std::string maze = world("maze.json");
  const fs::path dir = fs::temp_directory_path() / ("polyplan_main_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Case {
    std::string arguments, expected;
  };
  const std::vector<Case> cases = {
      {"teleport " + maze,
       "error: unknown command \"teleport\" (commands: cspace check plan scen grid arm planners steer replan potential "
       "ik search benchmark)"},
      {"cspace " + maze + " --frobnicate", "--frobnicate"},
      {"plan", "problem is required"},
      {"plan " + maze + " --svg " + dir.string(), dir.string() + ": cannot write the SVG file: Is a directory"},
      {"plan " + maze + " --svg " + (dir / "missing" / "x.svg").string(),
       "cannot write the SVG file: No such file or directory"},
      {"plan " + maze + " --json /dev/full", "/dev/full: cannot write the JSON output"},
      {"cspace " + maze + " --json /dev/full", "/dev/full: cannot write the JSON output"},
      {"plan " + maze + " --weight inf", "option weight=inf"},
      {"plan " + maze + " --weight nan", "option weight=nan"},
      {"plan /dev/zero", "/dev/zero: larger than the supported 64 MiB"},
      {"plan " + dir.string(), dir.string() + ": is a directory, not a file"},
      {"arm " + dir.string(), dir.string() + ": is a directory, not a file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments);
    const CliRun run = run_polyplan(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("error: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected \"" << c.expected << "\" in: " << run.err;
  }
  // Standard output that cannot be written (a full disk) is the user's too.
  std::string command = "'";  // appended: GCC 12 takes "'" + string for an out-of-bounds copy
  command += POLYPLAN_CLI;
  command += "' plan " + maze + " --json - >/dev/full 2>/dev/null";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
  fs::remove_all(dir);
}
