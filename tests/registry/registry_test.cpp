// The conformance test of polygon-world planners: every planner of planners<TranslatingRobot>() on
// every world of data/worlds and every query, with its default options. A planner added to the
// registry is tested here without a test of its own. Each report must keep planner.hpp's promises:
// a found path runs exactly from start to goal, passes the independent exact check_path, is
// certified, and is no shorter than the exact shortest path (the reduced visibility graph's,
// itself re-checked); a path not found comes with a reason and a status, and a status that claims
// a proof (no_path, invalid_query) is true of the exact C-space. The report must also print
// (plan_json) and draw (draw_plan), and a second planner built alike, recording what a picture
// needs, must give the same answer.
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/rotation/rotation_facts.hpp>
#include "registry/registry_fixtures.hpp"
#include "rotation/pose_motion_check.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

namespace polyplan {
namespace {

// A world, its C-space, and the exact shortest path lengths of its queries, built once per world.
struct ShippedWorld {
  World world;
  CSpace cspace;
  std::vector<std::optional<double>> shortest;
  explicit ShippedWorld(const std::string& name)
      : world(read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json")), cspace(world) {
    VisibilityGraph reference(cspace);
    for (const Query& q : world.queries) {
      const auto report = reference.plan(q);
      shortest.push_back(report.found ? std::optional<double>(report.length) : std::nullopt);
    }
  }
};

const ShippedWorld& shipped(const std::string& name) {
  static std::map<std::string, std::unique_ptr<ShippedWorld>> cache;
  auto& slot = cache[name];
  if (!slot) slot = std::make_unique<ShippedWorld>(name);
  return *slot;
}

// "roadmap.kind" as the JSON pointer /roadmap/kind.
nlohmann::json::json_pointer dotted(std::string name) {
  std::replace(name.begin(), name.end(), '.', '/');
  return nlohmann::json::json_pointer("/" + name);
}

class EveryPlannerOnEveryWorld : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(EveryPlannerOnEveryWorld, KeepsThePlannerPromises) {
  const auto& [planner_name, world_name] = GetParam();
  const ShippedWorld& w = shipped(world_name);
  const PlannerEntry<TranslatingRobot>* entry = planners<TranslatingRobot>().find(planner_name);
  ASSERT_NE(entry, nullptr);
  if (w.world.robot.car)
    GTEST_SKIP() << "the robot is a car: a question for planners<SteeredCar>() (car_registry_test.cpp)";
  if (turns_the_robot(w.world)) GTEST_SKIP() << "the robot must turn: a question for planners<RotatingRobot>()";
  // Defaults, but sampling planners stop after 0.25 s where a passage is too narrow to sample
  // (corridor_wide's is 10^-9 wide) or there is none: an answer either way, and a quick one.
  OptionValues options;
  for (const OptionInfo& o : entry->options) {
    if (o.name == "time") options.emplace_back("time", "0.25");
    if (o.name == "iterations" && entry->anytime)
      options.emplace_back("iterations", "8000");  // repeatable, and ends soon
  }
  std::unique_ptr<Planner<TranslatingRobot>> planner, again;
  try {
    planner = entry->make(w.cspace, options);
    // A second planner built alike, asked the same queries with pictures recorded: the answers
    // must not change (a roadmap planner's roadmap grows from query to query, so it cannot be
    // asked twice itself).
    again = entry->make(w.cspace, options);
  } catch (const InputError& e) {
    // A planner may need what a world lacks (a raster needs bounds); it must say so, naming the file.
    EXPECT_FALSE(w.world.bounds.has_value()) << e.what();
    EXPECT_NE(std::string(e.what()).find(world_name), std::string::npos) << e.what();
    GTEST_SKIP() << e.what();
  }
  ASSERT_FALSE(w.world.queries.empty());
  std::vector<PlanReport<ExactPoint>> recorded;
  test::SameAnswers same;
  for (std::size_t i = 0; i < w.world.queries.size(); ++i) {
    const Query& q = w.world.queries[i];
    SCOPED_TRACE(q.name);
    const PlanReport<ExactPoint> report = planner->plan(q);
    test::expect_consistent_answer(report, q.name);
    if (report.found) {
      ASSERT_GE(report.path.size(), 2u);
      EXPECT_EQ(report.path.front(), q.start);
      EXPECT_EQ(report.path.back(), q.goal);
      const PathCheck check = check_path(w.cspace, report.path);
      EXPECT_TRUE(check.valid) << check.reason;
      EXPECT_NEAR(report.length, euclidean_length(report.path), 1e-9 * std::max(1.0, report.length));
      ASSERT_TRUE(w.shortest[i].has_value()) << "a path where the exact shortest path finds none";
      EXPECT_GE(report.length, *w.shortest[i] - 1e-9 * std::max(1.0, *w.shortest[i]));
    } else if (!report.path.empty()) {  // a walk that stopped short: from the start, and free
      EXPECT_EQ(report.path.front(), q.start);
      const PathCheck check = check_path(w.cspace, report.path);
      EXPECT_TRUE(check.valid) << check.reason;
    }
    // A status that claims a proof is checked against the exact C-space.
    if (report.status == PlanStatus::invalid_query) {  // braces: EXPECT_TRUE is an if-else of its own
      EXPECT_TRUE(w.cspace.query_not_free(q).has_value());
    }
    if (report.status == PlanStatus::no_path) {
      EXPECT_FALSE(w.cspace.query_not_free(q).has_value());
      EXPECT_FALSE(w.shortest[i].has_value()) << "no_path claimed where the exact shortest path exists";
    }
    // The JSON the programs print holds every fact.
    const nlohmann::json json = plan_json(report, q.name);
    EXPECT_EQ(json["path_exact"].size(), report.path.size());
    for (const auto& [name, value] : report.facts.entries()) EXPECT_TRUE(json.contains(dotted(name))) << name;
    recorded.push_back(again->plan(q, QueryOptions{true}));
    same.expect(report, recorded.back());
  }
  const std::string picture = draw_plan(w.cspace, recorded).str();
  EXPECT_NE(picture.find("<svg"), std::string::npos);
  for (std::size_t i = 0; i < recorded.size(); ++i) {
    if (recorded[i].found) {  // braces: EXPECT_NE is an if-else of its own (-Wdangling-else)
      EXPECT_NE(picture.find(recorded.size() == 1 ? "path" : "path " + std::to_string(i)), std::string::npos);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryPlannerOnEveryWorld,
                         ::testing::Combine(::testing::ValuesIn(test::registered_planners<TranslatingRobot>()),
                                            ::testing::ValuesIn(test::shipped_worlds(false))),
                         [](const auto& info) {
                           return test::test_name(std::get<0>(info.param), std::get<1>(info.param));
                         });

// The conformance test of rotating-robot planners: every planner of planners<RotatingRobot>() on
// every shipped world and query (30° apart, to keep it quick: the rotation worlds' own tests try
// finer steps). A found path runs from the start pose to the goal pose, changes position or
// rotation in each motion, never both, passes the dense sampling re-check, and is no shorter than
// the exact shortest translation of the robot as drawn where start and goal are at 0°; the report
// prints and draws.
class EveryRotatingPlannerOnEveryWorld : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(EveryRotatingPlannerOnEveryWorld, KeepsThePlannerPromises) {
  const auto& [planner_name, world_name] = GetParam();
  const World world = read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + world_name + ".json");
  const PlannerEntry<RotatingRobot>* entry = planners<RotatingRobot>().find(planner_name);
  ASSERT_NE(entry, nullptr);
  if (world.robot.car)
    GTEST_SKIP() << "the robot is a car: a question for planners<SteeredCar>() (car_registry_test.cpp)";
  const auto planner = entry->make(world, {{"rotation-step", "30"}}),
             again = entry->make(world, {{"rotation-step", "30"}});
  std::vector<PlanReport<Pose>> reports;
  test::SameAnswers same;
  for (const Query& q : world.queries) {
    SCOPED_TRACE(q.name);
    const PlanReport<Pose> report = planner->plan(q);
    test::expect_consistent_answer(report, q.name);
    same.expect(report, again->plan(q));
    if (report.found) {
      ASSERT_GE(report.path.size(), 1u);
      EXPECT_EQ(report.path.front().position, q.start);
      EXPECT_EQ(report.path.back().position, q.goal);
      if (auto why = test::check_motions_are_single(report.path)) ADD_FAILURE() << *why;
      if (auto why = test::sampled_overlap(world, report.path, 0.05)) ADD_FAILURE() << *why;
      if (!q.start_theta.value_or(0) && !q.goal_theta.value_or(0) && report.facts.at(RotationFacts::rotation) == 0) {
        const CSpace cspace(world);
        const auto translating = VisibilityGraph(cspace).plan(q);
        ASSERT_TRUE(translating.found);
        EXPECT_GE(report.length, translating.length - 1e-9 * std::max(1.0, translating.length));
      }
    }
    const nlohmann::json json = plan_json(report, q.name);
    EXPECT_EQ(json["path"].size(), report.path.size());
    for (const auto& entry : json["path"]) EXPECT_EQ(entry.size(), 3u);        // [x, y, theta]
    for (const auto& entry : json["path_exact"]) EXPECT_EQ(entry.size(), 4u);  // x, y, sin, cos
    for (const auto& [name, value] : report.facts.entries()) EXPECT_TRUE(json.contains(dotted(name))) << name;
    reports.push_back(report);
  }
  EXPECT_NE(draw_plan(world, reports).str().find("<svg"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryRotatingPlannerOnEveryWorld,
                         ::testing::Combine(::testing::ValuesIn(test::registered_planners<RotatingRobot>()),
                                            ::testing::ValuesIn(test::shipped_worlds(false))),
                         [](const auto& info) {
                           return test::test_name(std::get<0>(info.param), std::get<1>(info.param));
                         });

TEST(Registry, ListsTheDesignsPlannersWithDescriptionsAndOptions) {
  const auto& registry = planners<TranslatingRobot>();
  for (const char* name : {"visibility", "visibility-full", "raster", "trapezoid", "voronoi", "gvd-grid"}) {
    const auto* entry = registry.find(name);
    ASSERT_NE(entry, nullptr) << name;
    EXPECT_FALSE(entry->description.empty());
    EXPECT_EQ(entry->description.find('\n'), std::string::npos) << "one line";
  }
  EXPECT_EQ(registry.find("teleport"), nullptr);
  EXPECT_EQ(registry.names(),
            "visibility, visibility-full, raster, trapezoid, voronoi, gvd-grid, dstar-lite, lpastar, repeated-astar, "
            "potential-field, navigation-function, bug1, bug2, tangent-bug, homotopy, tether, prm, lazyprm, rrt, "
            "rrtstar, rrtconnect");
  EXPECT_EQ(planners<RotatingRobot>().names(), "rotation");
  const auto* raster = registry.find("raster");
  ASSERT_EQ(raster->options.size(), 7u);
  EXPECT_EQ(raster->options[0].name, "resolution");
  EXPECT_EQ(raster->options[0].default_value, "100");
}

TEST(Registry, OptionsAreSetByNameAndBadOnesNameThePlannerAndTheOption) {
  const ShippedWorld& w = shipped("sphere_world_polygons");
  const auto* raster = planners<TranslatingRobot>().find("raster");
  const auto coarse = raster->make(w.cspace, {{"resolution", "10"}, {"search", "dijkstra"}})->plan(w.world.queries[1]);
  EXPECT_EQ(coarse.facts.at(RasterFacts::cells_per_axis), 10);
  EXPECT_EQ(coarse.facts.at(SearchFacts::algorithm), "dijkstra");
  const auto message = [&](const OptionValues& values) {
    try {
      raster->make(w.cspace, values);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{"resolution", "ten"}}), "planner raster: option resolution=ten: expected a whole number");
  EXPECT_EQ(message({{"resolution", "-3"}}), "planner raster: option resolution=-3: expected a whole number >= 0");
  EXPECT_EQ(message({{"colour", "red"}}),
            "planner raster: option colour=red: no such option (its options: resolution, connectivity, corner-cutting, "
            "diagonal-cost, search, weight, "
            "reopen)");
  EXPECT_EQ(message({{"connectivity", "6"}}), "planner raster: option connectivity=6: expected one of 8|4");
  EXPECT_EQ(message({{"weight", "0.5"}}), "planner raster: option weight=0.5: expected a number in [1, inf)");
  EXPECT_EQ(message({{"resolution", "0"}}),
            "planner raster: option resolution=0: expected a whole number in [1, 2048]");
}

TEST(Registry, TwoEntriesOfOneNameAreRefused) {
  EXPECT_THROW((PlannerRegistry<TranslatingRobot>{"visibility",
                                                  {visibility_planner_entry(VisibilityKind::reduced),
                                                   visibility_planner_entry(VisibilityKind::reduced)}}),
               std::logic_error);
}

TEST(Registry, ADefaultNobodyRegisteredIsRefused) {
  EXPECT_THROW((PlannerRegistry<TranslatingRobot>{"raster", {visibility_planner_entry(VisibilityKind::reduced)}}),
               std::logic_error);
}

}  // namespace
}  // namespace polyplan
