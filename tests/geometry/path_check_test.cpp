// check_path on the cases where floating point gets "free" wrong.
#include <polyplan/geometry/path_check.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

const char* kUnitSquareAt1 = R"({"obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})";

PathCheck check(const CSpace& c, std::vector<ExactPoint> path) { return check_path(c, path); }

}  // namespace

TEST(CheckPath, GrazingAVertexIsValid) {
  const CSpace c(world_from(kUnitSquareAt1));
  EXPECT_TRUE(check(c, {pt("1", "3"), pt("3", "1")}).valid);  // touches the corner (2,2) only
}

TEST(CheckPath, SlidingAlongAnEdgeIsValid) {
  const CSpace c(world_from(kUnitSquareAt1));
  EXPECT_TRUE(check(c, {pt("0", "1"), pt("3", "1")}).valid);
  EXPECT_TRUE(check(c, {pt("0", "1"), pt("2", "1"), pt("2", "3")}).valid);  // and around the corner
}

TEST(CheckPath, CuttingTheCornerBy1e10IsInvalid) {
  const CSpace c(world_from(kUnitSquareAt1));
  const PathCheck r = check(c, {pt("1", "2.9999999999"), pt("2.9999999999", "1")});
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.segment, 0u);
  EXPECT_NE(r.reason.find("enters a C-obstacle"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("obstacles[0]"), std::string::npos) << r.reason;
}

TEST(CheckPath, CrossingAnObstacleIsInvalid) {
  const CSpace c(world_from(kUnitSquareAt1));
  EXPECT_FALSE(check(c, {pt("0", "0"), pt("3", "3")}).valid);
  EXPECT_FALSE(check(c, {pt("0", "1.5"), pt("1.5", "1.5")}).valid);  // ends inside
}

TEST(CheckPath, ExactFitCorridorIsClosedAndOneBillionthWiderIsOpen) {
  const std::string walls =
      R"("bounds": [0, 0, 10, 9], "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]})";
  const CSpace exact(world_from(
      "{" + walls + R"(, "obstacles": [[[2, 3], [8, 3], [8, 4], [2, 4]], [[2, 5], [8, 5], [8, 6], [2, 6]]]})"));
  const CSpace wider(world_from(
      "{" + walls +
      R"(, "obstacles": [[[2, 3], [8, 3], [8, 4], [2, 4]], [[2, 5.000000001], [8, 5.000000001], [8, 6], [2, 6]]]})"));
  const std::vector<ExactPoint> through{pt("1", "4.5"), pt("9", "4.5")};
  const PathCheck closed = check(exact, through);
  EXPECT_FALSE(closed.valid);
  EXPECT_NE(closed.reason.find("only exactly"), std::string::npos) << closed.reason;
  EXPECT_TRUE(check(wider, {pt("1", "4.5000000005"), pt("9", "4.5000000005")}).valid);
  EXPECT_TRUE(check(wider, through).valid);  // slides along the lower wall's C-obstacle
  EXPECT_FALSE(check(wider, {pt("1", "4.500000002"), pt("9", "4.500000002")}).valid);
}

