// Bug1 and Bug2 among walls of zero thickness (the course's Bug material draws its walls as lines):
// a wall is an obstacle of two sides — up one, round its end, down the other — and the walks are
// checked exactly, their lengths against sums computed by hand, within the textbook's bounds; a
// wall meeting a polygon and the bounds joins their boundaries into one; a polygon robot's walls
// are its Minkowski sums. Along arcs: round a disc, a disc robot round a square, disc bounds, the
// course's sphere world, the walks checked apart from the planner, their lengths by hand.
#include "registry/piece_path_check.hpp"
#include "world_fixtures.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace polyplan {
namespace {

constexpr FactKey<double> tangent_length_lower{"length_lower"}, tangent_length_upper{"length_upper"};

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

// The walk along arcs, checked apart from the planner (registry/piece_path_check.hpp: in doubles
// every 1/400 of each piece, and the segment pieces exactly as printed), found or not as `found`.
void expect_pieces(const PlanReport<ExactPoint>& report, const RoundWorld& world, double length) {
  ASSERT_TRUE(report.found) << report.why_not;
  test::expect_valid_pieces(world.world(), report, [&](const auto& p) { return world.check_path(p); });
  EXPECT_NEAR(report.length, length, 1e-9 * length);
  EXPECT_LE(report.facts.at(tangent_length_lower), length + 1e-12 * length);
  EXPECT_GE(report.facts.at(tangent_length_upper), length - 1e-12 * length);
  EXPECT_LE(report.facts.at(BugFacts::distance), report.facts.at(BugFacts::bound) * (1 + 1e-12));
}

std::size_t arcs(const PlanReport<ExactPoint>& report) {
  return static_cast<std::size_t>(std::count_if(report.pieces.begin(), report.pieces.end(),
                                                [](const PathPiece& p) { return p.kind == PathPiece::Kind::arc; }));
}

// A point robot, the unit disc, from (-3, 0) to (3, 0): Bug2 hits at (-1, 0), goes over the top
// (clockwise, the disc on its right) to (1, 0) and on: 2 + π + 2. Bug1 goes once round (2π), then
// on to (1, 0), half round either way (it takes the way it walked): 2 + 3π + 2.
TEST(BugPlannersAlongArcs, GoRoundADisc) {
  const RoundWorld world(parse_world(R"({"discs": [{"center": [0, 0], "radius": 1}], "start": [-3, 0],
                                         "goal": [3, 0]})",
                                     "disc.json"));
  const auto two = walk("bug2", world);
  expect_pieces(two, world, 4 + M_PI);
  EXPECT_EQ(two.facts.at(BugFacts::hits), (FactPoints{{-1, 0}}));
  EXPECT_EQ(two.facts.at(BugFacts::leaves), (FactPoints{{1, 0}}));
  ASSERT_EQ(arcs(two), 1u);
  EXPECT_FALSE(two.pieces[1].counter_clockwise);  // the disc on its right: over the top
  expect_pieces(walk("bug1", world), world, 4 + 3 * M_PI);
}

// A disc robot of radius 1/2 round the square [-1, 1]²: its C-obstacle is the square grown by 1/2,
// four sides and four quarter circles. From (-4, 0) to (4, 0) Bug2 hits at (-1.5, 0), climbs the
// left side (1), rounds the corner (π/4), crosses the top (2), rounds the other corner (π/4), comes
// down (1) to (1.5, 0) and leaves: 2.5 + 4 + π/2 + 2.5.
TEST(BugPlannersAlongArcs, ADiscRobotGoesRoundASquareGrownByItsRadius) {
  const RoundWorld world(parse_world(R"({"robot": {"disc": 0.5}, "obstacles": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]],
                                         "start": [-4, 0], "goal": [4, 0]})",
                                     "square.json"));
  const auto two = walk("bug2", world);
  expect_pieces(two, world, 9 + M_PI / 2);
  EXPECT_EQ(arcs(two), 2u);
  EXPECT_EQ(two.facts.at(BugFacts::leaves), (FactPoints{{1.5, 0}}));
  const auto one = walk("bug1", world);  // once round (8 + π), then back down to (1.5, 0)
  expect_pieces(one, world, 5 + 8 + M_PI + 4 + M_PI / 2);
}

// Disc bounds of radius 5 split by a wall from (0, -5) to (0, 5): the walk goes up the wall, round
// the bounds' circle (counter-clockwise, the free space inside on its left) and down the wall again
// to its hit point — the goal is unreachable, and both Bugs say so.
TEST(BugPlannersAlongArcs, FollowDiscBoundsAndAWallToNoPath) {
  const RoundWorld world(parse_world(R"({"bounds": {"center": [0, 0], "radius": 5}, "walls": [[[0, -5], [0, 5]]],
                                         "start": [-2, 0], "goal": [2, 0]})",
                                     "halves.json"));
  for (const char* bug : {"bug1", "bug2"}) {
    SCOPED_TRACE(bug);
    const auto report = walk(bug, world);
    EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
    EXPECT_NE(report.why_not.find("the goal is unreachable"), std::string::npos) << report.why_not;
    EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{0, 0}}));
    // The walk is returned, checked: up the wall (5), half round the circle (5π), up to the hit (5).
    EXPECT_NEAR(report.facts.at(BugFacts::distance), 2 + 10 + 5 * M_PI, 1e-9);
  }
}

// The course's sphere world, every query: each walk a valid motion along arcs, within its bound.
TEST(BugPlannersAlongArcs, WalkTheCoursesSphereWorld) {
  const RoundWorld world(test::shipped("sphere_world"));
  for (std::size_t q = 0; q < world.world().queries.size(); ++q)
    for (const char* bug : {"bug1", "bug2"}) {
      SCOPED_TRACE(std::string(bug) + " query " + std::to_string(q));
      const auto report = walk(bug, world, q);
      ASSERT_TRUE(report.found) << report.why_not;
      test::expect_valid_pieces(world.world(), report, [&](const auto& p) { return world.check_path(p); });
      EXPECT_LE(report.facts.at(BugFacts::distance), report.facts.at(BugFacts::bound) * (1 + 1e-12));
    }
}

}  // namespace
}  // namespace polyplan
