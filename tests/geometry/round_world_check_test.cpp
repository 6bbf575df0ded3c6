// Exact motions among discs, walls, disc bounds and for a disc robot (geometry/round_world_check):
// grazing is valid, entering is not; a wall may be touched and slid along, never crossed, even at
// a point; a passage exactly as wide as the robot (or two tangent discs) is no passage, one a
// hair wider is; and decimals that doubles put on the wrong side are decided right.
#include <polyplan/geometry/round_world_check.hpp>

#include "world_fixtures.hpp"

#include <gtest/gtest.h>

namespace polyplan {
namespace {

using test::pt;
using test::world_from;

bool valid(const World& world, const std::vector<ExactPoint>& path) {
  const PathCheck check = RoundWorld(world).check_path(path);
  return check.valid;
}

TEST(RoundWorldCheck, APathMayGrazeADiscButNotEnterIt) {
  // The line y = 0.3 is tangent to the disc of centre (0, 0.1) and radius 0.2; in doubles 0.3 - 0.1
  // is 0.19999999999999998, below the radius, and the tangent would count as a collision.
  const World w = world_from(R"({"discs": [{"center": [0, 0.1], "radius": 0.2}]})");
  EXPECT_TRUE(valid(w, {pt("-1", "0.3"), pt("1", "0.3")}));
  EXPECT_FALSE(valid(w, {pt("-1", "0.29999999999999999999"), pt("1", "0.29999999999999999999")}));
  EXPECT_FALSE(valid(w, {pt("0", "0.3"), pt("0", "-1")}));  // from the rim straight in
  EXPECT_TRUE(valid(w, {pt("0", "0.3"), pt("0", "1")}));    // from the rim away
  EXPECT_TRUE(RoundWorld(w).config_not_free(pt("0", "0.2")).has_value());
  EXPECT_FALSE(RoundWorld(w).config_not_free(pt("0", "0.3")).has_value());
}

TEST(RoundWorldCheck, TwoTangentDiscsLeaveNoPassage) {
  const World w = world_from(R"({"discs": [{"center": [0, 1], "radius": 1}, {"center": [0, -1], "radius": 1}]})");
  EXPECT_FALSE(valid(w, {pt("-2", "0"), pt("2", "0")}));                   // through the point they touch at
  EXPECT_FALSE(valid(w, {pt("-2", "0"), pt("0", "0"), pt("2", "0")}));     // the same with a vertex there
  EXPECT_TRUE(valid(w, {pt("-2", "0"), pt("0", "0"), pt("-1", "0")}));     // to it and back the way it came
  EXPECT_FALSE(valid(w, {pt("-2", "0"), pt("0", "0"), pt("-2", "0.5")}));  // turning there: into a disc
}

TEST(RoundWorldCheck, AWallMayBeTouchedAndSlidAlongButNotCrossed) {
  const World w = world_from(R"({"walls": [[[0, -1], [0, 1]], [[5, -1], [5, 0], [6, 1]]]})");
  EXPECT_FALSE(valid(w, {pt("-1", "0.5"), pt("1", "0.5")}));            // across its middle
  EXPECT_FALSE(valid(w, {pt("-1", "0"), pt("0", "0"), pt("1", "0")}));  // across, a vertex on it
  EXPECT_TRUE(valid(w, {pt("0", "-2"), pt("0", "2")}));                 // along it, end to end
  EXPECT_TRUE(valid(w, {pt("-1", "0"), pt("0", "0"), pt("-1", "1")}));  // to it and back
  EXPECT_TRUE(valid(w, {pt("-1", "1"), pt("1", "1")}));                 // past its end, through the end
  EXPECT_FALSE(valid(w, {pt("4", "0"), pt("6", "0")}));                 // across its bend
  EXPECT_TRUE(valid(w, {pt("5", "-2"), pt("5", "0"), pt("6", "1")}));   // along it round the bend
  EXPECT_TRUE(valid(w, {pt("4", "2"), pt("4", "-2")}));                 // beside it
}

// A closed square of walls: a robot that slides along one side keeps to the face it came on, so
// it cannot turn in at a corner it slid to from outside; round a wall's end it may change faces.
TEST(RoundWorldCheck, SlidingAlongAWallKeepsToItsFace) {
  const World w = world_from(R"({"walls": [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]], [[6, 0], [6, 4]]]})");
  EXPECT_FALSE(valid(w, {pt("0", "2"), pt("1", "2"), pt("1", "3"), pt("2", "2")}));   // onto the wall, up, in
  EXPECT_FALSE(valid(w, {pt("2", "2"), pt("1", "2"), pt("1", "3"), pt("0", "4")}));   // from inside, out
  EXPECT_TRUE(valid(w, {pt("0", "2"), pt("1", "2"), pt("1", "3"), pt("0", "4")}));    // outside all the way
  EXPECT_TRUE(valid(w, {pt("2", "2"), pt("1", "2"), pt("1", "3"), pt("2", "2.5")}));  // inside all the way
  EXPECT_TRUE(valid(w, {pt("0", "2"), pt("1", "2"), pt("1", "1"), pt("1", "3"), pt("0", "4")}));  // down and up
  EXPECT_FALSE(valid(w, {pt("0", "2"), pt("1", "2"), pt("1", "1"), pt("1", "3"), pt("2", "2")}));
  // Up the west face of the wall x = 6, round its end and down the east face, then east: valid.
  EXPECT_TRUE(valid(w, {pt("5", "2"), pt("6", "2"), pt("6", "4"), pt("6", "2"), pt("7", "2")}));
  EXPECT_FALSE(valid(w, {pt("5", "2"), pt("6", "2"), pt("6", "3"), pt("6", "2"), pt("7", "2")}));  // no end there
}

TEST(RoundWorldCheck, ADiscRobotPassesAGapAHairWiderThanItselfOnly) {
  const std::string walls = R"("obstacles": [[[-3, -1], [-0.5, -1], [-0.5, 1], [-3, 1]],
                                             [[0.5, -1], [3, -1], [3, 1], [0.5, 1]]])";
  const World exact = world_from(R"({"robot": {"disc": 0.5}, )" + walls + "}");
  EXPECT_FALSE(valid(exact, {pt("0", "-3"), pt("0", "3")}));  // both sides touched: a passage of zero width
  const World wider = world_from(R"({"robot": {"disc": 0.4999999999999}, )" + walls + "}");
  EXPECT_TRUE(valid(wider, {pt("0", "-3"), pt("0", "3")}));
  EXPECT_FALSE(valid(wider, {pt("0.0000000000002", "-3"), pt("0.0000000000002", "3")}));  // too near one side
}

