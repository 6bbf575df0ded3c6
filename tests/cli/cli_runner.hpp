#pragma once
// Runs the polyplan program as a user does (a shell, files for stdout and stderr) for the CLI
// tests: every cli_tests source includes this one runner.
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace polyplan::test {

inline const std::string kSource = POLYPLAN_SOURCE_DIR;

struct CliRun {
  int exit_code;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Bounds on a run: seconds before `timeout` stops it, and its address space in KiB (`ulimit -v`;
// never under the sanitizers, whose shadow memory reserves terabytes); 0: none.
struct RunLimits {
  int seconds = 0;
  std::size_t memory_kb = 0;
};

// `arguments` is pasted into a shell command line: quote paths with '...'.
inline CliRun run_polyplan(const std::string& arguments, RunLimits limits = {}) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("polyplan_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string command = limits.memory_kb ? "ulimit -v " + std::to_string(limits.memory_kb) + "; " : "";
  if (limits.seconds > 0) command += "timeout " + std::to_string(limits.seconds) + " ";
  command += "'";  // appended: GCC 12 takes "'" + string for an out-of-bounds copy
  for (const std::string& piece :
       {std::string(POLYPLAN_CLI), std::string("' "), arguments, std::string(" >'"), (dir / "out").string(),
        std::string("' 2>'"), (dir / "err").string(), std::string("' </dev/null")})
    command += piece;
  const int status = std::system(command.c_str());
  CliRun run{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurp(dir / "out"), slurp(dir / "err")};
  fs::remove_all(dir);
  return run;
}

// Quoted paths of the shipped data, for command lines.
inline std::string world(const std::string& name) { return "'" + kSource + "/data/worlds/" + name + "'"; }
inline std::string arm_file(const std::string& name) { return "'" + kSource + "/data/arms/" + name + "'"; }
inline std::string path_file(const std::string& name) { return "'" + kSource + "/tests/data/paths/" + name + "'"; }
inline const std::string kMovingAi = kSource + "/data/movingai";

inline std::size_t lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace polyplan::test
