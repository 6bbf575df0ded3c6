#pragma once
// One problem of an experiment, read from its file: what the registry's planners are built from
// (a world's C-space, the world itself for rotating robots and cars, an arm problem) and the
// query they are asked. The experiment's reader uses it to check planners and options against
// the registry; the runner to run a cell. Each thread reads its own: planners and the exact
// numbers under them are not shared between threads.
#include <polyplan/experiment/experiment.hpp>
#include <polyplan/plan/planner_options.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace polyplan {

class ExperimentProblemFile {
 public:
  // Reads `problem.file` as its kind says; InputError from the world or arm reader.
  explicit ExperimentProblemFile(const ExperimentProblem& problem);
  ~ExperimentProblemFile();
  ExperimentProblemFile(ExperimentProblemFile&&) noexcept;
  ExperimentProblemFile& operator=(ExperimentProblemFile&&) noexcept;

  // The names of the file's queries, in order ("start/goal", "queries[1]", an arm query's name).
  std::vector<std::string> query_names() const;

  // The options of the registry's planner `name` in this problem's space (a car world's, a
  // rotating robot's, an arm's, ...); nullptr when it does not plan such problems.
  const std::vector<OptionInfo>* planner_options(const std::string& name) const;
  // Whether that planner improves its solution until its limit (PlannerEntry::anytime).
  bool planner_anytime(const std::string& name) const;
  // The planners of this problem's spaces, for messages: "visibility, raster, ...".
  std::string planner_names() const;
  // InputError when the planner cannot plan for this problem's robot at all (a car planner for a
  // robot that does not steer, a translating planner for a car).
  void require_planner_for_robot(const std::string& name) const;

  // Builds `planner` with `options` (the registry's parsing: InputError for a value it refuses).
  void build(const std::string& planner, const OptionValues& options) const;

  // One run: `planner` built with `options`, then asked the query named `query` once, timed.
  // Fills every field of `run` but its indices and seed.
  void run(const std::string& planner, const OptionValues& options, const std::string& query, ExperimentRun& run) const;

 private:
  struct Loaded;
  template <class Read>
  auto read_entry(const std::string& name, Read read) const;
  std::unique_ptr<Loaded> loaded_;
};

// `options` with the experiment's seed and time limit as the planner's "seed" and "time" options,
// for the planners that have them.
OptionValues options_for_run(const OptionValues& options, const std::vector<OptionInfo>& known, std::uint64_t seed,
                             double time_limit);

}  // namespace polyplan
