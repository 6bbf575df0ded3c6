// Running an experiment's cells: every cell once, in cell order whatever the threads, the same
// answers on one thread and on two (the planners are seeded; rrt's iteration limit, not its time,
// ends its runs), and a progress call per run.
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/experiment/experiment_runner.hpp>

#include <gtest/gtest.h>

namespace polyplan {
namespace {

const std::string kExperimentName = std::string(POLYPLAN_SOURCE_DIR) + "/data/experiments/test.json";

Experiment small() {
  return parse_experiment(R"({"name": "small",
      "problems": [{"name": "office", "file": "../worlds/office.json"}, {"name": "arm", )"
                          R"("file": "../arms/three_link_forest.json"}],
      "planners": [{"name": "rrt", "planner": "rrt", "options": {"iterations": 20000}},
                   {"name": "connect", "planner": "rrtconnect"}],
      "seeds": [1, 2, 3], "time_limit": 30, "cost_times": [10, 30]})",
                          kExperimentName);
}

TEST(ExperimentRunner, RunsEveryCellOnceInCellOrder) {
  const Experiment e = small();
  std::size_t calls = 0, last_done = 0;
  const ExperimentResults one = run_experiment(e, 1, [&](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_EQ(done, last_done + 1);
    EXPECT_EQ(total, 12u);
    last_done = done;
  });
  EXPECT_EQ(calls, 12u);
  ASSERT_EQ(one.runs.size(), 12u);
  for (std::size_t i = 0; i < one.runs.size(); ++i) {
    EXPECT_EQ(one.runs[i].problem, i / 6);
    EXPECT_EQ(one.runs[i].planner, i / 3 % 2);
    EXPECT_EQ(one.runs[i].seed, e.seeds[i % 3]);
    EXPECT_TRUE(one.runs[i].solved) << i << ": " << one.runs[i].why_not;
    EXPECT_FALSE(one.runs[i].improvements.empty());
    EXPECT_EQ(one.runs[i].improvements.back().length, one.runs[i].length);
    EXPECT_GT(one.runs[i].seconds, 0);
  }
  EXPECT_EQ(one.threads, 1u);

  const ExperimentResults two = run_experiment(e, 2);
  EXPECT_EQ(two.threads, 2u);
  for (std::size_t i = 0; i < one.runs.size(); ++i) {
    EXPECT_EQ(two.runs[i].seed, one.runs[i].seed);
    EXPECT_EQ(two.runs[i].length, one.runs[i].length) << i;  // seeded: the same path on any thread
  }
}

}  // namespace
}  // namespace polyplan
