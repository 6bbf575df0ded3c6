// polyplan benchmark EXPERIMENT.json [--out DIR] [--threads N] [--seeds N] [--time-limit S]
// Every cell of an experiment (docs/benchmark.md: problems × planner entries × seeds), run on N
// threads with a progress bar on stderr, and into DIR: results.log (OMPL's benchmark log, for
// ompl_benchmark_statistics.py and Planner Arena), results.json, results.csv, tables.md, and per
// problem the pictures PROBLEM-success.svg, PROBLEM-cost.svg (anytime planners), PROBLEM-time.svg
// and PROBLEM-length.svg. --seeds and --time-limit scale an experiment down (a quick look, a test).
#include "cli/command.hpp"
#include "cli/option_flags.hpp"
#include "cli/progress.hpp"

#include <polyplan/draw/experiment_outputs.hpp>
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_runner.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <iostream>
#include <thread>

namespace polyplan::cli {
namespace {

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

int run_benchmark(const BenchmarkCommand& command) {
  const BenchmarkScale scale = command.scale->parse();
  Experiment experiment = read_experiment(command.experiment);
  scale_experiment(experiment, scale.seeds, scale.time_limit, "--seeds", "--time-limit");
  const std::string out = command.out.empty() ? file_name_part(experiment.name) + "_results" : command.out;
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
                 "warning: only %u of the %u threads asked could start (the system's limits on threads and memory); "
                 "the runs went on "
                 "with those\n",
                 results.threads, threads);

  const std::vector<std::string> written = write_experiment_outputs(out, experiment, results);

  std::size_t solved = 0;
  for (const ExperimentRun& run : results.runs) solved += run.solved;
  std::cout << experiment.name << ": " << results.runs.size() << " runs, " << solved << " solved, "
            << results.total_seconds << " s\n";
  for (const std::string& path : written) std::cout << "wrote " << path << '\n';
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
