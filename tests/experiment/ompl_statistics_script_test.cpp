// OMPL's own scripts/ompl_benchmark_statistics.py reads polyplan's log (the frozen
// tests/data/experiment/tiny.log, which ompl_benchmark_log_test checks the writer gives) into its
// SQLite database, with every run and its time. Skipped when python3 or the script is not found:
// Debian's libompl-dev does not ship the script; OMPL_BENCHMARK_STATISTICS=/path/to/it runs it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::string find_script() {
  if (const char* given = std::getenv("OMPL_BENCHMARK_STATISTICS"); given && fs::exists(given)) return given;
  for (const char* place :
       {"/usr/share/ompl/scripts/ompl_benchmark_statistics.py",
        "/usr/local/share/ompl/scripts/ompl_benchmark_statistics.py", "/usr/bin/ompl_benchmark_statistics.py",
        "/usr/local/bin/ompl_benchmark_statistics.py", "/usr/share/ompl/demos/ompl_benchmark_statistics.py"})
    if (fs::exists(place)) return place;
  return "";
}

// Standard output of a shell command, and whether it exited 0.
std::pair<bool, std::string> output_of(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return {false, out};
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  return {::pclose(pipe) == 0, out};
}

TEST(OmplStatisticsScript, ReadsTheLogIntoItsDatabaseWithEveryRun) {
  const std::string script = find_script();
  if (script.empty())
    GTEST_SKIP() << "ompl_benchmark_statistics.py not found (set OMPL_BENCHMARK_STATISTICS to run this test)";
  if (!output_of("python3 -c 'import sqlite3'").first) GTEST_SKIP() << "python3 with sqlite3 not found";
  const fs::path dir = fs::temp_directory_path() / ("polyplan_ompl_script_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string log = std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/experiment/tiny.log";
  const std::string database = (dir / "tiny.db").string();
  const auto [read, said] =
      output_of("cd '" + dir.string() + "' && python3 '" + script + "' '" + log + "' -d '" + database + "' 2>&1");
  ASSERT_TRUE(read) << said;
  const auto [queried, rows] = output_of(
      "python3 -c \"import sqlite3, sys\n"
      "c = sqlite3.connect(sys.argv[1])\n"
      "for name, runs, time in c.execute('SELECT plannerConfigs.name, count(*), sum(runs.time) FROM runs JOIN "
      "plannerConfigs "
      "ON runs.plannerid = plannerConfigs.id GROUP BY plannerConfigs.name ORDER BY plannerConfigs.name'):\n"
      "    print(name, runs, repr(time))\n"
      "print(c.execute('SELECT name, runcount, timelimit FROM experiments').fetchall())\" '" +
      database + "'");
  fs::remove_all(dir);
  ASSERT_TRUE(queried) << rows;
  EXPECT_EQ(rows, "rrt-e1@office 2 2.25\nrrtstar-k3@office 2 4.0\n[('tiny_test', 2, 2.0)]\n");
}

}  // namespace
