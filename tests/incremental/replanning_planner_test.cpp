// The replanning planners of polygon worlds (dstar-lite, lpastar, repeated-astar): a world whose
// obstacles change as the robot drives its raster, the path checked exactly against the worlds
// before and after the changes; on a world that stays still, the grid cost of an independent
// search; the answers for an obstacle on the robot and a goal shut off; the registry refusing
// every other planner for a changing world.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/incremental/replan_facts.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

World changing_world() {
  return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/changing_worlds/door_closes.json");
}

// The world with its first `made` changes made, written out independently of the planner's own
// bookkeeping: obstacles listed by hand.
World with_changes(World world, std::size_t made) {
  std::vector<PolygonWithHoles> all = world.obstacles;
  std::vector<bool> gone(all.size(), false);
  for (std::size_t i = 0; i < made; ++i) {
    if (world.changes[i].added) {
      all.push_back(*world.changes[i].added);
      gone.push_back(false);
    }
    if (world.changes[i].removed) gone[*world.changes[i].removed] = true;
  }
  world.obstacles.clear();
  world.obstacle_names.clear();
  for (std::size_t k = 0; k < all.size(); ++k)
    if (!gone[k]) {
      world.obstacles.push_back(all[k]);
      world.obstacle_names.push_back("obstacle " + std::to_string(k));
    }
  world.changes.clear();
  return world;
}

PlanReport<ExactPoint> plan_with(const std::string& planner, const CSpace& cspace, const OptionValues& options = {}) {
  return planners<TranslatingRobot>().find(planner)->make(cspace, options)->plan(cspace.world().queries.at(0));
}

// The door closes and the wall beside it goes after 8 moves (the robot is still far from both),
// a wall rises across the lower left after 40: the drive goes round where the wall was, never
// through the door, and keeps clear of the late wall. So its path is free in the final world and
// not in the first (it crosses the removed wall's place).
TEST(ReplanningPlanners, DriveRoundTheChangesOfTheWorld) {
  const World world = changing_world();
  const CSpace cspace(world);
  const CSpace first(with_changes(world, 0)), last(with_changes(world, 3));
  for (const char* planner : {"dstar-lite", "lpastar", "repeated-astar"}) {
    SCOPED_TRACE(planner);
    const auto report = plan_with(planner, cspace);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.path.front(), world.queries[0].start);
    EXPECT_EQ(report.path.back(), world.queries[0].goal);
    EXPECT_TRUE(check_path(last, report.path).valid) << check_path(last, report.path).reason;
    EXPECT_FALSE(check_path(first, report.path).valid);
    EXPECT_EQ(report.facts.at(ReplanFacts::changes_made), 3);
    EXPECT_GE(report.facts.at(ReplanFacts::replans), 3);  // the first plan, then one for each moment of change
    EXPECT_TRUE(report.certificate.certified);
  }
  // The picture's world is the one the drive ended in: obstacle 0 gone, the door and the late wall there.
  const auto recorded =
      planners<TranslatingRobot>().find("dstar-lite")->make(cspace, {})->plan(world.queries[0], QueryOptions{true});
  ASSERT_TRUE(recorded.recording.world_at_end && recorded.recording.cells);
  EXPECT_EQ(recorded.recording.world_at_end->world().obstacles.size(), 4u);
  EXPECT_EQ(recorded.recording.world_at_end->world().obstacle_names.front(), "obstacles[1]");
  EXPECT_FALSE(plan_with("dstar-lite", CSpace(with_changes(world, 0)))
                   .recording.world_at_end);  // a still world is the problem's
}

