#include <polyplan/experiment/experiment_runner.hpp>

#include <polyplan/experiment/experiment_problem.hpp>
#include <polyplan/plan/stopwatch.hpp>
#include <polyplan/plan/thread_pool.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <unistd.h>

namespace polyplan {
namespace {

std::string local_time_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &local);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0 || !name[0]) return "UNKNOWN";
  return name;
}

// What a thread keeps between its runs: the problem files it has read.
class Worker {
 public:
  explicit Worker(const Experiment& experiment) : experiment_(experiment), files_(experiment.problems.size()) {}

  ExperimentRun run(std::size_t cell) {
    const std::size_t seeds = experiment_.seeds.size(), entries = experiment_.planners.size();
    const std::size_t problem = cell / (seeds * entries), planner = cell / seeds % entries;
    const std::uint64_t seed = experiment_.seeds[cell % seeds];
    ExperimentRun run;
    try {
      run = run_cell(file(problem), experiment_.planners[planner], experiment_.problems[problem].query, seed,
                     experiment_.time_limit);
    } catch (const std::exception& e) {  // the problem file, read again here
      run.seed = seed;
      mark_failed(run, std::string("the run failed: ") + e.what());
    }
    run.problem = problem;
    run.planner = planner;
    return run;
  }

 private:
  const Problem& file(std::size_t problem) {
    if (!files_[problem]) {
      std::vector<std::string> warnings;  // unknown fields of a problem file are not the experiment's concern
      files_[problem] = std::make_unique<Problem>(Problem::read(experiment_.problems[problem].file, &warnings));
      files_[problem]->prepare();
    }
    return *files_[problem];
  }

  const Experiment& experiment_;
  std::vector<std::unique_ptr<Problem>> files_;
};

}  // namespace

ExperimentResults run_experiment(const Experiment& experiment, unsigned threads, const ExperimentProgress& progress) {
  ExperimentResults results;
  results.started_at = local_time_now();
  results.host = host_name();
  const std::size_t total = experiment.cells();
  results.threads = static_cast<unsigned>(std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(total, 1)));
  results.runs.resize(total);
  const Stopwatch whole;

  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex reporting;
  const auto work = [&](unsigned) {
    Worker worker(experiment);
    for (std::size_t cell = next++; cell < total; cell = next++) {
      ExperimentRun run = worker.run(cell);
      const std::lock_guard lock(reporting);
      results.runs[cell] = std::move(run);
      ++done;
      if (progress) progress(done, total);
    }
  };
  results.threads = run_on_threads(results.threads, work).started;  // fewer when the system cannot start them all
  results.total_seconds = whole.seconds();
  return results;
}

}  // namespace polyplan