TEST(CheckPath, PinchPointIsAZeroWidthPassage) {
  // Free space: two squares [0,2]^2 and [2,4]^2 meeting only at (2,2).
  const CSpace c(world_from(R"({"bounds": [0, 0, 4, 4],
                                "obstacles": [[[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]]})"));
  const PathCheck straight = check(c, {pt("1", "1"), pt("3", "3")});
  EXPECT_FALSE(straight.valid);
  EXPECT_NE(straight.reason.find("pinch point [2, 2]"), std::string::npos) << straight.reason;
  const PathCheck turning = check(c, {pt("1", "1"), pt("2", "2"), pt("3", "3")});
  EXPECT_FALSE(turning.valid);
  EXPECT_NE(turning.reason.find("pinch point"), std::string::npos) << turning.reason;
  // Touching the pinch point and turning back is fine.
  EXPECT_TRUE(check(c, {pt("1", "1"), pt("2", "2"), pt("1", "1.5")}).valid);
  EXPECT_TRUE(check(c, {pt("0", "0"), pt("2", "2"), pt("2", "0")}).valid);  // along both walls of one wedge
}

TEST(CheckPath, SeamBetweenTouchingObstaclesIsClosed) {
  // Two squares sharing the edge x = 1: the seam has no width.
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 2], [0, 2]], [[1, 0], [2, 0], [2, 2], [1, 2]]]})"));
  EXPECT_FALSE(check(c, {pt("1", "-1"), pt("1", "3")}).valid);
  EXPECT_TRUE(check(c, {pt("-1", "0"), pt("3", "0")}).valid);  // along the bottom of both
}

TEST(CheckPath, DecimalCoordinatesAreExact) {
  // The segment (0,0)-(0.3,0.9) passes exactly through the triangle's vertex (0.1, 0.3); in
  // doubles 0.1*3 != 0.3 and the test of the vertex against the line goes either way.
  const CSpace c(world_from(R"({"obstacles": [[[0.1, 0.3], [0.2, 0.3], [0.2, 0.5]]]})"));
  EXPECT_TRUE(check(c, {pt("0", "0"), pt("0.3", "0.9")}).valid);
  EXPECT_FALSE(check(c, {pt("0", "0"), pt("0.3", "0.8999999999999999")}).valid);
}

TEST(CheckPath, PointsOutsideBoundsAreInvalid) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": []})"));
  EXPECT_TRUE(check(c, {pt("0", "0"), pt("4", "4")}).valid);
  const PathCheck r = check(c, {pt("1", "1"), pt("5", "1")});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.reason.find("outside the bounds"), std::string::npos) << r.reason;
}

TEST(CheckSegment, AgreesWithCheckPathOfTheTwoPoints) {
  // The planners' segment test is the two-point path: same verdict, reason and segment.
  const CSpace pinch(world_from(R"({"bounds": [0, 0, 4, 4],
                                    "obstacles": [[[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], )"
                                R"([2, 2]]]})"));
  const CSpace square(world_from(kUnitSquareAt1));
  struct Case {
    const CSpace* cspace;
    ExactPoint a, b;
    bool valid;
  };
  const std::vector<Case> cases{
      {&square, pt("1", "3"), pt("3", "1"), true},                         // grazes the corner (2, 2)
      {&square, pt("0", "1"), pt("3", "1"), true},                         // slides along the bottom edge
      {&square, pt("0", "0"), pt("0", "0"), true},                         // stays put in the free space
      {&square, pt("0", "0"), pt("3", "3"), false},                        // through the obstacle
      {&square, pt("1", "2.9999999999"), pt("2.9999999999", "1"), false},  // cuts the corner
      {&square, pt("3/2", "3/2"), pt("3", "3"), false},                    // starts inside
      {&pinch, pt("1", "1"), pt("2", "2"), true},                          // reaches the pinch point
      {&pinch, pt("1", "1"), pt("3", "3"), false},                         // passes through it
      {&pinch, pt("1", "1"), pt("5", "1"), false},                         // leaves the bounds
  };
  for (const Case& c : cases) {
    const PathCheck segment = check_segment(*c.cspace, c.a, c.b);
    const PathCheck path = check_path(*c.cspace, {c.a, c.b});
    EXPECT_EQ(segment.valid, c.valid) << to_string(c.a) << "-" << to_string(c.b) << ": " << segment.reason;
    EXPECT_EQ(segment.valid, path.valid) << to_string(c.a) << "-" << to_string(c.b);
    EXPECT_EQ(segment.reason, path.reason);
    EXPECT_EQ(segment.segment, path.segment);
    EXPECT_EQ(segment.valid, segment.reason.empty()) << segment.reason;
  }
}