TEST(RoundWorldCheck, ADiscRobotKeepsItsRadiusFromDiscsWallsAndBounds) {
  const World w = world_from(R"({"robot": {"disc": 0.5}, "bounds": {"center": [0, 0], "radius": 10},
                                 "discs": [{"center": [0, 0], "radius": 1}], "walls": [[[5, -1], [5, 1]]]})");
  EXPECT_TRUE(valid(w, {pt("-3", "1.5"), pt("3", "1.5")}));  // tangent to the disc grown by the radius
  EXPECT_FALSE(valid(w, {pt("-3", "1.49"), pt("3", "1.49")}));
  EXPECT_TRUE(valid(w, {pt("4.5", "-3"), pt("4.5", "3")}));  // sliding along the wall at the radius
  EXPECT_FALSE(valid(w, {pt("4.6", "-3"), pt("4.6", "3")}));
  EXPECT_FALSE(valid(w, {pt("4", "0"), pt("6", "0")}));    // a disc robot does not cross a wall either
  EXPECT_TRUE(valid(w, {pt("3", "-3"), pt("9.5", "0")}));  // to the rim of the bounds less the radius
  EXPECT_FALSE(valid(w, {pt("3", "-3"), pt("9.6", "0")}));
}

TEST(RoundWorldCheck, PolygonsTouchingAtACornerLeaveNoPassage) {
  const World w = world_from(R"({"obstacles": [[[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]],
                                 "discs": [{"center": [9, 9], "radius": 0.5}]})");
  EXPECT_FALSE(valid(w, {pt("1", "1"), pt("3", "3")}));
  EXPECT_TRUE(valid(w, {pt("1", "1"), pt("2", "2"), pt("1", "1.5")}));
  EXPECT_FALSE(valid(w, {pt("1", "3"), pt("3", "1")}));  // through both squares
}

TEST(RoundWorldCheck, APolygonRobotMayTouchADiscButNotOverlapIt) {
  // The triangle (0, 0), (1, 0), (0, 1) about its corner, a unit disc at (5, 5): at (3, 4) it keeps
  // √2 away; at (3, 5) its vertex (4, 5) touches the disc's leftmost point (contact is free), and
  // sliding along x = 3 it touches there only; 1e-9 further right it overlaps.
  const World w =
      world_from(R"({"robot": {"parts": [[[0, 0], [1, 0], [0, 1]]]}, "discs": [{"center": [5, 5], "radius": 1}]})");
  const RoundWorld checker(w);
  EXPECT_FALSE(checker.config_not_free({3, 4}).has_value());
  EXPECT_FALSE(checker.config_not_free({3, 5}).has_value());
  EXPECT_TRUE(checker.config_not_free(pt("3.000000001", "5")).has_value());
  EXPECT_TRUE(valid(w, {pt("3", "0"), pt("3", "10")}));
  EXPECT_FALSE(valid(w, {pt("3.000000001", "0"), pt("3.000000001", "10")}));
}

TEST(RoundWorldCheck, APolygonRobotInDiscBoundsIsRefusedNamingIt) {
  const World w = world_from(R"({"robot": {"parts": [[[0, 0], [1, 0], [0, 1]]]},
                                 "obstacles": [], "bounds": {"center": [5, 5], "radius": 5}})");
  try {
    RoundWorld checker(w);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: bounds: a polygon robot in disc bounds"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace polyplan
