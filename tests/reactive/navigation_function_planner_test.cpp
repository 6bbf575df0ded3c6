// The navigation function of a sphere world: through the gap between two discs where the potential
// field stops, and every query of the course's graph-search homework's sphere world, paths checked exactly and the κ
// used reported; worlds that are not sphere worlds said so; a bad κ named.
#include "world_fixtures.hpp"

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <string>

namespace polyplan {
namespace {

using test::shipped;

PlanReport<ExactPoint> plan_with(const char* planner, const CSpace& cspace, const Query& q,
                                 const OptionValues& options = {}) {
  return planners<TranslatingRobot>().find(planner)->make(cspace, options)->plan(q);
}

TEST(NavigationFunctionPlanner, PassesTheGapWhereThePotentialFieldStops) {
  const World world = shipped("disc_gap");
  const CSpace cspace(world);
  const Query& q = world.queries[0];
  const auto field = plan_with("potential-field", cspace, q);
  EXPECT_EQ(field.status, PlanStatus::local_minimum) << field.why_not;
  const auto navigation = plan_with("navigation-function", cspace, q);
  ASSERT_TRUE(navigation.found) << navigation.why_not;
  EXPECT_EQ(navigation.path.back(), q.goal);
  EXPECT_TRUE(check_path(cspace, navigation.path).valid);
  EXPECT_GE(navigation.facts.at(NavigationFacts::kappa), 2);
  EXPECT_EQ(navigation.facts.at(NavigationFacts::spheres), 2);
  // A κ given is the κ used.
  const auto at_64 = plan_with("navigation-function", cspace, q, {{"kappa", "64"}});
  ASSERT_TRUE(at_64.found) << at_64.why_not;
  EXPECT_EQ(at_64.facts.at(NavigationFacts::kappa), 64);
}

TEST(NavigationFunctionPlanner, SolvesEveryQueryOfTheSphereWorld) {
  const World world = shipped("sphere_world_polygons");
  const CSpace cspace(world);
  for (const Query& q : world.queries) {
    SCOPED_TRACE(q.name);
    const auto report = plan_with("navigation-function", cspace, q);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_TRUE(check_path(cspace, report.path).valid);
  }
}

TEST(NavigationFunctionPlanner, AWorldThatIsNoSphereWorldIsSaidToBe) {
  const World office = shipped("office");
  const auto report = plan_with("navigation-function", CSpace(office), office.queries[0]);
  EXPECT_EQ(report.status, PlanStatus::not_found);
  EXPECT_EQ(report.why_not.rfind("not a sphere world: ", 0), 0u) << report.why_not;
  const World trap = shipped("u_trap");  // the start lies in the disc around the U
  const auto inside = plan_with("navigation-function", CSpace(trap), trap.queries[0]);
  EXPECT_EQ(inside.status, PlanStatus::not_found);
  EXPECT_NE(inside.why_not.find("inside the disc standing for C-obstacle 0"), std::string::npos) << inside.why_not;
}

TEST(NavigationFunctionPlanner, ABadKappaIsNamed) {
  const CSpace cspace(shipped("disc_gap"));
  try {
    planners<TranslatingRobot>().find("navigation-function")->make(cspace, {{"kappa", "0.5"}});
    FAIL() << "kappa 0.5 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("planner navigation-function: kappa", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace polyplan

namespace polyplan {
namespace {

// A sphere world written with discs (data/worlds/sphere_world_disc_bounds.json): its discs and its
// disc bounds are the navigation function's spheres exactly, and it reaches the goal from every
// start, each path checked exactly among the discs; a world with walls is no sphere world.
TEST(RoundNavigationFunctionPlanner, ReachesTheGoalOfASphereWorldFromEveryStart) {
  const World world = test::shipped("sphere_world_disc_bounds");
  const RoundWorld round(world);
  const auto planner = planners<RoundRobot>().find("navigation-function")->make(round, {});
  for (const Query& q : world.queries) {
    SCOPED_TRACE(q.name);
    const auto report = planner->plan(q);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.path.back(), q.goal);
    EXPECT_TRUE(round.check_path(report.path).valid);
    EXPECT_TRUE(report.facts.contains(NavigationFacts::kappa));
  }
  const World walls = test::shipped("disc_robot_floor_plan");
  const RoundWorld floor(walls);
  const auto refused = planners<RoundRobot>().find("navigation-function")->make(floor, {})->plan(walls.queries[0]);
  EXPECT_EQ(refused.status, PlanStatus::not_found);
  EXPECT_NE(refused.why_not.find("not a sphere world: it has walls or polygons besides its discs"), std::string::npos)
      << refused.why_not;
}

}  // namespace
}  // namespace polyplan
