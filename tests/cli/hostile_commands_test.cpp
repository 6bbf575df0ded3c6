// The hostile inputs of the hardening issues, one command line each (tests/data/hostile/
// commands.tsv): each must exit as the table says, within a time limit and (outside the
// sanitizers, whose shadow memory needs the address space) a 4 GiB memory cap. Exit 2 is one line
// on stderr containing the expected text; exit 0 prints it on stdout. Never a crash, an abort,
// exit 3 with a library's message, or a silent success.
#include "cli_runner.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace polyplan::test {
namespace {

namespace fs = std::filesystem;

struct HostileCase {
  int line = 0;
  int exit_code = 0;
  std::string expected, arguments;
};

void PrintTo(const HostileCase& c, std::ostream* os) { *os << "line " << c.line << ": " << c.arguments; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The table: EXIT <tab> EXPECTED <tab> ARGUMENTS; '#' starts a comment line.
std::vector<HostileCase> hostile_cases() {
  std::ifstream in(kSource + "/tests/data/hostile/commands.tsv");
  std::vector<HostileCase> cases;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (text.empty() || text[0] == '#') continue;
    const auto first = text.find('\t'), second = text.find('\t', first + 1);
    if (second == std::string::npos)
      throw std::runtime_error("commands.tsv line " + std::to_string(line) + ": 3 columns");
    cases.push_back(
        {line, std::stoi(text.substr(0, first)), text.substr(first + 1, second - first - 1), text.substr(second + 1)});
  }
  return cases;
}

class HostileCommand : public ::testing::TestWithParam<HostileCase> {};

TEST_P(HostileCommand, ExitsAsTheTableSays) {
  const HostileCase& c = GetParam();
  const fs::path tmp =
      fs::temp_directory_path() / ("polyplan_hostile_" + std::to_string(::getpid()) + "_" + std::to_string(c.line));
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  std::string arguments = replaced(c.arguments, "{data}", kSource + "/data");
  arguments = replaced(arguments, "{tests}", kSource + "/tests/data");
  arguments = replaced(arguments, "{tmp}", tmp.string());
  SCOPED_TRACE("commands.tsv line " + std::to_string(c.line) + ": polyplan " + arguments);
  const CliRun run = run_polyplan(arguments, {.seconds = 120, .memory_kb = POLYPLAN_MEMORY_CAP ? 4u << 20 : 0u});
  EXPECT_EQ(run.exit_code, c.exit_code) << run.err;
  if (c.exit_code == 2) {
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected \"" << c.expected << "\" in: " << run.err;
  } else {
    EXPECT_NE(run.out.find(c.expected), std::string::npos) << "expected \"" << c.expected << "\" in: " << run.out;
  }
  fs::remove_all(tmp);
}

INSTANTIATE_TEST_SUITE_P(Table, HostileCommand, ::testing::ValuesIn(hostile_cases()),
                         [](const auto& info) { return "line_" + std::to_string(info.param.line); });

// Threads the system cannot start (here: no address space for their stacks) shrink the pool with
// a message; the experiment still runs every run. 240 runs on 200 threads asked: their stacks alone
// (8 MB each) would take 1.6 GB of the 1.2 GB allowed, however soon the first runs end; malloc's
// arenas kept to 2, so that their 64 MB reservations do not take the runs' memory first.
TEST(HostileThreads, ThreadsThatCannotStartShrinkThePool) {
  if (!POLYPLAN_MEMORY_CAP) GTEST_SKIP() << "the sanitizers reserve the address space the cap would take";
  const fs::path out = fs::temp_directory_path() / ("polyplan_hostile_threads_" + std::to_string(::getpid()));
  fs::create_directories(out);
  std::string seeds;
  for (int seed = 1; seed <= 120; ++seed) seeds += (seed > 1 ? ", " : "") + std::to_string(seed);
  std::ofstream(out / "many_runs.json")
      << R"({"name": "many-runs", "problems": [{"name": "3R", "file": ")" << kSource
      << R"(/data/arms/three_link_forest.json"}], "planners": [{"name": "prm", "planner": "prm"},
          {"name": "rrtconnect", "planner": "rrtconnect"}], "seeds": [)"
      << seeds << R"(], "time_limit": 0.2})";
  ::setenv("MALLOC_ARENA_MAX", "2", 1);
  const CliRun run = run_polyplan("benchmark '" + (out / "many_runs.json").string() + "' --threads 200 --out '" +
                                      (out / "results").string() + "'",
                                  {.memory_kb = 1200000});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find(
                "threads asked could start (the system's limits on threads and memory); the runs went on with those"),
            std::string::npos)
      << run.err;
  EXPECT_NE(slurp(out / "results" / "results.json").find("\"runs\""), std::string::npos);
  ::unsetenv("MALLOC_ARENA_MAX");
  fs::remove_all(out);
}

// Past --max-memory-mb an allocation fails, and the program says so in one line, exit 2.
TEST(HostileLimits, AMemoryBudgetEndsTheProgramWithOneLine) {
  if (!POLYPLAN_MEMORY_CAP) GTEST_SKIP() << "the sanitizers reserve the address space the cap would take";
  const fs::path map =
      fs::temp_directory_path() / ("polyplan_hostile_open_2000_" + std::to_string(::getpid()) + ".map");
  {
    std::ofstream out(map);
    out << "type octile\nheight 2000\nwidth 2000\nmap\n";
    for (int row = 0; row < 2000; ++row) out << std::string(2000, '.') << '\n';
  }
  const CliRun run = run_polyplan("replan '" + map.string() + "' --start 1,1 --goal 1990,1990 --max-memory-mb 100");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("out of memory: the command needed more than it may take (100 MB, --max-memory-mb"),
            std::string::npos)
      << run.err;
  fs::remove(map);
}

}  // namespace
}  // namespace polyplan::test
