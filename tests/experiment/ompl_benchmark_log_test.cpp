// The OMPL benchmark log of a small hand-made experiment, against the text worked out by hand
// from OMPL's Benchmark::saveResultsToStream (tests/data/experiment/tiny.log), and read back by the
// tests' own reader of the format (ompl_log_parser.hpp, written from ompl_benchmark_statistics.py).
#include "experiment/ompl_log_parser.hpp"

#include <polyplan/experiment/ompl_benchmark_log.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace polyplan {
namespace {

const std::string kSource = POLYPLAN_SOURCE_DIR;

ExperimentRun run(std::size_t planner, std::uint64_t seed, PlanStatus status, double seconds, double setup,
                  double length, std::vector<SolutionImprovement> improvements) {
  ExperimentRun r;
  r.problem = 0, r.planner = planner, r.seed = seed;
  r.status = status;
  r.solved = status == PlanStatus::solved;
  r.seconds = seconds, r.setup_seconds = setup;
  r.length = length;
  r.improvements = std::move(improvements);
  if (!r.solved) r.why_not = "the tree did not reach the goal within the time limit (2 s)";
  return r;
}

// Two planner entries (one anytime) on one problem, two seeds each.
std::pair<Experiment, ExperimentResults> tiny() {
  Experiment e;
  e.name = "tiny test";
  e.source = "tiny.json";
  e.problems = {{"office", "data/worlds/office.json", ProblemKind::world, "start/goal"}};
  e.planners = {{"rrt-e1", "rrt", {{"extend", "e1"}}, false}, {"rrtstar-k3", "rrtstar", {{"k", "3"}}, true}};
  e.seeds = {1, 2};
  e.time_limit = 2;
  e.cost_times = {1, 2};
  ExperimentResults r;
  r.host = "testhost";
  r.started_at = "2026-12-05T20:00:00";
  r.threads = 1;
  r.total_seconds = 4.5;
  r.runs.push_back(run(0, 1, PlanStatus::solved, 0.25, 0.125, 10.5, {{0.25, 10.5}}));
  r.runs.back().facts.set(RoadmapFacts::kind, "rrt");  // a word: results.json's, not the log's
  r.runs.back().facts.set(SamplingFacts::samples, 40);
  r.runs.back().facts.set(SamplingFacts::seed, 1);  // the run's own "seed" property already has the column
  r.runs.back().facts.set(SamplingFacts::raw_length, 12.75);
  r.runs.push_back(run(0, 2, PlanStatus::limit, 2, 0.125, 0, {}));
  r.runs.back().facts.set(SamplingFacts::samples, 100);
  r.runs.push_back(run(1, 1, PlanStatus::solved, 2, 0.5, 9, {{0.5, 11}, {1.5, 9.5}, {2, 9}}));
  r.runs.back().facts.set(SamplingFacts::tree_size, 300);
  r.runs.push_back(run(1, 2, PlanStatus::solved, 2, 0.5, 8.25, {{1.25, 8.25}}));
  r.runs.back().facts.set(SamplingFacts::tree_size, 280);
  r.runs.back().facts.set(FactKey<std::int64_t>{"order"}, 7);  // an SQL word: the script's ALTER TABLE would fail on it
  return {e, r};
}

std::string without_first_line(const std::string& text) { return text.substr(text.find('\n') + 1); }

TEST(OmplBenchmarkLog, WritesOmplsFormatExactly) {
  const auto [experiment, results] = tiny();
  std::ostringstream written;
  write_ompl_benchmark_log(written, experiment, results);
  std::ifstream frozen(kSource + "/tests/data/experiment/tiny.log");
  std::ostringstream expected;
  expected << frozen.rdbuf();
  ASSERT_FALSE(expected.str().empty());
  EXPECT_EQ(written.str().rfind("polyplan version ", 0), 0u);  // the script's "version" column
  EXPECT_EQ(without_first_line(written.str()), without_first_line(expected.str()));
}

TEST(OmplBenchmarkLog, ReadsBackWithTheCountsAndTimesOfTheRuns) {
  const auto [experiment, results] = tiny();
  std::stringstream written;
  write_ompl_benchmark_log(written, experiment, results);
  const test::OmplLog log = test::parse_ompl_log(written);
  EXPECT_EQ(log.experiment, "tiny_test");
  EXPECT_EQ(log.runs_per_planner, 2);
  EXPECT_EQ(log.time_limit, 2);
  ASSERT_EQ(log.planners.size(), 2u);
  EXPECT_EQ(log.enums.at("status").size(), 9u);
  std::size_t next = 0;
  for (const test::OmplLogPlanner& planner : log.planners) {
    const auto time = std::find(planner.columns.begin(), planner.columns.end(), "time") - planner.columns.begin();
    ASSERT_LT(static_cast<std::size_t>(time), planner.columns.size());
    for (const auto& values : planner.runs) EXPECT_EQ(std::stod(values[time]), results.runs[next++].seconds);
  }
  EXPECT_EQ(next, results.runs.size());
  EXPECT_TRUE(log.planners[0].progress.empty());
  ASSERT_EQ(log.planners[1].progress.size(), 2u);
  EXPECT_EQ(log.planners[1].progress_columns, (std::vector<std::string>{"best_cost", "time"}));
}

TEST(OmplBenchmarkLog, ColumnsAreNamesTheScriptCanAdd) {
  EXPECT_EQ(ompl_column_name("roadmap.vertices"), "roadmap_vertices");
  EXPECT_EQ(ompl_column_name("first solution time"), "first_solution_time");
  EXPECT_EQ(ompl_column_name("goal-bias"), "goal_bias");
  EXPECT_EQ(ompl_column_name("order"), "order_value");
  EXPECT_EQ(ompl_column_name("id"), "id_value");
  EXPECT_EQ(ompl_column_name("2d"), "fact_2d");
}

TEST(OmplBenchmarkLog, PlannerNamesAreOneWordPerProblemAndEntry) {
  auto [experiment, results] = tiny();
  experiment.problems[0].name = "my office";
  EXPECT_EQ(ompl_planner_name(experiment, 0, 1), "rrtstar-k3@my_office");
}

}  // namespace
}  // namespace polyplan
