// polyplan benchmark EXPERIMENT.json [--out DIR] [--threads N] [--seeds N] [--time-limit S]
// Every cell of an experiment (docs/benchmark.md: problems × planner entries × seeds), run on N
// threads with a progress bar on stderr, and into DIR: results.log (OMPL's benchmark log, for
// ompl_benchmark_statistics.py and Planner Arena), results.json, results.csv, tables.md, and per
// problem the pictures PROBLEM-success.svg, PROBLEM-cost.svg (anytime planners), PROBLEM-time.svg
// and PROBLEM-length.svg. --seeds and --time-limit scale an experiment down (a quick look, a test).
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/draw/experiment_plots.hpp>
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_results.hpp>
#include <polyplan/experiment/experiment_runner.hpp>
#include <polyplan/experiment/experiment_statistics.hpp>
#include <polyplan/experiment/experiment_tables.hpp>
#include <polyplan/experiment/ompl_benchmark_log.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <thread>

namespace polyplan::cli {
namespace {

namespace fs = std::filesystem;

// --threads, --seeds and --time-limit.
struct BenchmarkScale {
  unsigned threads = 1;
  std::size_t seeds = 0;  // 0: all of the experiment's
  double time_limit = 0;  // 0: the experiment's
};
OptionTable<BenchmarkScale> benchmark_scale_table() {
  OptionTable<BenchmarkScale> table;
  return table
      .add("threads", &BenchmarkScale::threads, "runs at a time, each alone in its thread (0: one per core)",
           in_range(0, 256))
      .add("seeds", &BenchmarkScale::seeds, "only the experiment's first N seeds (0: all)", at_least(0))
      .add("time-limit", &BenchmarkScale::time_limit,
           "seconds per run instead of the experiment's, its cost_times scaled alike (0: the experiment's)",
           at_least(0));
}

struct BenchmarkCommand {
  std::string experiment;
  std::string out;
  std::unique_ptr<CommandOptions<BenchmarkScale>> scale;
};

// The experiment cut to the first `seeds` seeds and given another time limit, its cost times
// scaled with it (the curve keeps its shape).
void scale_down(Experiment& e, const BenchmarkScale& command) {
  if (command.seeds) {
    if (command.seeds > e.seeds.size())
      throw InputError("--seeds " + std::to_string(command.seeds) + ": the experiment has " +
                       std::to_string(e.seeds.size()) + " seeds");
    e.seeds.resize(command.seeds);
  }
  if (command.time_limit > 0) {
    for (double& t : e.cost_times) t *= command.time_limit / e.time_limit;
    e.time_limit = command.time_limit;
  }
}

// A problem's name as part of a file name: letters, digits, '.', '-' and '_' kept.
std::string file_part(const std::string& name) {
  std::string part;
  for (char c : name) part += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  return part;
}

void write_text(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path);
  if (out) write(out);
  if (out) out.close();
  if (!out) throw InputError(path.string() + ": cannot write");
}

void write_picture(const svg::Drawing& drawing, const fs::path& path, std::vector<fs::path>& written) {
  try {
    drawing.write(path.string());
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  written.push_back(path);
}

int run_benchmark(const BenchmarkCommand& command) {
  const BenchmarkScale scale = command.scale->parse();
  Experiment experiment = read_experiment(command.experiment);
  scale_down(experiment, scale);
  const fs::path out = command.out.empty() ? fs::path(file_part(experiment.name) + "_results") : fs::path(command.out);
  std::error_code error;
  fs::create_directories(out, error);
  if (error || !fs::is_directory(out)) throw InputError("--out " + out.string() + ": cannot make the folder");
  const unsigned threads = scale.threads ? scale.threads : std::max(1u, std::thread::hardware_concurrency());

  std::fprintf(stderr,
               "%s: %zu runs (%zu problems x %zu planner entries x %zu seeds, %g s each at most) on %u thread(s)\n",
               experiment.name.c_str(), experiment.cells(), experiment.problems.size(), experiment.planners.size(),
               experiment.seeds.size(), experiment.time_limit, threads);
  Progress progress("runs");
  const ExperimentResults results =
      run_experiment(experiment, threads, [&](std::size_t done, std::size_t total) { progress.update(done, total); });
  if (results.threads < std::min<std::size_t>(threads, experiment.cells()))
    std::fprintf(stderr,
                 "warning: only %u of the %u threads asked could start (the system's limits); the runs went on "
                 "with those\n",
                 results.threads, threads);

  std::vector<fs::path> written{out / "results.log", out / "results.json", out / "results.csv", out / "tables.md"};
  write_text(written[0], [&](std::ostream& o) { write_ompl_benchmark_log(o, experiment, results); });
  write_json(experiment_results_json(experiment, results), written[1].string());
  write_text(written[2], [&](std::ostream& o) { write_experiment_results_csv(o, experiment, results); });
  write_text(written[3], [&](std::ostream& o) { write_experiment_tables(o, experiment, results); });
  const auto statistics = experiment_statistics(experiment, results);
  for (std::size_t problem = 0; problem < experiment.problems.size(); ++problem) {
    const std::string name = file_part(experiment.problems[problem].name);
    write_picture(success_rate_plot(experiment, problem, statistics[problem]), out / (name + "-success.svg"), written);
    if (auto cost = cost_over_time_plot(experiment, problem, statistics[problem]))
      write_picture(*cost, out / (name + "-cost.svg"), written);
    write_picture(box_plot(experiment, problem, statistics[problem], BoxPlotOf::time), out / (name + "-time.svg"),
                  written);
    write_picture(box_plot(experiment, problem, statistics[problem], BoxPlotOf::length), out / (name + "-length.svg"),
                  written);
  }

  std::size_t solved = 0;
  for (const ExperimentRun& run : results.runs) solved += run.solved;
  std::cout << experiment.name << ": " << results.runs.size() << " runs, " << solved << " solved, "
            << results.total_seconds << " s\n";
  for (const fs::path& path : written) std::cout << "wrote " << path.string() << '\n';
  return ok;
}

}  // namespace

void add_benchmark_command(CLI::App& app, Action& run) {
  auto command = std::make_shared<BenchmarkCommand>();
  CLI::App* benchmark = app.add_subcommand(
      "benchmark",
      "Run an experiment (problems x planner entries x seeds): OMPL benchmark log, JSON, CSV, tables and plots");
  benchmark->add_option("experiment", command->experiment, "experiment file (JSON; docs/benchmark.md)")->required();
  benchmark->add_option("--out", command->out, "folder for the results (default: NAME_results, NAME the experiment's)");
  command->scale = std::make_unique<CommandOptions<BenchmarkScale>>(*benchmark, benchmark_scale_table());
  benchmark->callback([command, &run] { run = [command] { return run_benchmark(*command); }; });
}

}  // namespace polyplan::cli
