// arm/arm_goal_set: the configurations a query with its goal in the workspace may end at. The two-link
// annulus decided exactly (one goal exactly on either boundary, none a double's last bit beyond),
// both elbows inside, three links with an orientation, redundant arms' numeric goals (within 1e-12
// and distinct), joint limits kept, colliding solutions left out, why there are none, and the facts;
// then every arm planner planning to such a set, its path re-checked independently (the hand at the
// point by forward kinematics written out in the test, every motion at dense samples and by
// certify_motion).
#include <polyplan/arm/arm_goal_set.hpp>
#include <polyplan/arm/inverse_kinematics.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace polyplan {
namespace {

using test::arm_of;
using test::hand_at;

ArmProblem problem_of(Arm arm, std::vector<Eigen::Vector2d> points = {}) {
  ArmProblem p;
  p.source = "test";
  p.arm = std::move(arm);
  p.points = std::move(points);
  return p;
}

ArmQuery to_point(JointAngles start, Eigen::Vector2d point, std::optional<double> orientation = std::nullopt) {
  return {"reach", std::move(start), {}, WorkspaceGoal{point, orientation}};
}

ArmGoalSet goal_set_of(const ArmProblem& problem, const ArmQuery& query) {
  const ArmCollisionChecker checker(problem);
  return arm_goal_set(checker, query);
}

// Every goal puts the hand at the point (within `tolerance`, by hand_at), is normalised, and its
// recorded error is the hand's distance as the library measures it.
void expect_goals_reach(const ArmProblem& problem, const ArmGoalSet& set, const WorkspaceGoal& goal, double tolerance) {
  for (const ArmGoal& g : set.goals) {
    EXPECT_LE((hand_at(problem.arm.links, g.angles) - goal.point).norm(), tolerance);
    EXPECT_LE(g.error, tolerance);
    EXPECT_NEAR(g.error, (hand_at(problem.arm.links, g.angles) - goal.point).norm(), 1e-15);
    test::expect_hand_at_goal(problem.arm, goal, g.angles);
  }
}

// The largest difference of one joint between two configurations, the short way round.
double apart(const JointAngles& a, const JointAngles& b) {
  double most = 0;
  for (std::size_t i = 0; i < a.size(); ++i) most = std::max(most, angular_distance(a[i], b[i]));
  return most;
}

// l = [3, 2]: the hand reaches 1 ≤ d ≤ 5. (3, 4) and (5, 0) lie exactly at 5, (0, -1) and (1, 0) at 1.
TEST(ArmGoalSet, TwoLinksExactlyOnTheAnnulusHaveOneGoalAndOneUlpBeyondNone) {
  const ArmProblem problem = problem_of(arm_of({3, 2}));
  for (const Eigen::Vector2d& point :
       {Eigen::Vector2d(3, 4), Eigen::Vector2d(5, 0), Eigen::Vector2d(0, -1), Eigen::Vector2d(1, 0)}) {
    SCOPED_TRACE(point.transpose());
    const ArmQuery query = to_point({1, 1}, point);
    const ArmGoalSet set = goal_set_of(problem, query);
    ASSERT_EQ(set.goals.size(), 1u);
    EXPECT_EQ(set.solutions, 1u);
    EXPECT_TRUE(set.workspace);
    expect_goals_reach(problem, set, *query.goal_point, 1e-14);
  }
  // One ulp beyond 5, and one below 1: out of reach, proved.
  for (const Eigen::Vector2d& point : {Eigen::Vector2d(test::up(5), 0), Eigen::Vector2d(0, test::down(1))}) {
    const ArmGoalSet set = goal_set_of(problem, to_point({1, 1}, point));
    EXPECT_TRUE(set.goals.empty());
    EXPECT_EQ(set.status, PlanStatus::no_path);
  }
  EXPECT_EQ(goal_set_of(problem, to_point({1, 1}, {test::up(5), 0})).why_none,
            "the point (5.000000000000001, 0) is out of reach: the arm reaches distances 1 to 5 from its base");
  // One ulp within 5: both elbows, a hair apart.
  EXPECT_EQ(goal_set_of(problem, to_point({1, 1}, {test::down(5), 0})).goals.size(), 2u);
}

TEST(ArmGoalSet, TwoLinksStrictlyInsideHaveBothElbows) {
  const ArmProblem problem = problem_of(arm_of({3, 2}));
  const ArmQuery query = to_point({1, 1}, {-2, 3});
  const ArmGoalSet set = goal_set_of(problem, query);
  ASSERT_EQ(set.goals.size(), 2u);
  expect_goals_reach(problem, set, *query.goal_point, 1e-14);
  // d² = 13 = 3² + 2²: the elbow is square, up and down.
  EXPECT_NEAR(set.goals[0].angles[1], M_PI / 2, 1e-14);
  EXPECT_NEAR(set.goals[1].angles[1], 3 * M_PI / 2, 1e-14);
  EXPECT_EQ(set.configurations(), (std::vector<JointAngles>{set.goals[0].angles, set.goals[1].angles}));
  EXPECT_EQ(set.index_of(set.goals[1].angles), 1u);
  EXPECT_THROW(set.index_of({0, 0}), std::logic_error);
}

TEST(ArmGoalSet, ThreeLinksWithAnOrientationHaveTheClosedFormsGoals) {
  const ArmProblem problem = problem_of(arm_of({1, 0.8, 0.3}));
  for (const double orientation : {0.0, 1.0, -2.5}) {
    const ArmQuery query = to_point({0, 0, 0}, {0.6, 1.1}, orientation);
    const ArmGoalSet set = goal_set_of(problem, query);
    ASSERT_EQ(set.goals.size(), 2u) << orientation;
    expect_goals_reach(problem, set, *query.goal_point, 1e-12);
    const IkAnswer closed = three_link_ik(problem.arm, {0.6, 1.1}, orientation);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_LT(apart(set.goals[i].angles, closed.solutions[i].angles), 1e-15);
  }
  // The wrist out of the first two links' reach: inverse kinematics finds nothing, which proves
  // nothing about the rounded wrist, so not_found.
  const ArmGoalSet none = goal_set_of(problem, to_point({0, 0, 0}, {2, 0}, M_PI));
  EXPECT_TRUE(none.goals.empty());
  EXPECT_EQ(none.status, PlanStatus::not_found);
  EXPECT_NE(none.why_none.find(
                "the point (2, 0) with the last link at 3.141592653589793 rad is within the arm's reach, but inverse "
                "kinematics found no configuration there"),
            std::string::npos)
      << none.why_none;
}

TEST(ArmGoalSet, RedundantArmsHaveDistinctNumericGoalsWithinATrillionth) {
  const ArmProblem four = problem_of(arm_of({1, 1, 1, 1}));
  const ArmQuery query = to_point({0, 0, 0, 0}, {1.5, -1.2});
  const ArmGoalSet set = goal_set_of(four, query);
  EXPECT_GE(set.goals.size(), 24u);  // a continuum of solutions: nearly every seed gives one of its own
  EXPECT_LE(set.goals.size(), goal_set_seeds + 1);
  expect_goals_reach(four, set, *query.goal_point, 1e-12);
  for (std::size_t i = 0; i < set.goals.size(); ++i)
    for (std::size_t j = i + 1; j < set.goals.size(); ++j)
      EXPECT_GT(apart(set.goals[i].angles, set.goals[j].angles), 1e-6);

  const ArmProblem six = problem_of(arm_of({1, 0.9, 0.8, 0.7, 0.6, 0.5}));
  const ArmQuery oriented = to_point(JointAngles(6, 0.0), {-1.2, 2.1}, 2.0);
  const ArmGoalSet with = goal_set_of(six, oriented);
  EXPECT_GE(with.goals.size(), 16u);
  expect_goals_reach(six, with, *oriented.goal_point, 1e-12);
  // Fewer seeds, fewer goals: the count is the caller's.
  EXPECT_LE(arm_goal_set(ArmCollisionChecker(four), query, 4).goals.size(), 4u);
}

TEST(ArmGoalSet, GoalsKeepTheJointLimits) {
  Arm four = arm_of({1, 1, 1, 1});
  four.limits.assign(4, {-1.0, 1.0});
  const ArmProblem limited = problem_of(four);
  const ArmQuery query = to_point({0, 0, 0, 0}, {2.5, 1.0});
  const ArmGoalSet set = goal_set_of(limited, query);
  ASSERT_GE(set.goals.size(), 8u);
  expect_goals_reach(limited, set, *query.goal_point, 1e-12);  // expect_hand_at_goal checks the limits
  for (const ArmGoal& g : set.goals)
    for (const double a : g.angles) EXPECT_TRUE(a <= 1 + 1e-12 || a >= two_pi - 1 - 1e-12) << a;

  // Two links, the elbow only bending left (θ2 in [0, π]): of the two elbows at (-2, 3), one is kept.
  Arm two = arm_of({3, 2});
  two.limits = {{-10, 10}, {0, M_PI}};
  const ArmGoalSet left = goal_set_of(problem_of(two), to_point({1, 1}, {-2, 3}));
  ASSERT_EQ(left.goals.size(), 1u);
  EXPECT_EQ(left.solutions, 2u);
  EXPECT_NEAR(left.goals[0].angles[1], M_PI / 2, 1e-14);
  // Read round the circle: [π, 2π] is the other elbow, and so is [-π, 0].
  for (const std::pair<double, double>& right : {std::pair{M_PI, 2 * M_PI}, std::pair{-M_PI, 0.0}}) {
    two.limits[1] = right;
    const ArmGoalSet other = goal_set_of(problem_of(two), to_point({1, 1}, {-2, 3}));
    ASSERT_EQ(other.goals.size(), 1u);
    EXPECT_NEAR(other.goals[0].angles[1], 3 * M_PI / 2, 1e-14);
  }
  // Neither elbow: reachable, yet no goal.
  two.limits[1] = {2.5, 3};
  const ArmGoalSet none = goal_set_of(problem_of(two), to_point({1, 1}, {-2, 3}));
  EXPECT_TRUE(none.goals.empty());
  EXPECT_EQ(none.status, PlanStatus::not_found);
  EXPECT_NE(none.why_none.find("every solution (2) lies outside the joint limits"), std::string::npos) << none.why_none;
}

// Links [3, 2], 0.4 wide; (3, 2) has the elbows (0, π/2) — link 1 along the x axis — and
// (1.176, -π/2). A point at (2, 0.1) lies on the first's link 1.
TEST(ArmGoalSet, ACollidingSolutionIsNoGoal) {
  Arm arm = arm_of({3, 2}, 0.4);
  const ArmQuery query = to_point({2, 1}, {3, 2});
  const ArmGoalSet one = goal_set_of(problem_of(arm, {{2, 0.1}}), query);
  ASSERT_EQ(one.goals.size(), 1u);
  EXPECT_EQ(one.solutions, 2u);
  EXPECT_NEAR(one.goals[0].angles[1], 3 * M_PI / 2, 1e-14);
  expect_goals_reach(problem_of(arm), one, *query.goal_point, 1e-14);
  // A second point on the other elbow's link 2: none is free; the closed form found every solution.
  const ArmGoalSet none = goal_set_of(problem_of(arm, {{2, 0.1}, {2.1, 2.5}}), query);
  EXPECT_TRUE(none.goals.empty());
  EXPECT_EQ(none.status, PlanStatus::not_found);
  EXPECT_EQ(
      none.why_none,
      "the point (3, 2) is within the arm's reach, but none of the 2 inverse-kinematics solution(s) found is a goal: "
      "2 collide (every solution there is)");
  // The hand inside an obstacle: every numeric solution collides, and the set says a free one may
  // have been missed (as far as the numeric method knows).
  ArmProblem walled = problem_of(arm_of({1, 1, 1}));
  walled.obstacles = {test::square(0.1, 1.5, 1)};
  walled.obstacle_names = {"obstacles[0]"};
  const ArmGoalSet missed = goal_set_of(walled, to_point({0, 0, 0}, {1.5, 1}));
  EXPECT_TRUE(missed.goals.empty());
  EXPECT_NE(missed.why_none.find("; a free configuration the seeds missed may still exist"), std::string::npos)
      << missed.why_none;
}

// The annulus of n links is the longest folded back over the rest: [5, 1, 1] reaches 3 ≤ d ≤ 7,
// [1, 1, 1] the whole disc of radius 3.
TEST(ArmGoalSet, TheReachOfNLinksIsDecidedExactly) {
  EXPECT_TRUE(hand_reach({5, 1, 1}, {3, 0}).reachable());
  EXPECT_EQ(hand_reach({5, 1, 1}, {3, 0}).inner_side, 0);
  EXPECT_FALSE(hand_reach({5, 1, 1}, {test::down(3), 0}).reachable());
  EXPECT_FALSE(hand_reach({5, 1, 1}, {test::up(7), 0}).reachable());
  EXPECT_TRUE(hand_reach({1, 1, 1}, {0, 0}).reachable());
  EXPECT_EQ(hand_reach({1, 1, 1}, {0, 0}).inner, 0);
  // 0.1 + 0.2 rounds up, beyond the exact sum of the links 0.1 and 0.2 (doubles both): out of reach,
  // though d == l1 + l2 in floating point; the double 0.3 lies below that sum, strictly inside.
  EXPECT_FALSE(hand_reach({0.1, 0.2}, {0.1 + 0.2, 0}).reachable());
  EXPECT_EQ(hand_reach({0.1, 0.2}, {0.3, 0}).outer_side, 1);
  const ArmGoalSet set = goal_set_of(problem_of(arm_of({5, 1, 1})), to_point({0, 0, 0}, {0, test::down(3)}));
  EXPECT_EQ(set.status, PlanStatus::no_path);
  EXPECT_EQ(set.why_none,
            "the point (0, 2.9999999999999996) is out of reach: the arm reaches distances 3 to 7 from its base");
}

// An arm file's decimals are the values written: links 0.2 and 0.3 reach (0.3, 0.4) only stretched
// out, one goal, though the doubles of the three numbers would put it out of reach.
TEST(ArmGoalSet, AFilesDecimalGoalOnTheBoundaryHasOneGoal) {
  const ArmProblem p =
      parse_arm_problem(R"({"links": [0.2, 0.3], "start": [1, 1], "goal_point": [0.3, 0.4]})", "decimal");
  EXPECT_EQ(p.arm.exact_links, (std::vector<Rational>{Rational(1, 5), Rational(3, 10)}));
  ASSERT_TRUE(p.queries[0].goal_point && p.queries[0].goal_point->exact_point);
  EXPECT_EQ(*p.queries[0].goal_point->exact_point, (ExactPoint{Rational(3, 10), Rational(2, 5)}));
  const ArmGoalSet set = goal_set_of(p, p.queries[0]);
  ASSERT_EQ(set.goals.size(), 1u) << set.why_none;
  EXPECT_LT(set.goals[0].error, 1e-15);
}

TEST(ArmGoalSet, AGoalInJointAnglesIsItselfNormalisedAndHasNoFacts) {
  const ArmProblem problem = problem_of(arm_of({1, 1}));
  const ArmGoalSet set = goal_set_of(problem, {"q", {0, 0}, {7, -1}});
  ASSERT_EQ(set.goals.size(), 1u);
  EXPECT_FALSE(set.workspace);
  EXPECT_EQ(set.goals[0].angles, (JointAngles{normalize_angle(7), normalize_angle(-1)}));
  Facts facts;
  set_goal_facts(set, 0, facts);
  EXPECT_TRUE(facts.entries().empty());

  const ArmGoalSet reach = goal_set_of(problem, to_point({0, 0}, {1, 1}));
  set_goal_facts(reach, 1, facts);
  EXPECT_EQ(facts.at(GoalFacts::candidates), 2);
  EXPECT_EQ(facts.at(GoalFacts::reached), 1);
  EXPECT_EQ(facts.at(GoalFacts::error), reach.goals[1].error);
  EXPECT_EQ(facts.at(GoalFacts::solutions), 2);
}

TEST(ArmGoalSet, QueriesThatCannotBeAskedAreRefused) {
  const ArmCollisionChecker checker(problem_of(arm_of({1, 1})));
  ArmQuery both = to_point({0, 0}, {1, 1});
  both.goal = {1, 1};
  EXPECT_EQ(query_not_free(checker, both),
            "the query reach has both goal angles and a goal point: its goal is one or the other");
  EXPECT_EQ(query_not_free(checker, to_point({0}, {1, 1})),
            "the query reach has 1 start angles for an arm of 2 joints");
  EXPECT_EQ(query_not_free(checker, to_point({0, 0}, {std::nan(""), 1})),
            "the query reach's goal point (or orientation) is not a finite number");
  EXPECT_EQ(query_not_free(checker, to_point({0, 0}, {1, 1}, INFINITY)),
            "the query reach's goal point (or orientation) is not a finite number");
  EXPECT_EQ(query_not_free(checker, to_point({0, 0}, {1, 1})), std::nullopt);
}

// A three-link arm among points, its hand to a point with and without an orientation, and a point
// whose every solution collides: every arm planner of the registry.
class EveryArmPlannerToAPoint : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryArmPlannerToAPoint, EndsWithTheHandAtThePointOnCertifiedMotions) {
  const ArmProblem problem = problem_of(arm_of({1.2, 1, 0.6}, 0.1), {{1.5, 1.5}, {-1, 1.8}, {0.4, -1.6}, {-2.2, -0.5}});
  const ArmCollisionChecker checker(problem);
  const PlannerEntry<PlanarArm>& entry = *planners<PlanarArm>().find(GetParam());
  const auto planner =
      entry.make(problem, entry.anytime ? OptionValues{{"iterations", "20000"}} : OptionValues{});  // RRT* ends soon
  for (const ArmQuery& query : {to_point({0.3, 0.2, 0.1}, {-1.4, 1.3}), to_point({0.3, 0.2, 0.1}, {0.5, 2.2}, 2.0),
                                to_point({0.3, 0.2, 0.1}, {2.2, -0.7})}) {
    SCOPED_TRACE(query.goal_point->point.transpose());
    const PlanReport<JointAngles> report = planner->plan(query);
    ASSERT_TRUE(report.found) << report.why_not;
    test::expect_arm_path_free(checker, query, report.path);
    test::expect_goal_facts(report, arm_goal_set(checker, query));
  }
  // Both solutions of (0, 1.6) with the last link pointing up have that link from (0, 1) to (0, 1.6),
  // through a point at (0, 1.3).
  const ArmProblem blocked = problem_of(arm_of({1.2, 1, 0.6}, 0.1), {{0, 1.3}});
  const auto stuck = planners<PlanarArm>().find(GetParam())->make(blocked, {});
  const PlanReport<JointAngles> none = stuck->plan(to_point({0.3, 0.2, 0.1}, {0, 1.6}, M_PI / 2));
  EXPECT_EQ(none.status, PlanStatus::not_found);
  EXPECT_EQ(
      none.why_not,
      "the point (0, 1.6) with the last link at 1.5707963267948966 rad is within the arm's reach, but none of the 2 "
      "inverse-kinematics solution(s) found is a goal: 2 collide (every solution there is)");
  const PlanReport<JointAngles> far = stuck->plan(to_point({0.3, 0.2, 0.1}, {0, 2.9}));
  EXPECT_EQ(far.status, PlanStatus::no_path);
  EXPECT_EQ(far.why_not, "the point (0, 2.9) is out of reach: the arm reaches distances 0 to 2.8 from its base");
}

INSTANTIATE_TEST_SUITE_P(ArmGoalSet, EveryArmPlannerToAPoint,
                         ::testing::Values("grid", "prm", "lazyprm", "rrt", "rrtstar", "rrtconnect"));

}  // namespace
}  // namespace polyplan
