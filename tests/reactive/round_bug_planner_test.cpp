// Bug1 and Bug2 among walls of zero thickness (the course's Bug material draws its walls as lines):
// a wall is an obstacle of two sides — up one, round its end, down the other — and the walks are
// checked exactly, their lengths against sums computed by hand, within the textbook's bounds; a
// wall meeting a polygon and the bounds joins their boundaries into one; a polygon robot's walls
// are its Minkowski sums; worlds whose C-obstacles have arcs are refused, naming them.
#include "world_fixtures.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

PlanReport<ExactPoint> walk(const char* bug, const RoundWorld& world, std::size_t query = 0) {
  return planners<RoundRobot>().find(bug)->make(world, {})->plan(world.world().queries[query]);
}

void expect_walked(const PlanReport<ExactPoint>& report, const RoundWorld& world, double length) {
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_TRUE(world.check_path(report.path).valid);
  EXPECT_NEAR(report.length, length, 1e-9);
  EXPECT_LE(report.facts.at(BugFacts::distance), report.facts.at(BugFacts::bound));
}

// The course's wall x = 0, y from -100 to 100, a line; from (-3, 0.5) to (2, 0) the m-line meets it
// at (0, 0.2). Bug2 goes up the near side, round the end and down the far side to (0, 0.2) again,
// now with the goal in sight: √9.09 + 2 · 99.8 + √4.04. Bug1 goes once round (400), then to the
// nearest point (0, 0) on the far side the shorter way (99.8 + 100), then on: √9.09 + 599.8 + 2.
TEST(BugPlannersAmongWalls, GoRoundAWallOfZeroThickness) {
  const RoundWorld world(test::shipped("walls_bug"));
  const auto two = walk("bug2", world);
  expect_walked(two, world, std::sqrt(9.09) + 199.6 + std::sqrt(4.04));
  EXPECT_EQ(two.facts.at(BugFacts::hits), (FactPoints{{0, 0.2}}));
  EXPECT_EQ(two.facts.at(BugFacts::leaves), (FactPoints{{0, 0.2}}));
  expect_walked(walk("bug1", world), world, std::sqrt(9.09) + 599.8 + 2);
}

// Box [0, 10]², the square [4, 6]², and a wall from the square's top (5, 6) up to the box's top:
// from (2, 5) to (8, 5) Bug2 hits the square at (4, 5), climbs to its top, up the wall's left side,
// round the whole box (the wall and the bounds shut the way over the square), down the wall's
// right side and the square's right side to (6, 5), and on: 2 + 1 + 1 + 4 + 5 + 30 + 5 + 4 + 1 + 1
// + 2 = 56.
TEST(BugPlannersAmongWalls, AWallMeetingASquareAndTheBoundsIsOneBoundary) {
  World w = parse_world(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
                                "walls": [[[5, 6], [5, 10]]], "start": [2, 5], "goal": [8, 5]})",
                        "square_and_wall.json");
  const RoundWorld world(w);
  const auto two = walk("bug2", world);
  expect_walked(two, world, 56);
  EXPECT_EQ(two.facts.at(BugFacts::leaves), (FactPoints{{6, 5}}));
}

// A square robot 1 wide and walls along x = 0 leaving a door at y -1..1: heading along y = 5 it
// meets the upper wall's sum, goes round (the sums reach the bounds) and through the door; the
// walk is a valid motion within its bound.
TEST(BugPlannersAmongWalls, APolygonRobotWalksRoundTheWallsSums) {
  const RoundWorld world(parse_world(R"({"bounds": [-5, -10, 5, 10],
      "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]},
      "walls": [[[0, -10], [0, -1]], [[0, 1], [0, 10]]], "start": [-3, 5], "goal": [3, 5]})",
                                     "door.json"));
  for (const char* bug : {"bug1", "bug2"}) {
    SCOPED_TRACE(bug);
    const auto report = walk(bug, world);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_TRUE(world.check_path(report.path).valid);
    EXPECT_LE(report.facts.at(BugFacts::distance), report.facts.at(BugFacts::bound));
    EXPECT_GT(report.length, 6);  // round, not through the wall
  }
}

TEST(BugPlannersAmongWalls, ArcsAreRefusedNamingThem) {
  const RoundWorld world(test::shipped("sphere_world"));
  try {
    walk("bug2", world);
    ADD_FAILURE() << "a world of discs walked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sphere_world.json: discs: the planner bug2 follows boundaries of straight "
                                         "edges only"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace polyplan
