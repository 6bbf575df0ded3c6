// The arm grid planner at fine resolutions (issue 14's table): `polyplan arm FILE --method grid
// --resolution R` on the 4R and 3R forests at 5, 2 and 1 degrees, each run a process of its own,
// measured from outside as the issue measured it: cells evaluated and moves checked (from the
// JSON answer), CPU seconds (user + system) and peak resident memory (wait4's rusage).
//
// Side by side, in the same run:
//  --earlier BIN   an earlier polyplan (e.g. a build of the release before this change) on the same
//                  problems, within --limit seconds and --memory-limit GB each (a run beyond them
//                  is stopped and shown as such; the earlier release needs 6.6 GB and 10 minutes
//                  for the 4R forest at 2 degrees);
//  --exact         this polyplan with --coarse 0: the whole grid, the proved shortest, to show what
//                  the corridor's paths give away (nothing, on these problems).
//
// A plain program, not Google Benchmark: it times whole planning runs of the command-line program.
// Usage: arm_grid_table [--resolutions 5,2,1] [--earlier BIN] [--exact] [--limit 600] [--memory-limit 16]
#include "spawn_quiet.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Run {
  enum class End { answered, time_limit, failed } end = End::failed;
  double cpu_seconds = 0, peak_mb = 0;
  nlohmann::json answer;
};

// Runs `program args...` with its answer written to a JSON file; stopped after `limit` seconds of
// wall time, and refused memory beyond `memory_gb` (its allocations fail: it stops, it is not
// the machine that runs out).
Run run(const std::string& program, std::vector<std::string> args, double limit, double memory_gb) {
  const std::string json = "/tmp/arm_grid_table_" + std::to_string(getpid()) + ".json";
  std::remove(json.c_str());
  args.insert(args.begin(), program);
  args.push_back("--json");
  args.push_back(json);
  const pid_t child = polyplan::bench::spawn_quiet(args, [memory_gb] {
    const auto bytes = static_cast<rlim_t>(memory_gb * 1024 * 1024 * 1024);
    const rlimit cap{bytes, bytes};
    setrlimit(RLIMIT_AS, &cap);
  });
  Run result;
  const auto began = std::chrono::steady_clock::now();
  int status = 0;
  rusage usage{};
  for (;;) {
    const pid_t done = wait4(child, &status, WNOHANG, &usage);
    if (done == child) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() > limit) {
      kill(child, SIGKILL);
      wait4(child, &status, 0, &usage);
      result.end = Run::End::time_limit;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  result.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  result.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024;  // KB on Linux
  if (result.end == Run::End::time_limit) return result;
  std::ifstream in(json);
  if (WIFEXITED(status) && in) {
    result.answer = nlohmann::json::parse(in, nullptr, false);
    if (!result.answer.is_discarded()) result.end = Run::End::answered;
  }
  std::remove(json.c_str());
  return result;
}

std::string cell(const Run& r) {
  char text[200];
  if (r.end == Run::End::time_limit) {
    std::snprintf(text, sizeof text, "stopped at the time limit (%.0f s CPU, %.0f MB)", r.cpu_seconds, r.peak_mb);
    return text;
  }
  if (r.end == Run::End::failed) {
    std::snprintf(text, sizeof text, "failed (%.0f s CPU, %.0f MB: out of memory?)", r.cpu_seconds, r.peak_mb);
    return text;
  }
  const auto& a = r.answer;
  const auto count = [&](const char* name) { return a.contains(name) ? a[name].get<double>() : 0.0; };
  const auto thousands = [](double x) {
    char t[32];
    if (x >= 1e6) std::snprintf(t, sizeof t, "%.2f M", x / 1e6);
    else std::snprintf(t, sizeof t, "%.0f k", x / 1e3);
    return std::string(t);
  };
  std::string outcome = "no path";
  const std::string why = a.value("why_not", "");
  if (why.rfind("stopped after", 0) == 0) outcome = "stopped at the budget";
  if (a.value("found", false)) {
    std::snprintf(text, sizeof text, "%.3f", a["length"].get<double>());
    outcome = text;
    if (a["grid"].contains("shortest")) outcome += a["grid"]["shortest"] == "proved" ? " proved" : " corridor";
  }
  std::snprintf(text, sizeof text, "%s / %s / %.1f s / %.0f MB: %s", thousands(count("cells_evaluated")).c_str(),
                thousands(count("moves_checked")).c_str(), r.cpu_seconds, r.peak_mb, outcome.c_str());
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The arm grid planner at 5, 2 and 1 degrees: cells / moves / CPU / peak memory, one process per run"};
  std::vector<double> resolutions{5, 2, 1};
  std::string earlier;
  bool exact = false;
  double limit = 600, memory_gb = 16;
  app.add_option("--resolutions", resolutions, "grid steps in degrees")->delimiter(',');
  app.add_option("--earlier", earlier, "an earlier polyplan program to run side by side");
  app.add_flag("--exact", exact, "also search the whole grid (--coarse 0): the proved shortest");
  app.add_option("--limit", limit, "seconds of wall time per run");
  app.add_option("--memory-limit", memory_gb, "GB of address space per run");
  CLI11_PARSE(app, argc, argv);

  const std::vector<std::string> problems{"four_link_forest", "four_link_eight", "three_link_forest"};
  struct Program {
    std::string name, path;
    std::vector<std::string> extra;
  };
  std::vector<Program> programs{{"polyplan", POLYPLAN_CLI, {}}};
  if (exact) programs.push_back({"polyplan --coarse 0", POLYPLAN_CLI, {"--coarse", "0"}});
  if (!earlier.empty()) programs.push_back({"earlier", earlier, {}});

  std::printf("cells evaluated / moves checked / CPU / peak memory: length\n\n| problem | program |");
  for (const double r : resolutions) std::printf(" %g° |", r);
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < resolutions.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const std::string& problem : problems)
    for (const Program& program : programs) {
      std::printf("| `%s` | %s |", problem.c_str(), program.name.c_str());
      std::fflush(stdout);
      for (const double r : resolutions) {
        char degrees[32];
        std::snprintf(degrees, sizeof degrees, "%g", r);
        std::vector<std::string> args{"arm",          std::string(POLYPLAN_DATA_DIR) + "/arms/" + problem + ".json",
                                      "--method",     "grid",
                                      "--resolution", degrees};
        args.insert(args.end(), program.extra.begin(), program.extra.end());
        std::printf(" %s |", cell(run(program.path, args, limit, memory_gb)).c_str());
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  return 0;
}
