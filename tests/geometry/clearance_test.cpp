// Clearances measured on worlds where they are known by hand.
#include <polyplan/geometry/clearance.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polyplan;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

const char* kSquareInABox = R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})";

TEST(Clearance, AtAPointIsTheDistanceToTheNearestObstacleOrWall) {
  const CSpace c(world_from(kSquareInABox));
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("1", "5")), 1);                              // the left wall
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("3", "5")), 1);                              // the square's left side
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("3", "3")), std::min(std::sqrt(2.0), 3.0));  // the square's corner
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("4", "5")), 0);                              // on the square
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("5", "5")), 1);                              // inside it: 1 from its boundary
}

TEST(Clearance, AlongAPathIsItsNarrowestPlaceNotOnlyItsCorners) {
  const CSpace c(world_from(kSquareInABox));
  EXPECT_DOUBLE_EQ(path_clearance(c, {pt("2", "3"), pt("8", "3")}), 1);                    // passes 1 under the square
  EXPECT_DOUBLE_EQ(path_clearance(c, {pt("2", "2.5"), pt("5", "1"), pt("8", "2.5")}), 1);  // dips to 1 above the wall
  // Grazing a corner: 0.
  EXPECT_DOUBLE_EQ(path_clearance(c, {pt("2", "2"), pt("8", "8")}), 0);
}

TEST(Clearance, APolygonRobotMeasuresFromItsCSpace) {
  // A 2 x 2 robot: the C-obstacle is [3, 7]^2 and the walls are at 1 and 9.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
      "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}})"));
  EXPECT_DOUBLE_EQ(clearance_at(c, pt("2", "5")), 1);
  EXPECT_DOUBLE_EQ(path_clearance(c, {pt("2", "2"), pt("8", "2")}), 1);
}

}  // namespace
