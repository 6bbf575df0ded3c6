// TangentBug among discs, walls and a disc robot: with an unlimited range it walks the shortest
// path round one convex obstacle (its length the tangent visibility graph's, an independent method,
// and a closed form); touch-only it slides along the arc from where it hit; it never passes through
// a wall, whose points have two sides; a goal shut in by walls is no_path; every walk is checked
// apart from the planner, piece by piece.
#include "registry/piece_path_check.hpp"
#include "world_fixtures.hpp"

#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

PlanReport<ExactPoint> plan(const char* planner, const RoundWorld& world, const std::string& range = "inf",
                            std::size_t query = 0) {
  OptionValues options;
  if (std::string(planner) == "tangent-bug") options = {{"sensor-range", range}};
  return planners<RoundRobot>().find(planner)->make(world, options)->plan(world.world().queries[query]);
}

// Found, and the walk a valid motion as an independent check finds it.
void expect_walked(const PlanReport<ExactPoint>& report, const RoundWorld& world) {
  ASSERT_TRUE(report.found) << report.why_not;
  test::expect_valid_pieces(world.world(), report, [&](const auto& p) { return world.check_path(p); });
}

// The unit disc from (-3, 0) to (3, 0). Seeing all, the robot heads for the touching point
// (-1/3, √8/3), slides along the arc to where the goal comes into sight, (1/3, √8/3), and on: the
// shortest path, 2√8 + π − 2 acos(1/3). Touch-only it meets the disc at (-1, 0) and slides over the
// top to that same point: 2 + π − acos(1/3) + √8.
TEST(TangentBugAlongArcs, RoundADiscSeeingAllItWalksTheShortestPath) {
  const RoundWorld world(
      parse_world(R"({"discs": [{"center": [0, 0], "radius": 1}], "start": [-3, 0], "goal": [3, 0]})", "disc.json"));
  const auto far = plan("tangent-bug", world);
  expect_walked(far, world);
  EXPECT_NEAR(far.length, 2 * std::sqrt(8.0) + M_PI - 2 * std::acos(1.0 / 3), 1e-9);
  EXPECT_NEAR(far.length, plan("visibility", world).length, 1e-9);
  const auto touch = plan("tangent-bug", world, "0");
  expect_walked(touch, world);
  EXPECT_NEAR(touch.length, 2 + M_PI - std::acos(1.0 / 3) + std::sqrt(8.0), 1e-9);
  EXPECT_EQ(touch.facts.at(BugFacts::hits), (FactPoints{}));  // it slid: no local minimum, no following
}

// A disc robot of radius 1/2 round the square [-1, 1]²: the C-obstacle is the square grown by 1/2.
// Seeing all, TangentBug's walk is the tangent visibility graph's shortest path.
TEST(TangentBugAlongArcs, ADiscRobotSeeingAllWalksTheShortestPathRoundASquare) {
  const RoundWorld world(parse_world(R"({"robot": {"disc": 0.5}, "obstacles": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]],
                                         "start": [-4, 0], "goal": [4, 0]})",
                                     "square.json"));
  const auto report = plan("tangent-bug", world);
  expect_walked(report, world);
  const auto shortest = plan("visibility", world);
  ASSERT_TRUE(shortest.found) << shortest.why_not;
  EXPECT_NEAR(report.length, shortest.length, 1e-9);
  for (const char* range : {"0", "1"}) {  // seeing less it walks further, never through the obstacle
    SCOPED_TRACE(range);
    const auto near = plan("tangent-bug", world, range);
    expect_walked(near, world);
    EXPECT_GT(near.length, shortest.length + 0.1);
  }
}

// The course's wall x = 0 from y = -100 to 100, a line. From (-3, 0.5) to (2, 0) the robot meets it
// at (0, 0.2), slides down to (0, 0) (nearest the goal), follows it up (the obstacle on its right),
// round the end and sees the goal: √9.09 + 0.2 + 100 + √10004. Never through the wall.
TEST(TangentBugAlongArcs, GoesRoundAWallOfZeroThickness) {
  const RoundWorld world(test::shipped("walls_bug"));
  const auto report = plan("tangent-bug", world);
  expect_walked(report, world);
  EXPECT_NEAR(report.length, std::sqrt(9.09) + 100.2 + std::sqrt(10004.0), 1e-9);
  EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{0, 0}}));
}

// A goal inside a closed square of walls, in disc bounds, a disc on the way: no_path at every range.
TEST(TangentBugAlongArcs, AGoalShutInByWallsIsNoPath) {
  const RoundWorld world(parse_world(R"({"bounds": {"center": [0, 0], "radius": 10},
      "walls": [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]], "discs": [{"center": [-1, 0], "radius": 0.5}],
      "start": [-3, 0], "goal": [2, 2]})",
                                     "shut_in.json"));
  for (const char* range : {"inf", "0", "1"}) {
    SCOPED_TRACE(range);
    const auto report = plan("tangent-bug", world, range);
    EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
    EXPECT_NE(report.why_not.find("the goal is unreachable"), std::string::npos) << report.why_not;
  }
}

// The course's sphere world and the floor plans, every query at three ranges: each walk found and
// valid.
TEST(TangentBugAlongArcs, WalksTheShippedRoundWorlds) {
  for (const char* name : {"sphere_world", "disc_robot_floor_plan", "polygon_robot_floor_plan"}) {
    const RoundWorld world(test::shipped(name));
    for (std::size_t q = 0; q < world.world().queries.size(); ++q)
      for (const char* range : {"inf", "2", "0"}) {
        SCOPED_TRACE(std::string(name) + " query " + std::to_string(q) + " range " + range);
        expect_walked(plan("tangent-bug", world, range, q), world);
      }
  }
}

}  // namespace
}  // namespace polyplan
