// RoundRasterPlanner and RoundGvdGridPlanner: the grid planners on worlds with discs and walls
// (RoundRobot) — a doorway in a wall of zero thickness that coarse cells close and finer ones
// open, a disc robot through the shipped floor plan's doorways, a start inside a disc, and the
// cells recorded for the picture; every path re-checked by RoundWorld::check_path.
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/gvd_grid_planner.hpp>
#include <polyplan/grids/raster_planner.hpp>
#include "round_world_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::expect_checked;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

// A wall along x = 4 with a doorway 1 wide (y 3.5..4.5), point robot, from (1, 4) to (7, 4).
const char* const kDoorway =
    R"({"bounds": [0, 0, 8, 8], "walls": [[[4, 0], [4, 3.5]], [[4, 4.5], [4, 8]]], "start": [1, 4], "goal": [7, 4]})";

TEST(RoundRasterPlanner, ADoorwayClosedByCoarseCellsOpensWithFinerOnes) {
  const RoundWorld world(world_from(kDoorway));
  const Query& q = world.world().queries[0];
  // Unit cells and half cells: every cell beside the wall touches it (the doorway's ends lie on
  // grid lines), so no column of cells gets through.
  for (const std::size_t n : {8u, 16u}) {
    const PlanReport<ExactPoint> closed = RoundRasterPlanner(world, RasterOptions{n}).plan(q);
    EXPECT_EQ(closed.status, PlanStatus::not_found) << "n = " << n;
    EXPECT_NE(closed.why_not.find("no path on the " + std::to_string(n) + " x"), std::string::npos) << closed.why_not;
  }
  // Thirds: the rows (3⅔, 4) and (4, 4⅓) touch neither piece of the wall.
  const PlanReport<ExactPoint> open = RoundRasterPlanner(world, RasterOptions{24}).plan(q);
  expect_checked(world, open, q);
  EXPECT_EQ(open.facts.at(RasterFacts::cells_per_axis), 24);
}

TEST(RoundRasterPlanner, ADiscRobotPassesTheFloorPlansDoorways) {
  const RoundWorld world(test::shipped("disc_robot_floor_plan"));
  RoundRasterPlanner planner(world, RasterOptions{48});
  for (const Query& q : world.world().queries) expect_checked(world, planner.plan(q), q);
  // At 12 cells per axis (cells 1 × 2/3) the doorways, 1 wide for a robot 0.6 across, close.
  EXPECT_EQ(RoundRasterPlanner(world, RasterOptions{12}).plan(world.world().queries[0]).status, PlanStatus::not_found);
}

TEST(RoundRasterPlanner, AStartInsideADiscIsAnInvalidQueryWithTheReason) {
  const RoundWorld world(world_from(R"({"bounds": [0, 0, 8, 8], "discs": [{"center": [2, 2], "radius": 1}]})"));
  const PlanReport<ExactPoint> report =
      RoundRasterPlanner(world, RasterOptions{8}).plan({pt("2", "2.5"), pt("7", "7"), "q"});
  EXPECT_EQ(report.status, PlanStatus::invalid_query);
  EXPECT_NE(report.why_not.find("discs[0]"), std::string::npos) << report.why_not;
}

TEST(RoundRasterPlanner, RecordsTheCellsForThePicture) {
  const RoundWorld world(world_from(kDoorway));
  RoundRasterPlanner planner(world, RasterOptions{24});
  const PlanReport<ExactPoint> report = planner.plan(world.world().queries[0], QueryOptions{true});
  ASSERT_TRUE(report.recording.cells);
  EXPECT_EQ(report.recording.cells->states.size(), 24u * 24u);
  EXPECT_FALSE(report.recording.expanded.empty());
  EXPECT_EQ(report.facts.at(RasterFacts::blocked_cells), static_cast<std::int64_t>(planner.raster().blocked_count()));
}

TEST(RoundGvdGridPlanner, FollowsTheGvdThroughTheDoorwayAndTheSphereWorld) {
  const RoundWorld doorway(world_from(kDoorway));
  const Query& q = doorway.world().queries[0];
  expect_checked(doorway, RoundGvdGridPlanner(doorway, GvdGridOptions{48}).plan(q), q);
  const RoundWorld spheres(test::shipped("sphere_world"));
  RoundGvdGridPlanner planner(spheres, GvdGridOptions{64});
  for (const Query& query : spheres.world().queries) expect_checked(spheres, planner.plan(query), query);
}

}  // namespace
