// The sampled re-check of pose paths (pose_motion_check.hpp) must be able to fail: it reports a
// turn and a translation that hit an obstacle, a pose outside the bounds and a step that both moves
// and turns, measures non-convex robots and obstacles with holes, and accepts contact. Then the shipped rotation worlds
// (data/worlds/rotation_*.json), independently of the rotation planner: a hand-made path with the turn each world needs
// passes, and the motions that each world is built to forbid are reported.
#include "rotation/pose_motion_check.hpp"
#include <polyplan/geometry/rotation.hpp>
#include <polyplan/io/world_reader.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace polyplan;
using polyplan::test::check_motions_are_single;
using polyplan::test::data_file;
using polyplan::test::pt;
using polyplan::test::sampled_overlap;
using polyplan::test::world_from;

namespace {

Pose pose(const std::string& x, const std::string& y, double degrees) {
  return {pt(x, y), exact_rotation(degrees), degrees};
}

Pose start_of(const Query& q) {
  return {q.start, exact_rotation(q.start_theta.value_or(0)), q.start_theta.value_or(0)};
}
Pose goal_of(const Query& q) { return {q.goal, exact_rotation(q.goal_theta.value_or(0)), q.goal_theta.value_or(0)}; }

// A rod 10 x 1 centred on its reference point, in a corridor 2 wide (y 0..2) between two walls.
const char* kNarrowCorridor = R"({
  "obstacles": [[[-20, -5], [20, -5], [20, 0], [-20, 0]], [[-20, 2], [20, 2], [20, 7], [-20, 7]]],
  "robot": {"parts": [[[-5, -0.5], [5, -0.5], [5, 0.5], [-5, 0.5]]]},
  "start": [0, 1, 0], "goal": [0, 1, 90]
})";

// A unit square centred on its reference point beside a 2 x 2 block [4, 6]^2, in a 10 x 10 box.
const char* kBlock = R"({
  "bounds": [0, 0, 10, 10],
  "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
  "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]},
  "start": [1, 5], "goal": [9, 5]
})";

