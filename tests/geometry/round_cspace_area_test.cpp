// The free area of round worlds (geometry/round_cspace_area.hpp) against closed forms: the bounds
// hold the exact area and lie within 1e-9 of each other; without radii the area is the polygon
// world's, exactly.
#include <polyplan/geometry/round_cspace_area.hpp>

#include <polyplan/geometry/cspace.hpp>

#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polyplan {
namespace {

using test::world_from;

constexpr double pi = 3.14159265358979323846;

FreeArea area_of(const World& world) { return round_free_area(round_cspace(world), world.source); }

// The closed form is computed in doubles: it may be off by a few units in the last place, which the
// tolerance of 1e-12 (far below the bounds' 1e-9) covers.
void expect_certified(const FreeArea& area, double expected) {
  ASSERT_TRUE(area.bounded);
  EXPECT_FALSE(area.exact.has_value());
  EXPECT_LE(area.lower, expected * (1 + 1e-12));
  EXPECT_GE(area.upper, expected * (1 - 1e-12));
  EXPECT_LE(area.lower, area.upper);
  EXPECT_LE(area.upper - area.lower, 1e-9 * expected) << area.lower << " " << area.upper;
}

TEST(RoundFreeArea, ADiscRobotRoundASquare) {
  // r = 1/2 round a square of side 2: the box [-5, 5]² shrunk by r less s² + 4sr + πr².
  const World w = world_from(R"({"bounds": [-5, -5, 5, 5], "robot": {"disc": 0.5},
                                 "obstacles": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]})");
  expect_certified(area_of(w), 81 - (4 + 4 * 2 * 0.5 + pi * 0.25));
}

TEST(RoundFreeArea, ADiscRobotRoundATurnedSquareAndADiagonalWall) {
  // The square of side √2 (edges of irrational length: the rectangles are bounded, not exact) and
  // a wall of length 5 (exact) and one of length √8: each grown by r = 1/4.
  const World w = world_from(R"({"bounds": [-10, -10, 10, 10], "robot": {"disc": 0.25},
                                 "obstacles": [[[1, 0], [2, 1], [1, 2], [0, 1]]],
                                 "walls": [[[-8, -8], [-5, -4]], [[4, -6], [6, -4]]]})");
  const double r = 0.25;
  const double square = 2 + 4 * std::sqrt(2.0) * r + pi * r * r;
  const double walls = (2 * r * 5 + pi * r * r) + (2 * r * std::sqrt(8.0) + pi * r * r);
  expect_certified(area_of(w), 19.5 * 19.5 - square - walls);
}

TEST(RoundFreeArea, ADiscRobotInsideAHollowSquare) {
  // A 10×10 square with a 6×6 hole, r = 1/2: the square grows to 100 + 40r + πr², its hole shrinks to
  // (6 − 2r)² (free: the reference point may be in it); the box [-20, 20]² shrinks to 39².
  const World w = world_from(R"({"bounds": [-20, -20, 20, 20], "robot": {"disc": 0.5},
      "obstacles": [{"outer": [[-5, -5], [5, -5], [5, 5], [-5, 5]], "holes": [[[-3, -3], [-3, 3], [3, 3], [3, -3]]]}],
      "start": [0, 0], "goal": [10, 10]})");
  const double r = 0.5;
  expect_certified(area_of(w), 39 * 39 - (100 + 40 * r + pi * r * r - (6 - 2 * r) * (6 - 2 * r)));
}

TEST(RoundFreeArea, APointRobotAmongTwoDisjointDiscs) {
  const World w = world_from(R"({"bounds": [0, 0, 10, 10], "discs": [{"center": [3, 3], "radius": 1},
                                                                      {"center": [7, 7], "radius": 1.5}]})");
  expect_certified(area_of(w), 100 - pi * (1 + 2.25));
}

TEST(RoundFreeArea, TwoOverlappingDiscsCountTheirLensOnce) {
  // Unit discs whose centres are 1 apart: the union is 2π less the lens 2π/3 − √3/2.
  const World w = world_from(R"({"bounds": [-5, -5, 5, 5], "discs": [{"center": [0, 0], "radius": 1},
                                                                      {"center": [1, 0], "radius": 1}]})");
  expect_certified(area_of(w), 100 - (4 * pi / 3 + std::sqrt(3.0) / 2));
}

TEST(RoundFreeArea, APolygonRobotRoundADisc) {
  // −R is the 2×2 square round the disc's centre, grown by 1: s² + 4s + π for s = 2; the reference
  // point keeps to [-9, 9]².
  const World w =
      world_from(R"({"bounds": [-10, -10, 10, 10], "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]},
                                 "discs": [{"center": [0, 0], "radius": 1}]})");
  expect_certified(area_of(w), 324 - (4 + 8 + pi));
}

TEST(RoundFreeArea, DiscBoundsLessTheDiscs) {
  const World w = world_from(R"({"bounds": {"center": [1, 1], "radius": 10},
                                 "discs": [{"center": [0, 3], "radius": 2}, {"center": [4, -2], "radius": 1.5}]})");
  expect_certified(area_of(w), pi * (100 - 4 - 2.25));
}

TEST(RoundFreeArea, APointRobotAmongPolygonsAndWallsIsThePolygonWorldsExactArea) {
  const std::string polygons = R"("bounds": [0, 0, 10, 8],
      "obstacles": [[[1, 1], [4, 1], [4, 3], [1, 3]], [[4, 3], [6, 5], [3, 7]], [[7, 1], [9, 1], [8, 2.5]]])";
  const World round = world_from("{" + polygons + R"(, "walls": [[[5, 0], [5, 2], [9, 6]]]})");
  const World plain = world_from("{" + polygons + "}");
  const CSpace cspace(plain);
  Rational expected = 0;
  for (const FreeComponent& c : cspace.free_components()) expected += *c.area;
  const FreeArea area = area_of(round);
  ASSERT_TRUE(area.exact.has_value());
  EXPECT_EQ(*area.exact, expected);
  EXPECT_LE(area.lower, to_double(expected));
  EXPECT_GE(area.upper, to_double(expected));
}

TEST(RoundFreeArea, WithoutBoundsTheFreeSpaceIsUnbounded) {
  for (const World& w : {world_from(R"({"discs": [{"center": [0, 0], "radius": 1}]})"), test::shipped("walls_bug")}) {
    const FreeArea area = area_of(w);
    EXPECT_FALSE(area.bounded);
    EXPECT_FALSE(area.exact.has_value());
    EXPECT_EQ(free_area_text(area), "unbounded");
  }
}

TEST(RoundFreeArea, TheShippedRoundWorldsAreBoundedWithin1e9) {
  for (const char* name :
       {"sphere_world", "sphere_world_disc_bounds", "disc_robot_floor_plan", "polygon_robot_floor_plan"}) {
    const World w = test::shipped(name);
    const FreeArea area = area_of(w);
    ASSERT_TRUE(area.bounded) << name;
    EXPECT_LE(area.lower, area.upper) << name;
    EXPECT_LE(area.upper - area.lower, 1e-9 * area.upper) << name;
  }
}

}  // namespace
}  // namespace polyplan
