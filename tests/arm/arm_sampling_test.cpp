// The sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) for planar arms: every shipped
// arm and query with three seeds, each path re-checked independently (the checker every 0.01° of
// the joint that turns most, and certify_motion again); one seed, one path; RRT* converging to the
// 0.5° grid's optimum on the two-link arm. The conformance test (arm_registry_test.cpp) runs them
// with their defaults as well.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/arm/arm_sampling_space.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include <polyplan/sampling/sampling_planner.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <string>

namespace polyplan {
namespace {

constexpr std::array<const char*, 5> sampling_planners{"prm", "lazyprm", "rrt", "rrtstar", "rrtconnect"};

ArmProblem shipped_arm(const std::string& name) {
  return read_arm_problem(std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/" + name + ".json");
}

std::unique_ptr<Planner<PlanarArm>> make(const std::string& name, const ArmProblem& problem,
                                         const OptionValues& options) {
  return planners<PlanarArm>().find(name)->make(problem, options);
}

class SamplingPlannerOnArm : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(SamplingPlannerOnArm, ThreeSeedsGiveIndependentlyCheckedPathsAndOneSeedOnePath) {
  const auto& [planner, arm_name] = GetParam();
  const ArmProblem problem = shipped_arm(arm_name);
  const ArmCollisionChecker checker(problem);
  for (const std::string seed : {"1", "2", "3"}) {
    SCOPED_TRACE("seed " + seed);
    // RRT* is anytime and stops at its time limit by default: an iteration limit makes its runs
    // repeatable.
    OptionValues options{{"seed", seed}, {"time", "20"}};
    if (planner == "rrtstar") options.emplace_back("iterations", "8000");
    auto planner_of_seed = make(planner, problem, options);
    for (const ArmQuery& q : problem.queries) {
      SCOPED_TRACE(q.name);
      const auto report = planner_of_seed->plan(q);
      ASSERT_TRUE(report.found) << report.why_not;
      const double length = test::expect_arm_path_free(checker, q, report.path);
      EXPECT_NEAR(report.length, length, 1e-9 * length);
      EXPECT_LE(report.length, report.facts.at(SamplingFacts::raw_length) * (1 + 1e-12));
      // The same seed, a planner of its own, the same first query: the same path.
      if (&q == &problem.queries.front()) {  // braces: EXPECT_EQ is an if-else of its own
        EXPECT_EQ(make(planner, problem, options)->plan(q).path, report.path);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ArmSampling, SamplingPlannerOnArm,
                         ::testing::Combine(::testing::ValuesIn(std::vector<std::string>(sampling_planners.begin(),
                                                                                         sampling_planners.end())),
                                            ::testing::ValuesIn(std::vector<std::string>{
                                                "two_link_points", "three_link_forest", "four_link_forest"})),
                         [](const auto& info) { return std::get<0>(info.param) + "_on_" + std::get<1>(info.param); });

// RRT* without shortcuts on the two-link arm's hard query: the cost of one seed never grows with
// more iterations, and comes within 10% of the optimum of the 0.5° grid (4-connected on the
// torus, so its moves measure the same sum of joint turns).
TEST(ArmSampling, RrtStarConvergesTowardTheFineGridOptimum) {
  const ArmProblem problem = shipped_arm("two_link_points");
  const ArmQuery& hard = problem.queries[2];
  ASSERT_EQ(hard.name, "hard");
  const auto grid = make("grid", problem, {{"resolution", "0.5"}})->plan(hard);
  ASSERT_TRUE(grid.found) << grid.why_not;
  double previous = std::numeric_limits<double>::infinity();
  for (const std::string iterations : {"500", "2000", "8000"}) {
    const auto report =
        make("rrtstar", problem, {{"iterations", iterations}, {"shortcut", "false"}, {"time", "60"}})->plan(hard);
    ASSERT_TRUE(report.found) << report.why_not;
    SCOPED_TRACE(iterations + " iterations: " + std::to_string(report.length) + " against the grid's " +
                 std::to_string(grid.length));
    EXPECT_LE(report.length, previous);
    previous = report.length;
  }
  EXPECT_LE(previous, 1.10 * grid.length);
  EXPECT_GE(previous, 0.95 * grid.length);  // the grid's optimum is near the true one at 0.5°
}

// Goals across the 0 = 2π seam: the tree goes the short way round.
TEST(ArmSampling, PathsGoTheShortWayAcrossTheSeam) {
  ArmProblem problem;
  problem.arm = test::arm_of({1, 1});
  problem.queries.push_back({"seam", {6.2, 0.1}, {0.1, 6.2}});
  for (const char* name : sampling_planners) {
    const auto report = make(name, problem, {})->plan(problem.queries[0]);
    ASSERT_TRUE(report.found) << name;
    EXPECT_NEAR(report.length, total_angular_distance({6.2, 0.1}, {0.1, 6.2}), 1e-9)
        << name;  // a straight motion after shortcuts
  }
}

TEST(ArmSampling, WrongSizesAndCollisionsAreAnswers) {
  const ArmProblem problem = shipped_arm("three_link_forest");
  for (const char* name : sampling_planners) {
    const auto planner = make(name, problem, {});
    const auto sizes = planner->plan({"short", {1, 2}, {1, 2, 3}});
    EXPECT_FALSE(sizes.found);
    EXPECT_EQ(sizes.why_not, "the query short has 2 start and 3 goal angles for an arm of 3 joints");
  }
}

TEST(ArmSampling, SpaceSamplesTheTorusAndMeasuresTheShortWay) {
  const ArmProblem problem = shipped_arm("four_link_forest");
  const auto space = arm_sampling_space(problem);
  EXPECT_EQ(space->dimension(), 4u);
  EXPECT_EQ(space->metric(), SamplingMetric::torus);
  EXPECT_DOUBLE_EQ(space->extent(), 4 * test::kPi);
  SamplingRandom random(7);
  std::vector<double> at(4);
  for (int i = 0; i < 1000; ++i) {
    space->sample(random, at);
    for (double a : at) EXPECT_TRUE(a >= 0 && a < two_pi);
  }
  EXPECT_NEAR(
      sampling_distance(SamplingMetric::torus, std::vector<double>{0.1, 0, 0, 0}, std::vector<double>{6.2, 0, 0, 0}),
      0.1 + (two_pi - 6.2), 1e-15);
  std::vector<double> half(4);
  sampling_interpolate(SamplingMetric::torus, std::vector<double>{0.1, 1, 1, 1}, std::vector<double>{6.2, 1, 1, 1}, 0.5,
                       half);
  EXPECT_NEAR(half[0], normalize_angle((0.1 + 6.2 - two_pi) / 2), 1e-15);
}

}  // namespace
}  // namespace polyplan
