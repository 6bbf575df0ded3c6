// The conformance test of car planners: every planner of planners<SteeredCar>() (the car's own and
// the sampling planners over the car's sampling space) on every shipped
// world whose robot is a car, every query. A found path starts at the start pose, ends at the goal
// pose (or within a goal region the planner reports, goal_miss), is certified, drives each segment
// to the next entry, passes the independent dense-sampling re-check (car/car_path_check.hpp), is
// no shorter than the steering curve ignoring obstacles, and prints (segments, gear_changes) and
// draws. A status that claims a proof (no_path) is true of the shipped world's design. Worlds
// without a car are refused by name.
#include "car/car_path_check.hpp"
#include "registry/registry_fixtures.hpp"

#include <polyplan/car/car_facts.hpp>
#include <polyplan/car/car_planner.hpp>
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/draw/car_svg.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>

#include <gtest/gtest.h>

#include <map>

namespace polyplan {
namespace {

// What each shipped car world's start/goal must give: hybrid A* finds every path that exists.
const std::map<std::string, PlanStatus> kHybridAStarAnswers = {
    {"car_no_path", PlanStatus::no_path},         {"car_park", PlanStatus::solved},
    {"car_parallel_parking", PlanStatus::solved}, {"car_slalom", PlanStatus::solved},
    {"car_u_turn", PlanStatus::solved},
};

CarPose pose_of(const ExactPoint& p, const std::optional<double>& theta) {
  return {to_double(p.x), to_double(p.y), theta.value_or(0) * pi / 180};
}

class EveryCarPlannerOnEveryWorld : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(EveryCarPlannerOnEveryWorld, KeepsThePlannerPromises) {
  const auto& [planner_name, world_name] = GetParam();
  const World world = read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + world_name + ".json");
  const PlannerEntry<SteeredCar>* entry = planners<SteeredCar>().find(planner_name);
  ASSERT_NE(entry, nullptr);
  // The sampling planners (those that shortcut) stop at an iteration limit, so that both runs
  // give one answer and RRT*, which improves until a limit, ends soon.
  OptionValues options{{"time", "5"}};
  for (const OptionInfo& o : entry->options)
    if (o.name == "shortcut") options.emplace_back("iterations", "3000");
  if (!world.robot.car) {
    EXPECT_THROW(entry->make(world, options), InputError) << "a car planner refuses a robot that is not a car";
    return;
  }
  const auto planner = entry->make(world, options), again = entry->make(world, options);
  const double r = world.robot.car->turning_radius;
  std::vector<PlanReport<CarState>> reports;
  test::SameAnswers same;
  for (std::size_t i = 0; i < world.queries.size(); ++i) {
    const Query& q = world.queries[i];
    SCOPED_TRACE(q.name);
    const PlanReport<CarState> report = planner->plan(q);
    test::expect_consistent_answer(report, q.name);
    same.expect(report, again->plan(q, QueryOptions{true}));
    if (i == 0 && planner_name == "hybrid-astar") {
      EXPECT_EQ(to_string(report.status), to_string(kHybridAStarAnswers.at(world_name)));
    }
    if (world_name == "car_no_path") {
      EXPECT_EQ(report.status, PlanStatus::no_path);
    }
    if (!report.found) continue;
    const CarPose start = pose_of(q.start, q.start_theta), goal = pose_of(q.goal, q.goal_theta);
    ASSERT_FALSE(report.path.empty());
    EXPECT_EQ(report.path.front().pose, start);
    const CarPose end = report.path.back().pose;
    const double miss = std::max(std::hypot(end.x - goal.x, end.y - goal.y),
                                 r * std::abs(std::remainder(end.theta - goal.theta, 2 * pi)));
    if (report.facts.contains(CarFacts::goal_miss)) EXPECT_LE(miss, report.facts.at(CarFacts::goal_miss) + 1e-12);
    else EXPECT_LE(miss, 1e-9 * (1 + std::abs(goal.x) + std::abs(goal.y) + r));
    if (auto why = test::sampled_car_overlap(world, report.path)) ADD_FAILURE() << *why;
    double length = 0;
    for (const CarState& s : report.path) length += s.arrival.length;
    EXPECT_NEAR(report.length, length, 1e-12 * length)
        << "the length is the segments' (summed as the planner sums them)";
    const double shortest =
        world.robot.car->reverse ? reeds_shepp_distance(start, end, r) : dubins_distance(start, end, r);
    EXPECT_GE(report.length, shortest * (1 - 1e-9));
    const nlohmann::json json = plan_json(report, q.name);
    ASSERT_EQ(json["segments"].size(), report.path.size() - 1);
    for (const auto& s : json["segments"]) {
      EXPECT_TRUE(s["steer"] == "L" || s["steer"] == "S" || s["steer"] == "R");
      EXPECT_TRUE(s["gear"] == 1 || s["gear"] == -1);
      EXPECT_EQ(s["start"].size(), 3u);
    }
    EXPECT_EQ(json["gear_changes"].get<std::size_t>(), gear_changes(report.path));
    EXPECT_EQ(json["certified_by"].get<std::string>().rfind(CarCollision::method, 0), 0u) << json["certified_by"];
    if (!world.robot.car->reverse) {
      for (const CarState& s : report.path) EXPECT_EQ(s.arrival.gear, 1) << "a Dubins car never reverses";
    }
    reports.push_back(report);
  }
  EXPECT_NE(draw_plan(world, reports).str().find("<svg"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryCarPlannerOnEveryWorld,
                         ::testing::Combine(::testing::ValuesIn(test::registered_planners<SteeredCar>()),
                                            ::testing::ValuesIn(test::shipped_worlds(false))),
                         [](const auto& info) {
                           return test::test_name(std::get<0>(info.param), std::get<1>(info.param));
                         });

TEST(CarRegistry, ListsTheCarPlanners) {
  EXPECT_EQ(planners<SteeredCar>().names(), "hybrid-astar, car-rrt, prm, lazyprm, rrt, rrtstar, rrtconnect");
}

}  // namespace
}  // namespace polyplan
