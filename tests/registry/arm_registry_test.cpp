// The conformance test of arm planners: every planner of planners<PlanarArm>() on every arm of
// data/arms and every query, with its default options. A planner added to the registry is tested
// here without a test of its own. A found path must begin exactly at the start and end exactly at
// the goal (normalised) — for a goal in the workspace, with the hand at the point within 1e-9 by
// forward kinematics computed in the test, within the joint limits —, be certified, and be free
// along every motion by two checks independent of the planner's: the collision checker at dense
// samples (every 0.01 degrees of the joint that turns most) and certify_motion again. A goal point
// out of the arm's reach (decided here on exact rationals) must be answered no_path, saying so;
// one within reach never is. The report must print (plan_json) and draw (draw_plan), its status
// must agree with it, and a second planner built alike must give the same answer.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_facts.hpp>
#include <polyplan/arm/arm_grid_planner.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/draw/arm_svg.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>
#include "arm/arm_fixtures.hpp"
#include "registry/registry_fixtures.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace polyplan {
namespace {

// Whether the hand of an arm with these links can be at `point`: max(0, 2·max l − Σ l) ≤ |point| ≤ Σ l,
// on the exact values of the doubles.
bool within_reach(const std::vector<double>& links, const Eigen::Vector2d& point) {
  Rational sum = 0, longest = 0;
  for (const double l : links) {
    sum += Rational(l);
    longest = std::max(longest, Rational(l));
  }
  const Rational inner = std::max(Rational(0), Rational(2 * longest - sum));
  const Rational x(point.x()), y(point.y()), d2 = x * x + y * y;
  return inner * inner <= d2 && d2 <= sum * sum;
}

class EveryArmPlannerOnEveryArm : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(EveryArmPlannerOnEveryArm, KeepsThePlannerPromises) {
  const auto& [planner_name, arm_name] = GetParam();
  const ArmProblem problem = read_arm_problem(std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/" + arm_name + ".json");
  // Defaults, but sampling planners stop after 30 s (iterations stop them sooner: every shipped
  // arm has a path, and a slow sanitizer build must still find it).
  const PlannerEntry<PlanarArm>* entry = planners<PlanarArm>().find(planner_name);
  OptionValues options;
  for (const OptionInfo& o : entry->options)
    if (o.name == "time") options.emplace_back("time", "30");
  // RRT* is anytime and stops at its time limit by default: an iteration limit ends it soon.
  if (entry->anytime) options.emplace_back("iterations", "8000");
  const auto planner = entry->make(problem, options), again = entry->make(problem, options);
  const ArmCollisionChecker checker(problem);
  ASSERT_FALSE(problem.queries.empty());
  std::size_t found = 0;
  test::SameAnswers same;
  for (const ArmQuery& q : problem.queries) {
    SCOPED_TRACE(q.name);
    const PlanReport<JointAngles> report = planner->plan(q, QueryOptions{true});
    test::expect_consistent_answer(report, q.name);
    same.expect(report, again->plan(q));
    if (report.status == PlanStatus::invalid_query) {  // braces: EXPECT_TRUE is an if-else of its own
      EXPECT_TRUE(query_not_free(checker, q).has_value());
    }
    if (q.goal_point && !within_reach(problem.arm.links, q.goal_point->point)) {
      EXPECT_EQ(report.status, PlanStatus::no_path);
      EXPECT_NE(report.why_not.find(" is out of reach: the arm reaches distances "), std::string::npos)
          << report.why_not;
    } else {
      EXPECT_NE(report.status, PlanStatus::no_path) << report.why_not;
    }
    if (!report.found) continue;
    ++found;
    ASSERT_GE(report.path.size(), 2u);
    const double length = test::expect_arm_path_free(checker, q, report.path);
    if (q.goal_point) test::expect_goal_facts(report, arm_goal_set(checker, q));
    // A torus path's length is the joints' short-way turns; no path is shorter than that sum.
    EXPECT_GE(report.length, length - 1e-9);
    EXPECT_GE(report.length, total_angular_distance(q.start, report.path.back()) - 1e-9);

    const nlohmann::json json = plan_json(report, q.name);
    EXPECT_EQ(json["query"], q.name);
    EXPECT_EQ(json["path"].size(), report.path.size());
    EXPECT_EQ(json["path"][0].size(), problem.arm.joints());
    const std::string picture = draw_plan(problem, report, {ArmPictureOptions::Kind::animation, q.name}).str();
    EXPECT_NE(picture.find("<animateTransform"), std::string::npos);
  }
  EXPECT_GT(found, 0u) << "every shipped arm has a query its planners answer";
}

INSTANTIATE_TEST_SUITE_P(ArmRegistry, EveryArmPlannerOnEveryArm,
                         ::testing::Combine(::testing::ValuesIn(test::registered_planners<PlanarArm>()),
                                            ::testing::ValuesIn(test::shipped("arms"))),
                         [](const auto& info) {
                           return test::test_name(std::get<0>(info.param), std::get<1>(info.param));
                         });

TEST(ArmRegistry, GridIsRegisteredWithItsOptions) {
  const auto* grid = planners<PlanarArm>().find("grid");
  ASSERT_NE(grid, nullptr);
  std::vector<std::string> names;
  for (const OptionInfo& o : grid->options) names.push_back(o.name);
  EXPECT_EQ(names, (std::vector<std::string>{"resolution", "torus", "evaluation", "search", "weight", "reopen",
                                             "coarse", "corridor", "exact-cells", "widenings", "memory-mb"}));
  EXPECT_EQ(grid->options[1].flag, true);
  ArmProblem p;
  p.arm.links = {1, 1};
  p.queries = {{"q", {0, 0}, {1, 1}}};
  const auto interval =
      grid->make(p, {{"torus", "false"}, {"evaluation", "eager"}, {"resolution", "10"}})->plan(p.queries[0]);
  EXPECT_EQ(interval.facts.at(ArmGridFacts::grid_torus), false);
  EXPECT_EQ(interval.facts.at(ArmGridFacts::grid_evaluation), "eager");
  EXPECT_EQ(interval.facts.at(ArmGridFacts::cells_evaluated), 36 * 36);
  try {
    grid->make(p, {{"resolution", "7"}});
    ADD_FAILURE() << "7 degrees do not divide 360";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "planner grid: the grid resolution 7 degrees must divide 360 into at least 3 cells");
  }
}

}  // namespace
}  // namespace polyplan