// The same drive sensing 3 cells around the robot: it learns of the closed door only in front of
// it, so it drives farther, and its path holds in the final world all the same.
TEST(ReplanningPlanners, ASensorOfThreeCellsLearnsOfTheDoorAtTheDoor) {
  const World world = changing_world();
  const CSpace cspace(world);
  const CSpace last(with_changes(world, 3));
  const auto seeing_all = plan_with("dstar-lite", cspace),
             seeing_near = plan_with("dstar-lite", cspace, {{"sensor", "3"}});
  ASSERT_TRUE(seeing_all.found && seeing_near.found) << seeing_near.why_not;
  EXPECT_GT(seeing_near.facts.at(ReplanFacts::moves), seeing_all.facts.at(ReplanFacts::moves));
  EXPECT_GT(seeing_near.facts.at(ReplanFacts::replans), seeing_all.facts.at(ReplanFacts::replans));
  EXPECT_TRUE(check_path(last, seeing_near.path).valid) << check_path(last, seeing_near.path).reason;
}

// In a world that stays still, a robot that sees everything drives a shortest grid path: its cost
// in cells times the cell's side is the raster planner's A* cost (another search, in world units).
TEST(ReplanningPlanners, AStillWorldCostsWhatTheRasterPlannerFinds) {
  World world = with_changes(changing_world(), 0);
  const CSpace cspace(world);
  const auto raster = plan_with("raster", cspace);
  ASSERT_TRUE(raster.found);
  for (const char* planner : {"dstar-lite", "lpastar", "repeated-astar"}) {
    SCOPED_TRACE(planner);
    const auto drive = plan_with(planner, cspace);
    ASSERT_TRUE(drive.found) << drive.why_not;
    EXPECT_NEAR(drive.facts.at(ReplanFacts::grid_cost) * 0.2, raster.facts.at(RasterFacts::grid_cost), 1e-9);
    EXPECT_EQ(drive.facts.at(ReplanFacts::replans), 1);
  }
}

// A wall that rises on the robot's cell, and one that shuts the goal off: not found, saying which.
TEST(ReplanningPlanners, AnObstacleOnTheRobotOrAcrossTheWayIsAnAnswer) {
  World world = with_changes(changing_world(), 0);
  world.changes = {
      WorldChange{0, PolygonWithHoles{{{1, 16}, {3, 16}, {3, 18}, {1, 18}}, {}}, std::nullopt, "changes[0]"}};
  const auto struck = plan_with("dstar-lite", CSpace(world));
  EXPECT_EQ(struck.status, PlanStatus::not_found);
  EXPECT_NE(struck.why_not.find("after 0 moves, the world of changes[0] blocks the robot's own cell"),
            std::string::npos)
      << struck.why_not;

  world.changes = {
      WorldChange{5, PolygonWithHoles{{{8, 9.5}, {10, 9.5}, {10, 10.5}, {8, 10.5}}, {}}, std::nullopt, "changes[0]"}};
  const auto shut = plan_with("dstar-lite", CSpace(world));
  EXPECT_EQ(shut.status, PlanStatus::not_found);
  EXPECT_NE(shut.why_not.find("after 5 moves, no path on the 100 x 100 grid"), std::string::npos) << shut.why_not;
  EXPECT_TRUE(shut.path.empty());
}

TEST(ReplanningPlanners, OnlyTheyAreGivenAWorldThatChanges) {
  const World world = changing_world();
  for (const char* planner : {"dstar-lite", "lpastar", "repeated-astar"})
    EXPECT_NO_THROW(require_planner_for_robot(world, planner));
  try {
    require_planner_for_robot(world, "visibility");
    FAIL() << "visibility was given a world that changes";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("door_closes.json: changes[0]: the world changes as the robot drives"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("(dstar-lite, lpastar, repeated-astar)"), std::string::npos) << e.what();
  }
}

TEST(ReplanningPlanners, ABadSensorIsRefusedNamingTheOption) {
  const CSpace cspace(changing_world());
  const auto* entry = planners<TranslatingRobot>().find("dstar-lite");
  for (const char* bad : {"1", "-2", "nan"}) {
    SCOPED_TRACE(bad);
    try {
      entry->make(cspace, {{"sensor", bad}});
      FAIL() << "sensor " << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("planner dstar-lite: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("sensor"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace polyplan
