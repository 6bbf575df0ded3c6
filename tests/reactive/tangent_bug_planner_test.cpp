// TangentBug on the course's planning problem set's walls (the endless one: limit with d_followed = 2, never a hang;
// the one open at the top: the touch-sensing robot leaves at (1, √3), the far-seeing one takes the corner), out of the
// U-shaped trap, the spiral and the maze, an unreachable goal inside a closed ring; the visibility polygon's windows
// where the geometry puts them; the sensed regions in the picture.
#include "world_fixtures.hpp"

#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/reactive/visibility_region.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace polyplan {
namespace {

using test::shipped;

PlanReport<ExactPoint> tangent_bug(const CSpace& cspace, const Query& q, const std::string& range,
                                   bool record = false) {
  return planners<TranslatingRobot>()
      .find("tangent-bug")
      ->make(cspace, {{"sensor-range", range}})
      ->plan(q, QueryOptions{record});
}

// The course's planning problem set (b): the robot meets the wall at (0, 0), the wall's point nearest the goal, so
// d_followed = 2, and follows it up for ever: here until max-distance, whatever it senses.
TEST(TangentBug, FollowsTheEndlessWallUntilItsDistanceLimitWithDFollowedTwo) {
  const World world = shipped("seed002_endless_wall");
  const CSpace cspace(world);
  for (const char* range : {"0", "1", "inf"}) {
    SCOPED_TRACE(range);
    const auto report = tangent_bug(cspace, world.queries[0], range);
    EXPECT_EQ(report.status, PlanStatus::limit) << report.why_not;
    EXPECT_EQ(report.facts.at(QueryFacts::stopped_by), "distance limit");
    EXPECT_EQ(report.facts.at(TangentBugFacts::d_followed), 2);
    EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{0, 0}}));
    EXPECT_EQ(report.facts.at(BugFacts::leaves), FactPoints{});
    EXPECT_NEAR(report.facts.at(BugFacts::distance), 10000, 1e-6);
    // Up, with the wall on its right: the wall's ends tie, so no discontinuity says otherwise.
    EXPECT_NE(report.why_not.find("at (0.000000, 9997.000000) following the boundary, d_followed 2"), std::string::npos)
        << report.why_not;
  }
}

// The course's planning problem set (c): the wall [0, 1] × [−10⁴, 3]. Touch only: up the wall's left side, over its top
// and down its right side until the distance to (2, 0) falls below d_followed = 2, at (1, √3); then straight to the
// goal: 3 + 3 + 1 + (3 − √3) + 2.
TEST(TangentBug, LeavesTheHalfWallAtOneRootThreeTouchingIt) {
  const World world = shipped("seed002_half_wall");
  const CSpace cspace(world);
  const auto report = tangent_bug(cspace, world.queries[0], "0");
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_TRUE(check_path(cspace, report.path).valid);
  EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{0, 0}}));
  EXPECT_EQ(report.facts.at(TangentBugFacts::d_followed), 2);
  EXPECT_EQ(report.facts.at(BugFacts::leaves), (FactPoints{{1, std::sqrt(3.0)}}));
  ASSERT_EQ(report.path.size(), 6u);  // start, (0, 0), (0, 3), (1, 3), the leave point, the goal
  EXPECT_EQ(report.path[4].x, 1);
  EXPECT_NEAR(to_double(report.path[4].y), std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(report.length, 12 - std::sqrt(3.0), 1e-12);
}

// Seeing far, the robot heads for the wall's top corner (0, 3) (the discontinuity nearest the goal
// by d(x, O) + d(O, goal)), then its other top corner, then the goal: it never follows the wall.
TEST(TangentBug, SeeingFarItHeadsForTheHalfWallsCorners) {
  const World world = shipped("seed002_half_wall");
  const CSpace cspace(world);
  const auto report = tangent_bug(cspace, world.queries[0], "inf");
  ASSERT_TRUE(report.found) << report.why_not;
  const std::vector<ExactPoint> expected{{-3, 0}, {0, 3}, {1, 3}, {2, 0}};
  EXPECT_EQ(report.path, expected);
  EXPECT_EQ(report.facts.at(BugFacts::hits), FactPoints{});
  EXPECT_NEAR(report.length, 3 * std::sqrt(2.0) + 1 + std::sqrt(10.0), 1e-12);
}

// From inside the U (x 7..13, y 7..14 free, open at the top) its windows begin at the tips of its
// arms, and only there.
TEST(TangentBug, TheWindowsOfTheTrapsInsideBeginAtItsTips) {
  const World world = shipped("u_trap");
  const CSpace cspace(world);
  const walk::Boundary boundary(cspace);
  const walk::VisibilityRegions regions(boundary);
  for (const ExactPoint& x : {ExactPoint{10, 10}, ExactPoint{10, 7}, ExactPoint{7, 7}}) {
    const auto region = regions.visible_from(x);
    std::vector<ExactPoint> near;
    for (const auto& [n, far] : walk::windows(boundary, x, region)) near.push_back(n);
    std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
    const std::vector<ExactPoint> tips{{7, 14}, {13, 14}};
    EXPECT_EQ(near, tips) << walk::text(x);
  }
}

