// The replanning planners (dstar-lite, lpastar, repeated-astar) on worlds with discs, walls, disc
// bounds and a disc robot (RoundRobot): each shipped round world driven by all three, every path
// checked again by RoundWorld::check_path, and the three driving equal grid costs (the raster
// planner's in world units where the cells are square); an obstacle polygon that rises across the
// straight route, driven round and checked against the world it made; a removed obstacle counted
// among the polygons only; a goal shut in by discs or walls answered with the reason; a changing
// round world refused by the other planners and given to dstar-lite by the front door.
#include "round_world_fixtures.hpp"
#include "world_fixtures.hpp"

#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/incremental/replan_facts.hpp>
#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <gtest/gtest.h>

#include <string>

namespace polyplan {
namespace {

const char* const kReplanners[] = {"dstar-lite", "lpastar", "repeated-astar"};

// A disc robot heads straight from (1, 5) to (9, 5); after 5 moves a block rises across its way (a
// disc above it closes the gap over the block).
const char* const kRisingBlock = R"({"bounds": [0, 0, 10, 10], "robot": {"disc": 0.2},
    "discs": [{"center": [5, 8], "radius": 1}], "start": [1, 5], "goal": [9, 5],
    "changes": [{"after_moves": 5, "add_obstacle": [[4, 3], [6, 3], [6, 7], [4, 7]]}]})";

PlanReport<ExactPoint> drive_round(const std::string& planner, const RoundWorld& world, const Query& query) {
  return planners<RoundRobot>().find(planner)->make(world, {})->plan(query);
}

// The world as it stands once every change is made, written out by hand (the changes here only add).
World with_every_obstacle_added(World world) {
  for (const WorldChange& change : world.changes) {
    world.obstacles.push_back(*change.added);
    world.obstacle_names.push_back(change.name);
  }
  world.changes.clear();
  return world;
}

// A shipped round world, and the side of its raster's cells at the default 100 per axis when they
// are square (0: they are not).
struct ShippedRoundWorld {
  std::string name;
  double square_cell = 0;
};

class RoundReplanningOnShippedWorlds : public ::testing::TestWithParam<ShippedRoundWorld> {};

// Every query of the world, by each planner: found, from the exact start to the exact goal, valid
// by the exact check; the three algorithms drive the same grid cost, and where the cells are square
// that cost in world units is what the raster planner's A* finds on the same raster (another search).
TEST_P(RoundReplanningOnShippedWorlds, EveryPlannerFindsPathsTheExactCheckAccepts) {
  const World world = test::shipped(GetParam().name);
  const RoundWorld round(world);
  const auto raster = planners<RoundRobot>().find("raster")->make(round, {});
  for (const Query& query : world.queries) {
    SCOPED_TRACE(query.name);
    const auto grid = raster->plan(query);
    ASSERT_TRUE(grid.found) << grid.why_not;
    double dstar_cost = -1;
    for (const char* planner : kReplanners) {
      SCOPED_TRACE(planner);
      const auto report = drive_round(planner, round, query);
      ASSERT_NO_FATAL_FAILURE(test::expect_checked(round, report, query));
      EXPECT_EQ(report.facts.at(ReplanFacts::changes_made), 0);
      const double cost = report.facts.at(ReplanFacts::grid_cost);
      if (dstar_cost < 0) dstar_cost = cost;
      EXPECT_EQ(cost, dstar_cost);       // OctileLength exactly: the same shortest cost on the same raster
      if (GetParam().square_cell > 0) {  // braces: EXPECT_NEAR is an if-else of its own
        EXPECT_NEAR(cost * GetParam().square_cell, grid.facts.at(RasterFacts::grid_cost), 1e-9);
      }
    }
  }
}

// The sphere worlds' cells are 0.2 wide (the box [-10, 10]², the square round the disc of radius
// 10); the floor plan's 0.12 x 0.08.
INSTANTIATE_TEST_SUITE_P(Shipped, RoundReplanningOnShippedWorlds,
                         ::testing::Values(ShippedRoundWorld{"sphere_world", 0.2},
                                           ShippedRoundWorld{"sphere_world_disc_bounds", 0.2},
                                           ShippedRoundWorld{"disc_robot_floor_plan", 0}),
                         [](const auto& info) { return info.param.name; });

