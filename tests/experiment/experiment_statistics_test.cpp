// Quartiles, means and whiskers of a sample, and the per-cell statistics the tables and plots read.
#include <polyplan/experiment/experiment_statistics.hpp>

#include <gtest/gtest.h>

#include <limits>

namespace polyplan {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(ExperimentStatistics, QuartilesInterpolateBetweenOrderStatistics) {
  const ValueSummary s = summarize({4, 1, 3, 2});
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.q1, 1.75);
  EXPECT_EQ(s.median, 2.5);
  EXPECT_EQ(s.q3, 3.25);
  EXPECT_EQ(s.max, 4);
  EXPECT_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.stddev, 1.2909944487358056, 1e-15);  // sample standard deviation
}

TEST(ExperimentStatistics, UnsolvedRunsCountAsInfinityInTheQuartilesOnly) {
  const ValueSummary s = summarize({1, 2, inf, inf});
  EXPECT_EQ(s.finite, 2u);
  EXPECT_EQ(s.mean, 1.5);
  EXPECT_EQ(s.median, inf);  // half the runs have none yet
  EXPECT_EQ(s.q1, 1.75);
}

TEST(ExperimentStatistics, WhiskersReachOneAndAHalfInterquartileRanges) {
  const ValueSummary s = summarize({1, 2, 3, 4, 5, 100});
  EXPECT_EQ(s.whisker_low, 1);
  EXPECT_EQ(s.whisker_high, 5);
  EXPECT_EQ(s.outliers, std::vector<double>{100});
}

TEST(ExperimentStatistics, CellsCountSuccessAndReadTheBestCostByEachTime) {
  Experiment e;
  e.problems = {{"p", "p.json", ProblemKind::world, "start/goal"}};
  e.planners = {{"a", "rrtstar", {}, true}};
  e.seeds = {1, 2};
  e.time_limit = 2;
  e.cost_times = {0.5, 1, 2};
  ExperimentResults r;
  ExperimentRun solved;
  solved.seed = 1, solved.solved = true, solved.status = PlanStatus::solved, solved.seconds = 2, solved.length = 8;
  solved.improvements = {{0.25, 10}, {1.5, 8}};
  ExperimentRun unsolved;
  unsolved.seed = 2, unsolved.seconds = 2, unsolved.status = PlanStatus::limit;
  r.runs = {solved, unsolved};
  const CellStatistics s = experiment_statistics(e, r)[0][0];
  EXPECT_EQ(s.runs, 2u);
  EXPECT_EQ(s.solved, 1u);
  EXPECT_EQ(s.success_rate, 0.5);
  EXPECT_EQ(s.solved_at, (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_EQ(s.cost_at[0].min, 10);
  EXPECT_EQ(s.cost_at[2].min, 8);
  EXPECT_EQ(s.cost_at[2].max, inf);
  EXPECT_EQ(s.first_solutions, (std::vector<double>{0.25, inf}));
  EXPECT_EQ(s.length.count, 1u);
  EXPECT_EQ(s.time.median, 2);
}

}  // namespace
}  // namespace polyplan