// In the trap the robot goes down to the U's floor (10, 7), a local minimum, follows the boundary
// with the obstacle on its right, and leaves at the U's outer corner (14, 6), which sees the goal.
TEST(TangentBug, WalksOutOfTheTrap) {
  const World world = shipped("u_trap");
  const CSpace cspace(world);
  const auto report = tangent_bug(cspace, world.queries[0], "inf");
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_TRUE(check_path(cspace, report.path).valid);
  EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{10, 7}}));
  EXPECT_EQ(report.facts.at(BugFacts::leaves), (FactPoints{{14, 6}}));
  EXPECT_NEAR(report.length, 3 + 3 + 7 + 1 + 8 + std::sqrt(32.0), 1e-12);
}

TEST(TangentBug, WalksOutOfTheSpiralAndTheMazeAtEveryRange) {
  for (const char* name : {"spiral", "maze", "office"}) {
    const World world = shipped(name);
    const CSpace cspace(world);
    for (const char* range : {"0", "2", "inf"}) {
      SCOPED_TRACE(std::string(name) + " range " + range);
      const auto report = tangent_bug(cspace, world.queries[0], range);
      ASSERT_TRUE(report.found) << report.why_not;
      EXPECT_TRUE(check_path(cspace, report.path).valid);
    }
  }
}

// The goal inside a closed square ring: round the ring's outside once without coming nearer than
// d_followed = 5 (its sides' midpoints), which proves it unreachable.
TEST(TangentBug, AGoalInsideAClosedRingIsNoPath) {
  const World world = shipped("ring_goal");
  const CSpace cspace(world);
  for (const char* range : {"0", "3", "inf"}) {
    SCOPED_TRACE(range);
    const auto report = tangent_bug(cspace, world.queries[0], range);
    EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
    EXPECT_NE(report.why_not.find("the goal is unreachable"), std::string::npos) << report.why_not;
    EXPECT_EQ(report.facts.at(TangentBugFacts::d_followed), 5);
  }
}

// Round the apex (0.51, 0.68) of a triangle the walk is 0.85 + 0.85 = 1.7 long exactly, which
// doubles make 1.7000000000000002: max-distance = 1.7 lets it arrive, 1e-15 less stops it.
TEST(TangentBug, MaxDistanceIsComparedExactly) {
  const World world = test::world_from(R"({"bounds": [-0.5, -1, 1.5, 1.5],
    "obstacles": [[[0.51, 0.68], [0.31, -1], [0.71, -1]]], "start": [0, 0], "goal": [1.02, 0]})");
  const CSpace cspace(world);
  const auto walk = [&](const char* most) {
    return planners<TranslatingRobot>()
        .find("tangent-bug")
        ->make(cspace, {{"max-distance", most}})
        ->plan(world.queries[0]);
  };
  const auto exact = walk("1.7");
  ASSERT_TRUE(exact.found) << exact.why_not;
  EXPECT_EQ(exact.path,
            (std::vector<ExactPoint>{{0, 0}, {Rational(51, 100), Rational(17, 25)}, {Rational(51, 50), 0}}));
  EXPECT_TRUE(walk("1.700000000000001").found);
  const auto short_of = walk("1.699999999999999");
  EXPECT_EQ(short_of.status, PlanStatus::limit) << short_of.why_not;
  EXPECT_NE(short_of.why_not.find("max-distance (1.699999999999999)"), std::string::npos) << short_of.why_not;
}

TEST(TangentBug, ABadSensorRangeIsNamed) {
  const World world = shipped("u_trap");
  const CSpace cspace(world);
  for (const char* bad : {"-1", "far", "nan"}) {
    try {
      planners<TranslatingRobot>().find("tangent-bug")->make(cspace, {{"sensor-range", bad}});
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("sensor-range=" + std::string(bad)), std::string::npos) << e.what();
    }
  }
}

// The picture of a walk: the m-line, the hit and leave points, the sensed regions (TangentBug) and
// a walk that stopped short of the goal.
TEST(TangentBug, ThePictureShowsTheMLineHitsLeavesAndTheSensedRegions) {
  const World trap = shipped("u_trap");
  const CSpace trap_space(trap);
  const std::string picture = draw_plan(trap_space, {tangent_bug(trap_space, trap.queries[0], "4", true)}).str();
  for (const char* legend : {"m-line (start to goal)", "hit points (1)", "leave points (1)",
                             "sensed (visibility within range) at the first stops"})
    EXPECT_NE(picture.find(legend), std::string::npos) << legend;
  const World wall = shipped("seed002_endless_wall");
  const CSpace wall_space(wall);
  const std::string stopped = draw_plan(wall_space, {tangent_bug(wall_space, wall.queries[0], "0", true)}).str();
  EXPECT_NE(stopped.find("the walk, stopped short of the goal"), std::string::npos);
  const auto bug2 =
      planners<TranslatingRobot>().find("bug2")->make(trap_space, {})->plan(trap.queries[0], QueryOptions{true});
  const std::string bug_picture = draw_plan(trap_space, {bug2}).str();
  for (const char* legend : {"m-line (start to goal)", "hit points (1)", "leave points (1)"})
    EXPECT_NE(bug_picture.find(legend), std::string::npos) << legend;
}

}  // namespace
}  // namespace polyplan
