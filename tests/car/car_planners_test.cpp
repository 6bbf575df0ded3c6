// The car's planners on the cases that tell them apart: a corridor narrower than 2R (a Dubins car
// cannot turn round, a Reeds–Shepp car can), a parallel-parking bay (reverse needed), an empty
// world (hybrid A*'s analytic expansion gives the shortest curve at once), start = goal, a blocked
// start, the options refused, and car-rrt's seed.
#include "car/car_fixtures.hpp"
#include "car/car_path_check.hpp"

#include <polyplan/car/car_facts.hpp>
#include <polyplan/car/car_planner.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/sampling_facts.hpp>

#include <gtest/gtest.h>

namespace polyplan {
namespace {

World shipped(const std::string& name, bool reverse = true) {
  World world = read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json");
  world.robot.car->reverse = reverse;
  return world;
}

PlanReport<CarState> plan(const std::string& planner, const World& world, OptionValues options = {},
                          std::size_t query = 0) {
  return planners<SteeredCar>().find(planner)->make(world, options)->plan(world.queries.at(query));
}

TEST(CarPlanners, AReedsSheppCarTurnsRoundInACorridorNarrowerThanTwoRadiiADubinsCarCannot) {
  const World reeds_shepp = shipped("car_u_turn", true), dubins = shipped("car_u_turn", false);
  for (const char* planner : {"hybrid-astar", "car-rrt", "rrt", "rrtconnect"}) {
    SCOPED_TRACE(planner);
    const auto turned = plan(planner, reeds_shepp);
    ASSERT_TRUE(turned.found) << turned.why_not;
    EXPECT_GE(turned.facts.at(CarFacts::gear_changes), 2) << "a three-point turn at least";
    if (auto why = test::sampled_car_overlap(reeds_shepp, turned.path)) ADD_FAILURE() << *why;
    const auto stuck = plan(planner, dubins, {{"time", "1"}, {"iterations", "2000"}});
    EXPECT_FALSE(stuck.found);
  }
  EXPECT_EQ(plan("hybrid-astar", dubins).status, PlanStatus::not_found);  // it closes every bin it reaches
}

TEST(CarPlanners, ParallelParkingReversesIntoTheBay) {
  const World world = shipped("car_parallel_parking");
  const auto parked = plan("hybrid-astar", world);
  ASSERT_TRUE(parked.found) << parked.why_not;
  bool reversed = false;
  for (const CarState& s : parked.path) reversed |= s.arrival.gear < 0 && s.arrival.length > 0;
  EXPECT_TRUE(reversed);
  if (auto why = test::sampled_car_overlap(world, parked.path)) ADD_FAILURE() << *why;
  EXPECT_FALSE(plan("hybrid-astar", shipped("car_parallel_parking", false)).found)
      << "forward only, the bay is too short";
}

TEST(CarPlanners, InAnEmptyWorldHybridAStarDrivesTheShortestCurveAtOnce) {
  const World world =
      test::car_world(R"({"obstacles": [], "robot": {"parts": [[[-1, -0.5], [2, -0.5], [2, 0.5], [-1, 0.5]]],
    "car": {"turning_radius": 2, "reverse": true}}, "start": [0, 0, 0], "goal": [3, 4, 200]})");
  const auto report = plan("hybrid-astar", world);
  ASSERT_TRUE(report.found);
  EXPECT_EQ(report.facts.at(SearchFacts::expanded), 1);
  EXPECT_NEAR(report.length, reeds_shepp_distance({0, 0, 0}, {3, 4, 200 * pi / 180}, 2), 1e-12);
}

TEST(CarPlanners, StartEqualToGoalAndABlockedStartAreAnswers) {
  const World world = test::car_world(R"({"obstacles": [[[4, -1], [5, -1], [5, 1], [4, 1]]],
    "robot": {"parts": [[[-1, -0.5], [2, -0.5], [2, 0.5], [-1, 0.5]]], "car": {"turning_radius": 2}},
    "start": [0, 0, 90], "goal": [0, 0, 90], "queries": [{"start": [3, 0, 0], "goal": [0, 5, 0]}]})");
  for (const char* planner : {"hybrid-astar", "car-rrt"}) {
    const auto same = plan(planner, world);
    ASSERT_TRUE(same.found);
    EXPECT_EQ(same.path.size(), 1u);
    EXPECT_EQ(same.length, 0);
    const auto blocked = planners<SteeredCar>().find(planner)->make(world, {})->plan(world.queries[1]);
    EXPECT_EQ(blocked.status, PlanStatus::invalid_query);
    EXPECT_NE(blocked.why_not.find("the start [3, 0, 0°] is not free: the car's body meets obstacles[0]"),
              std::string::npos)
        << blocked.why_not;
  }
}

TEST(CarPlanners, BadOptionsNameThePlannerAndTheOption) {
  const World world = shipped("car_u_turn");
  const auto refuses = [&](const char* planner, OptionValues options, const std::string& message) {
    try {
      planners<SteeredCar>().find(planner)->make(world, options);
      ADD_FAILURE() << "accepted " << options[0].first;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refuses("hybrid-astar", {{"headings", "2"}},
          "planner hybrid-astar: option headings=2: expected a whole number in [4, 3600]");
  refuses("hybrid-astar", {{"reverse-cost", "0.5"}},
          "planner hybrid-astar: option reverse-cost=0.5: expected a number in [1, inf)");
  refuses("car-rrt", {{"goal-bias", "2"}}, "planner car-rrt: option goal-bias=2: expected a number in [0, 1]");
  refuses("car-rrt", {{"dt", "-1"}}, "planner car-rrt: option dt=-1: expected a number in [0, inf)");
}

TEST(CarPlanners, CarRrtIsTheSameForOneSeedAndOtherForAnother) {
  const World world = shipped("car_park");
  const auto a = plan("car-rrt", world, {{"seed", "3"}}), b = plan("car-rrt", world, {{"seed", "3"}}),
             c = plan("car-rrt", world, {{"seed", "4"}});
  ASSERT_TRUE(a.found && b.found && c.found);
  EXPECT_EQ(a.path, b.path);
  EXPECT_NE(a.path, c.path);
  EXPECT_EQ(a.facts.at(SamplingFacts::seed), 3);
}

}  // namespace
}  // namespace polyplan
