#pragma once
// An experiment (`polyplan benchmark`): problems, planner entries with their options, seeds, a time
// limit and the times at which anytime planners' costs are sampled; and what its runs gave. Every
// cell (problem × planner entry × seed) is one run. Plain data: the reader is
// experiment/experiment_file.hpp, the runner experiment/experiment_runner.hpp, the writers
// experiment/ompl_benchmark_log.hpp, experiment/experiment_results.hpp and
// experiment/experiment_tables.hpp.
#include <polyplan/plan/plan_report.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace polyplan {

// What a problem file holds: a polygon world (a translating, rotating or car robot) or an arm.
enum class ProblemKind { world, arm };

struct ExperimentProblem {
  std::string name;
  std::string file;  // as the experiment names it, resolved against the experiment file's folder
  ProblemKind kind = ProblemKind::world;
  std::string query;  // the name of the file's query that is planned (its first when not given)
};

// One entry of the experiment's planners: a registry planner with one set of options.
struct ExperimentPlanner {
  std::string name;      // the entry's own name ("rrt-bias0.2"), unique in the experiment
  std::string planner;   // the registry's name ("rrt")
  OptionValues options;  // as `polyplan planners` names them, without seed and time (the experiment sets those)
  bool anytime = false;  // the registry's planner improves its solution until its limit (PlannerEntry::anytime)
};

struct Experiment {
  std::string name;
  std::string source;  // the experiment file, for messages
  std::vector<ExperimentProblem> problems;
  std::vector<ExperimentPlanner> planners;
  std::vector<std::uint64_t> seeds;
  double time_limit = 10;  // seconds per run: the planners' "time" option, where they have one
  // Increasing times in (0, time_limit] at which the best cost found so far is read.
  std::vector<double> cost_times;

  std::size_t cells() const { return problems.size() * planners.size() * seeds.size(); }
};

// What one run gave: the planner built for its problem with its options and seed, and asked the
// problem's query once.
struct ExperimentRun {
  std::size_t problem = 0, planner = 0;  // indices into Experiment::problems and ::planners
  std::uint64_t seed = 0;
  PlanStatus status = PlanStatus::not_found;
  bool solved = false;
  std::string why_not;
  double seconds = 0;        // the query (Planner::plan), wall clock
  double setup_seconds = 0;  // building the planner for the problem
  double length = 0;         // when solved
  // Each better solution with its time, the last one `length`; a planner that reports none (it
  // answers once) has its one solution at `seconds`. Empty when not solved.
  std::vector<SolutionImprovement> improvements;
  Facts facts;

  // The best length found by `seconds` into the query; +infinity before the first solution.
  double cost_at(double seconds) const;
  // When the first solution was found; +infinity when none was.
  double first_solution_seconds() const;
};

struct ExperimentResults {
  std::vector<ExperimentRun> runs;  // in cell order: problem, then planner entry, then seed
  double total_seconds = 0;         // wall clock of the whole experiment
  unsigned threads = 1;
  std::string started_at;  // "2026-12-05T19:55:02" (local time), as OMPL's logs say it
  std::string host;
};

// The experiment cut to its first `seeds` seeds (0: all of them) and given another time limit (0:
// its own), its cost times scaled with it (the curve keeps its shape): a quick look, a test.
// InputError "<seeds_name> N: the experiment has M seeds" when it has fewer, and "<limit_name> T:
// ..." for a time limit that scales the cost times out of what doubles hold apart. The names are
// the caller's spelling of the two (the program's --seeds, Python's seeds).
void scale_experiment(Experiment& experiment, std::size_t seeds, double time_limit,
                      const std::string& seeds_name = "seeds", const std::string& limit_name = "time_limit");

}  // namespace polyplan
