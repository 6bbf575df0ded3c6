// polyplan scen, run as a user runs it: a MovingAI scenario file against the reference lengths.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace polyplan::test;
namespace fs = std::filesystem;

TEST(Scen, ArenaMatchesTheReference) {
  const std::string& data = kMovingAi;
  const CliRun run = run_polyplan("scen '" + data + "/maps/arena.map' '" + data +
                                  "/scenarios/arena.map.scen' --reference '" + data + "/reference/arena.csv' --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = nlohmann::json::parse(run.out);
  EXPECT_EQ(out["summary"]["queries"], 160);
  EXPECT_EQ(out["summary"]["mismatches"], 0);
  EXPECT_LT(out["summary"]["max_difference"].get<double>(), 1e-9);
  EXPECT_EQ(out["queries"].size(), 160u);
  EXPECT_NE(run.err.find("queries: 160/160"), std::string::npos);  // progress on stderr
}

// One preprocessing shared by the threads: the answers do not depend on how many there are; the
// summary says what the preprocessing cost.
TEST(Scen, ThreadsGiveTheAnswersOfOneAndTheSummaryTellsTheCosts) {
  const std::string& data = kMovingAi;
  const std::string files = "scen '" + data + "/maps/den312d.map' '" + data + "/scenarios/den312d.map.scen' --json -";
  const CliRun one = run_polyplan(files + " --threads 1"), two = run_polyplan(files + " --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto a = nlohmann::json::parse(one.out), b = nlohmann::json::parse(two.out);
  ASSERT_EQ(a["queries"].size(), 320u);
  ASSERT_EQ(b["queries"].size(), 320u);
  for (std::size_t i = 0; i < 320; ++i) {
    EXPECT_EQ(a["queries"][i]["found"], b["queries"][i]["found"]) << i;
    EXPECT_EQ(a["queries"][i]["length"], b["queries"][i]["length"]) << i;
  }
  EXPECT_EQ(a["summary"]["threads"], 1);
  EXPECT_EQ(b["summary"]["threads"], 2);
  for (const char* key : {"mean_us", "median_us", "preprocess_seconds", "index_mb", "peak_memory_mb", "batch_seconds"})
    EXPECT_GT(b["summary"][key].get<double>(), 0) << key;
  EXPECT_EQ(b["summary"]["distance_table"], true);
  EXPECT_EQ(b["summary"]["roadmap_vertices"], 187);
  // 0 is one thread per core, as the default says (and as benchmark's --threads 0); past 256 is refused.
  const CliRun every_core = run_polyplan(files + " --threads 0");
  ASSERT_EQ(every_core.exit_code, 0) << every_core.err;
  EXPECT_GE(nlohmann::json::parse(every_core.out)["summary"]["threads"].get<int>(), 1);
  const CliRun too_many = run_polyplan(files + " --threads 257");
  EXPECT_EQ(too_many.exit_code, 2);
  EXPECT_NE(too_many.err.find("--threads 257: expected a whole number in [0, 256]"), std::string::npos) << too_many.err;
}

TEST(Scen, BadInputIsOneLineAndExitTwo) {
  const std::string& data = kMovingAi;
  const CliRun run = run_polyplan("scen '" + data + "/maps/arena.map' no_such.scen");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("no_such.scen: cannot open file"), std::string::npos) << run.err;
}

// scen answered queries outside the map, with negative coordinates or for another map size,
// where grid refused them; and a reference index of -1 or 3·10^8 crashed it or took gigabytes.
TEST(Scen, QueriesAndReferencesThatDoNotFitTheMapAreRefused) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("polyplan_scen_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    std::string quoted = "'";  // appended: GCC 12 takes "'" + string for an out-of-bounds copy
    quoted += (dir / name).string();
    return quoted + "'";
  };
  const std::string map = write("m.map", "type octile\nheight 3\nwidth 4\nmap\n....\n.@@.\n....\n");
  const std::string good = write("good.scen", "version 1\n0\tm.map\t4\t3\t0\t0\t3\t2\t3.82843\n");
  struct Case {
    std::string arguments, expected;
  };
  const std::vector<Case> cases = {
      {map + " " + write("outside.scen", "version 1\n0\tm.map\t4\t3\t0\t0\t7\t2\t7\n"),
       "line 2: goal (7, 2) is outside the 4x3 map"},
      {map + " " + write("negative.scen", "version 1\n0\tm.map\t4\t3\t-1\t0\t3\t2\t4\n"),
       "line 2: start (-1, 0) is outside the 4x3 map"},
      {map + " " + write("other.scen", "version 1\n0\tm.map\t5\t3\t0\t0\t3\t2\t4\n"),
       "line 2: the query is for a 5x3 map"},
      {map + " " + good + " --reference " + write("minus.csv", "index,length\n-1,5\n"),
       "line 2: expected 'index,length'"},
      {map + " " + good + " --reference " + write("far.csv", "index,length\n300000000,5\n"),
       "line 2: index 300000000 is beyond the scenario file's 1 queries"},
      {write("terrain.map", "type octile\nheight 1\nwidth 2\nmap\n.?\n") + " " + good,
       "row 0, column 1: unknown terrain '?'"},
      {write("huge.map", "type octile\nheight 100000\nwidth 100000\nmap\n") + " " + good, "at most 67108864 cells"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments);
    const CliRun run = run_polyplan("scen " + c.arguments);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected \"" << c.expected << "\" in: " << run.err;
  }
  EXPECT_EQ(run_polyplan("scen " + map + " " + good).exit_code, 0);
  fs::remove_all(dir);
}