// The block that rises across the way: each planner replans, drives round below, and its path
// holds in the world the change made, though the straight route does not.
TEST(RoundReplanning, ABlockRisingAcrossTheWayIsDrivenRound) {
  const World world = test::world_from(kRisingBlock);
  const RoundWorld round(world), changed(with_every_obstacle_added(world));
  const Query& query = world.queries.at(0);
  ASSERT_FALSE(changed.check_path({query.start, query.goal}).valid);
  for (const char* planner : kReplanners) {
    SCOPED_TRACE(planner);
    const auto report = drive_round(planner, round, query);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_GE(report.facts.at(ReplanFacts::changes_made), 1);
    EXPECT_GE(report.facts.at(ReplanFacts::replans), 2);  // the first plan, then the change
    const PathCheck check = changed.check_path(report.path);
    EXPECT_TRUE(check.valid) << check.reason;
    EXPECT_GT(report.length, 8.5);  // round the block, not straight
  }
}

// Obstacle 0 of remove_obstacle is the first polygon (discs are not numbered among them): with the
// block gone at once, the drive goes straight through where it stood, past disc 0 untouched.
TEST(RoundReplanning, ARemovedObstacleIsCountedAmongThePolygonsOnly) {
  const World world = test::world_from(R"({"bounds": [0, 0, 10, 10],
      "discs": [{"center": [5, 8.5], "radius": 1}], "obstacles": [[[4, 3], [6, 3], [6, 7], [4, 7]]],
      "start": [1, 5], "goal": [9, 5], "changes": [{"after_moves": 0, "remove_obstacle": 0}]})");
  World without_block = world;
  without_block.obstacles.clear();
  without_block.obstacle_names.clear();
  without_block.changes.clear();
  const RoundWorld round(world), changed(without_block);
  const auto report = drive_round("dstar-lite", round, world.queries.at(0));
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_EQ(report.facts.at(ReplanFacts::changes_made), 1);
  EXPECT_TRUE(changed.check_path(report.path).valid) << changed.check_path(report.path).reason;
  EXPECT_FALSE(round.check_path(report.path).valid);  // through the block's place
}

// A goal shut in by a ring of overlapping discs, and one shut in by walls: no path, and why.
TEST(RoundReplanning, AGoalShutInIsAnAnswerSayingWhy) {
  const World ring = test::world_from(R"({"bounds": [0, 0, 10, 10], "start": [1, 1], "goal": [7, 5],
      "discs": [{"center": [9, 5], "radius": 1.2}, {"center": [8, 6.732], "radius": 1.2},
                {"center": [6, 6.732], "radius": 1.2}, {"center": [5, 5], "radius": 1.2},
                {"center": [6, 3.268], "radius": 1.2}, {"center": [8, 3.268], "radius": 1.2}]})");
  const World walled = test::world_from(R"({"bounds": [0, 0, 10, 10], "start": [1, 1], "goal": [7, 5],
      "robot": {"disc": 0.1}, "walls": [[[6, 4], [8, 4], [8, 6], [6, 6], [6, 4]]]})");
  for (const World* world : {&ring, &walled}) {
    const RoundWorld round(*world);
    for (const char* planner : kReplanners) {
      SCOPED_TRACE(planner);
      const auto report = drive_round(planner, round, world->queries.at(0));
      EXPECT_FALSE(report.found);
      EXPECT_EQ(report.status, PlanStatus::not_found);
      EXPECT_NE(report.why_not.find("after 0 moves, no path on the 100 x 100 grid"), std::string::npos)
          << report.why_not;
      EXPECT_TRUE(report.path.empty());
    }
  }
}

// A round world that changes goes to the planners that follow changes, and only to them; through
// the front door, to dstar-lite when no planner is named.
TEST(RoundReplanning, OnlyTheyAreGivenARoundWorldThatChanges) {
  const World world = test::world_from(kRisingBlock);
  for (const char* planner : kReplanners) EXPECT_NO_THROW(require_planner_for_robot(world, planner)) << planner;
  EXPECT_THROW(require_planner_for_robot(world, "raster"), InputError);
  const Problem problem = Problem::parse(kRisingBlock, "rising_block.json");
  EXPECT_EQ(default_planner(problem), "dstar-lite");
  const Report report = make_planner(default_planner(problem), problem)->plan(0);
  EXPECT_TRUE(report.found()) << report.why_not();
}

}  // namespace
}  // namespace polyplan