TEST(PoseMotionCheck, ReportsARodTurningInACorridorTooNarrow) {
  const World world = world_from(kNarrowCorridor);
  ASSERT_EQ(sampled_overlap(world, {pose("0", "1", 0)}), std::nullopt);
  const auto hit = sampled_overlap(world, {pose("0", "1", 0), pose("0", "1", 90)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NE(hit->find("motion 0"), std::string::npos) << *hit;
  EXPECT_NE(hit->find("overlaps obstacles["), std::string::npos) << *hit;
  // The rod can rock until 10 sin a + cos a = 2 (a = 5.74 degrees), either way.
  EXPECT_EQ(sampled_overlap(world, {pose("0", "1", 0), pose("0", "1", 5.7), pose("0", "1", -5.7)}), std::nullopt);
  EXPECT_TRUE(sampled_overlap(world, {pose("0", "1", 0), pose("0", "1", 5.8)}));
  EXPECT_TRUE(sampled_overlap(world, {pose("0", "1", 0), pose("0", "1", -5.8)}));
}

TEST(PoseMotionCheck, ReportsATranslationThroughAnObstacle) {
  const World world = world_from(kBlock);
  // Both ends are free; the middle of the motion crosses the block.
  EXPECT_EQ(sampled_overlap(world, {pose("1", "5", 0)}), std::nullopt);
  EXPECT_EQ(sampled_overlap(world, {pose("9", "5", 0)}), std::nullopt);
  const auto hit = sampled_overlap(world, {pose("1", "5", 0), pose("9", "5", 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NE(hit->find("overlaps obstacles[0]"), std::string::npos) << *hit;
  // A sliver as thin as 0.01 is found too: it is far above rounding.
  EXPECT_TRUE(sampled_overlap(world, {pose("1", "3.51", 0), pose("9", "3.51", 0)}));
}

TEST(PoseMotionCheck, AcceptsContact) {
  const World world = world_from(kBlock);
  // Sliding along the block's lower edge and along the box's walls, and turning away from the
  // block's corner that the square's corner touches.
  EXPECT_EQ(sampled_overlap(world, {pose("1", "3.5", 0), pose("9", "3.5", 0)}), std::nullopt);
  EXPECT_EQ(sampled_overlap(world, {pose("0.5", "0.5", 0), pose("9.5", "0.5", 0), pose("9.5", "9.5", 0)}),
            std::nullopt);
  EXPECT_EQ(sampled_overlap(world, {pose("3.5", "3.5", 0), pose("3.5", "3.5", 90)}), std::nullopt);
  // In a corridor exactly 1 wide the square slides but cannot turn: the sampling sees contact only
  // (whether the zero-width corridor may be used is the exact check's question, not this one's).
  const World exact = world_from(R"({
    "obstacles": [[[0, 0], [10, 0], [10, 1], [0, 1]], [[0, 2], [10, 2], [10, 3], [0, 3]]],
    "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]},
    "start": [1, 1.5], "goal": [9, 1.5]})");
  EXPECT_EQ(sampled_overlap(exact, {pose("1", "1.5", 0), pose("9", "1.5", 0)}), std::nullopt);
  EXPECT_TRUE(sampled_overlap(exact, {pose("1", "1.5", 0), pose("1", "1.5", 0.1)}));
}

TEST(PoseMotionCheck, ReportsLeavingTheBounds) {
  const World world = world_from(kBlock);
  const auto hit = sampled_overlap(world, {pose("1", "1", 0), pose("0.4", "1", 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NE(hit->find("leaves the bounds"), std::string::npos) << *hit;
  // In the corner the square fits at 0 degrees but not turned.
  EXPECT_TRUE(sampled_overlap(world, {pose("0.5", "0.5", 0), pose("0.5", "0.5", 30)}));
  EXPECT_TRUE(sampled_overlap(world, {pose("0.4", "5", 0)}));
}

TEST(PoseMotionCheck, EachStepIsOneMotion) {
  const std::vector<Pose> both = {pose("1", "1", 0), pose("2", "1", 0), pose("2", "2", 30), pose("2", "2", 60)};
  const auto mixed = check_motions_are_single(both);
  ASSERT_TRUE(mixed.has_value());
  EXPECT_NE(mixed->find("motion 1"), std::string::npos) << *mixed;
  EXPECT_EQ(sampled_overlap(world_from(kBlock), both), mixed);  // not sampled as if it were a motion
  EXPECT_EQ(check_motions_are_single({pose("1", "1", 0), pose("2", "1", 0), pose("2", "1", 30), pose("2", "1", 30)}),
            std::nullopt);
}

TEST(PoseMotionCheck, MeasuresNonConvexRobotsAndHoles) {
  // An L-shaped robot whose notch holds the corner of a block: free, though its convex hull is not.
  const World notch = world_from(R"({
    "obstacles": [[[1, 1], [3, 1], [3, 3], [1, 3]]],
    "robot": {"parts": [[[-1, -1], [1, -1], [1, 0], [0, 0], [0, 1], [-1, 1]]]},
    "start": [1, 1], "goal": [0, 0]})");
  EXPECT_EQ(sampled_overlap(notch, {pose("1", "1", 0)}), std::nullopt);
  EXPECT_TRUE(sampled_overlap(notch, {pose("1", "1", 0), pose("1", "1", 10)}));
  EXPECT_TRUE(sampled_overlap(notch, {pose("1", "1", 0), pose("1.5", "1.5", 0)}));
  // A unit square in the 4 x 4 hole of an obstacle turns freely there, and cannot leave it.
  const World hole = world_from(R"({
    "obstacles": [{"outer": [[0, 0], [10, 0], [10, 10], [0, 10]], "holes": [[[3, 3], [7, 3], [7, 7], [3, 7]]]}],
    "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]},
    "start": [5, 5], "goal": [5, 6.5]})");
  EXPECT_EQ(sampled_overlap(hole, {pose("5", "5", 0), pose("5", "5", 180), pose("5", "6.5", 180)}), std::nullopt);
  EXPECT_TRUE(sampled_overlap(hole, {pose("5", "5", 0), pose("5", "8", 0)}));
}

TEST(PoseMotionCheck, PointRobotTouchesButDoesNotEnter) {
  const World world =
      world_from(R"({"obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [0, 4], "goal": [9, 4]})");
  EXPECT_EQ(sampled_overlap(world, {pose("0", "4", 0), pose("9", "4", 0)}), std::nullopt);
  EXPECT_TRUE(sampled_overlap(world, {pose("0", "5", 0), pose("9", "5", 0)}));
}

// --- The shipped rotation worlds ---

World shipped(const std::string& name) { return read_world(data_file("worlds/" + name)); }

TEST(RotationWorlds, Seed004FitsThroughTheSlotOnlyTurned) {
  // The slot between obstacles[2] and [3] runs at atan(14/8) = 60.3 degrees and is 8.34 wide
  // across; the house is 8.93 wide across it at 0 degrees and 8 at 60.
  const World world = shipped("rotation_seed004.json");
  ASSERT_EQ(world.queries.size(), 1u);
  const Query& q = world.queries[0];
  ASSERT_EQ(start_of(q).degrees, 0);
  ASSERT_EQ(goal_of(q).degrees, 0);
  // Below the slot, on its axis; twice (8, 14) further on, above it.
  const std::vector<Pose> path = {start_of(q),
                                  pose("10", "36.5", 0),
                                  pose("45.4", "36.5", 0),
                                  pose("45.4", "36.5", 60),
                                  pose("61.4", "64.5", 60),
                                  pose("61.4", "64.5", 0),
                                  pose("90", "64.5", 0),
                                  goal_of(q)};
  EXPECT_EQ(sampled_overlap(world, path), std::nullopt);
  // Not at 0 degrees, nor at 50 or 70 (over 8.5 across).
  for (double degrees : {0.0, 50.0, 70.0})
    EXPECT_TRUE(sampled_overlap(world, {pose("45.4", "36.5", degrees), pose("61.4", "64.5", degrees)})) << degrees;
}

TEST(RotationWorlds, PianoTurnsInTheCornerSquareOnly) {
  const World world = shipped("rotation_piano.json");
  ASSERT_EQ(world.queries.size(), 1u);
  const Query& q = world.queries[0];
  ASSERT_EQ(start_of(q).degrees, 0);
  ASSERT_EQ(goal_of(q).degrees, 90);
  // Into the middle of the 12 x 12 corner square, turn there (the rod's ends stay within 5.03 of
  // the centre), then up the vertical leg.
  const std::vector<Pose> path = {start_of(q), pose("30", "10", 0), pose("30", "10", 90), goal_of(q)};
  EXPECT_EQ(sampled_overlap(world, path), std::nullopt);
  // The rod cannot turn in the legs, nor enter the vertical leg lying down or the horizontal one standing.
  EXPECT_TRUE(sampled_overlap(world, {pose("12", "10", 0), pose("12", "10", 90)}));
  EXPECT_TRUE(sampled_overlap(world, {pose("30", "20", 90), pose("30", "20", 0)}));
  EXPECT_TRUE(sampled_overlap(world, {pose("30", "10", 0), pose("30", "22", 0)}));
  EXPECT_TRUE(sampled_overlap(world, {pose("30", "10", 90), pose("18", "10", 90)}));
}

TEST(RotationWorlds, ExactFitCorridorAllowsNoTurn) {
  const World world = shipped("rotation_exact_fit.json");
  ASSERT_EQ(world.queries.size(), 2u);
  // Query 0 asks for a quarter turn: its start and goal are free (the square covers the same place
  // turned by 90 degrees) ...
  const Query& turn = world.queries[0];
  ASSERT_EQ(goal_of(turn).degrees, 90);
  EXPECT_EQ(sampled_overlap(world, {start_of(turn)}), std::nullopt);
  EXPECT_EQ(sampled_overlap(world, {goal_of(turn)}), std::nullopt);
  // ... but a turn of 1 degree, either way, overlaps the walls anywhere along the corridor.
  for (int tenths = 5; tenths <= 115; tenths += 5) {
    const std::string x = std::to_string(tenths / 10) + "." + std::to_string(tenths % 10);
    for (double degrees : {1.0, -1.0})
      EXPECT_TRUE(sampled_overlap(world, {pose(x, "2.5", 0), pose(x, "2.5", degrees)})) << x << " " << degrees;
  }
  // Query 1 stays at 0 degrees: a straight slide along the corridor.
  const Query& slide = world.queries[1];
  EXPECT_EQ(sampled_overlap(world, {start_of(slide), goal_of(slide)}), std::nullopt);
}

}  // namespace
