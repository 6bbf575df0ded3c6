// The potential-field planner on the exact C-space: solved where the field leads to the goal (the
// path re-checked exactly), local_minimum in the U-shaped trap and at the course's planning problem set's minimum
// beside the infinite wall, no_path proved between components, the step limit, bad options named;
// and on a round world (a disc robot among discs), round a disc beside the way, and stopped by
// one on it, every step checked exactly among the discs.
#include "world_fixtures.hpp"

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace polyplan {
namespace {

using test::shipped;

PlanReport<ExactPoint> descend(const CSpace& cspace, const Query& query, const OptionValues& options = {}) {
  return planners<TranslatingRobot>().find("potential-field")->make(cspace, options)->plan(query);
}

// The fact potential.stopped_at.
std::pair<double, double> stopped_at(const PlanReport<ExactPoint>& report) {
  const FactPoint at = report.facts.at(PotentialFacts::descent.stopped_at);
  return {at[0], at[1]};
}

TEST(PotentialFieldPlanner, DescendsToAGoalInTheOpenWithAnExactlyCheckedPath) {
  const World world = shipped("u_trap");
  const CSpace cspace(world);
  const Query beside{{3, 17}, {17, 17}, "beside"};  // above the U, the way clear
  const Query round{{3, 3}, {17, 16}, "round"};     // past the U's corner: repelled, then past it
  for (const Query& q : {beside, round}) {
    SCOPED_TRACE(q.name);
    const auto report = descend(cspace, q);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.path.front(), q.start);
    EXPECT_EQ(report.path.back(), q.goal);
    EXPECT_TRUE(check_path(cspace, report.path).valid) << check_path(cspace, report.path).reason;
    EXPECT_GT(report.facts.at(PotentialFacts::descent.steps), 10);
  }
}

TEST(PotentialFieldPlanner, TheUShapedTrapIsALocalMinimumAboveItsBottomWall) {
  const World world = shipped("u_trap");
  const auto report = descend(CSpace(world), world.queries[0]);
  EXPECT_EQ(report.status, PlanStatus::local_minimum) << report.why_not;
  EXPECT_NE(report.why_not.find("a local minimum at"), std::string::npos) << report.why_not;
  const auto [x, y] = stopped_at(report);
  // The course's planning problem set's minimum again, turned: 0.68233 above the wall's top y = 7, where the repulsion
  // (η = Q* = 1) balances the conic pull (ζ = 1).
  EXPECT_NEAR(x, 10, 1e-4);
  EXPECT_NEAR(y, 7.68233, 1e-4);
}

// The course's planning problem set, problem 1: ζ = 1 conic (d* = 0), η = 1, Q* = 1; the descent ends at the seed's one
// critical point, the minimum (−0.68233, 0).
TEST(PotentialFieldPlanner, SeedTwosWallHoldsTheRobotAtItsMinimum) {
  const World world = shipped("seed002_wall");
  const auto report =
      descend(CSpace(world), world.queries[0], {{"step", "0.01"}, {"patience", "2000"}, {"max-steps", "50000"}});
  EXPECT_EQ(report.status, PlanStatus::local_minimum) << report.why_not;
  const auto [x, y] = stopped_at(report);
  EXPECT_NEAR(x, -0.68233, 1e-4);
  EXPECT_NEAR(y, 0, 1e-4);
}

TEST(PotentialFieldPlanner, NoPathIsProvedAndTheStepLimitIsALimit) {
  const World corners = shipped("touching_corners");
  EXPECT_EQ(descend(CSpace(corners), corners.queries[0]).status, PlanStatus::no_path);
  const World trap = shipped("u_trap");
  const auto cut = descend(CSpace(trap), trap.queries[0], {{"max-steps", "3"}});
  EXPECT_EQ(cut.status, PlanStatus::limit);
  EXPECT_EQ(cut.facts.at(QueryFacts::stopped_by), "step limit");
  EXPECT_EQ(cut.facts.at(PotentialFacts::descent.steps), 3);
}

TEST(PotentialFieldPlanner, BadOptionsAreNamed) {
  const CSpace cspace(shipped("u_trap"));
  const auto* entry = planners<TranslatingRobot>().find("potential-field");
  for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
           {"zeta", "-1"}, {"zeta", "0"}, {"q-star", "-2"}, {"patience", "0"}}) {
    SCOPED_TRACE(name + "=" + value);
    try {
      entry->make(cspace, {{name, value}});
      FAIL() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(
          std::string(e.what()).rfind("planner potential-field: option " + name + "=" + value + ": expected a ", 0), 0u)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace polyplan

namespace polyplan {
namespace {

// A disc robot (radius 1/2) from (−5, 0) to (5, 0) in the box [−10, 10]², a disc of radius 3/2
// centred at (0, `centre_y`) in between.
World disc_between(const std::string& centre_y) {
  return test::world_from(R"({"bounds": [-10, -10, 10, 10], "discs": [{"center": [0, )" + centre_y +
                          R"(], "radius": 1.5}], "robot": {"disc": 0.5}, "start": [-5, 0], "goal": [5, 0]})");
}

PlanReport<ExactPoint> descend_round(const RoundWorld& round, const Query& query, const OptionValues& options = {}) {
  return planners<RoundRobot>().find("potential-field")->make(round, options)->plan(query);
}

// Every step of the walk, and the walk as a whole, passes the round world's exact check.
void expect_valid_walk(const RoundWorld& round, const PlanReport<ExactPoint>& report) {
  ASSERT_GE(report.path.size(), 2u);
  for (std::size_t i = 0; i + 1 < report.path.size(); ++i)
    ASSERT_TRUE(round.check_segment(report.path[i], report.path[i + 1]).valid) << "step " << i;
  const PathCheck whole = round.check_path(report.path);
  EXPECT_TRUE(whole.valid) << whole.reason;
}

// The disc a little above the line start–goal: its repulsion turns the robot below it, and the
// goal's pull brings it home.
TEST(RoundPotentialFieldPlanner, PassesADiscBesideTheWayToTheGoal) {
  const World world = disc_between("0.75");
  const RoundWorld round(world);
  ASSERT_FALSE(round.check_segment(world.queries[0].start, world.queries[0].goal).valid);  // straight is blocked
  const auto report = descend_round(round, world.queries[0]);
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_EQ(report.path.front(), world.queries[0].start);
  EXPECT_EQ(report.path.back(), world.queries[0].goal);
  expect_valid_walk(round, report);
  EXPECT_TRUE(report.certificate.certified);
  EXPECT_EQ(report.facts.at(RoadmapFacts::kind), "potential-field");
}

// The disc on the line, the world symmetric about it: the gradient never leaves the line, and the
// robot stops where the conic pull (ζ = 1) balances the repulsion (η = Q* = 1), 1 − D = D³, so
// D = 0.68233 short of the disc grown by the robot (radius 2).
TEST(RoundPotentialFieldPlanner, ADiscOnTheLineOfASymmetricWorldIsALocalMinimum) {
  const World world = disc_between("0");
  const RoundWorld round(world);
  const auto report = descend_round(round, world.queries[0]);
  EXPECT_EQ(report.status, PlanStatus::local_minimum) << report.why_not;
  expect_valid_walk(round, report);
  const FactPoint at = report.facts.at(PotentialFacts::descent.stopped_at);
  EXPECT_NEAR(at[0], -2.68233, 1e-3);
  EXPECT_EQ(at[1], 0);
}

TEST(RoundPotentialFieldPlanner, TheStepLimitIsALimitAndBadOptionsAreNamed) {
  const World world = disc_between("0.75");
  const RoundWorld round(world);
  const auto cut = descend_round(round, world.queries[0], {{"max-steps", "3"}});
  EXPECT_EQ(cut.status, PlanStatus::limit);
  EXPECT_EQ(cut.facts.at(PotentialFacts::descent.steps), 3);
  expect_valid_walk(round, cut);
  try {
    descend_round(round, world.queries[0], {{"zeta", "0"}});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("planner potential-field: option zeta=0: expected a ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace polyplan
