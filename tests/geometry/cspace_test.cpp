// CSpace (geometry/cspace.cpp): C-obstacles against Minkowski sums worked out by hand, solids,
// bounds as walls, point location and the words that say why a query is not free.
#include <polyplan/geometry/cspace.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <memory>
#include <thread>

using namespace polyplan;
using polyplan::test::area;
using polyplan::test::canonical;
using polyplan::test::pt;
using polyplan::test::world_from;

TEST(Minkowski, SquareRobotAroundSquare) {
  // Robot [0,1]^2 with its reference at the lower-left corner: the obstacle [0,2]^2 grows by the
  // reflected robot [-1,0]^2 into [-1,2]^2.
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [2, 0], [2, 2], [0, 2]]],
                                "robot": {"parts": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}})"));
  ASSERT_EQ(c.cobstacles().size(), 1u);
  EXPECT_EQ(canonical(c.cobstacles()[0].outer), (Ring{pt("-1", "-1"), pt("2", "-1"), pt("2", "2"), pt("-1", "2")}));
}

TEST(Minkowski, TriangleRobotAroundSquare) {
  // -R = {(0,0), (-1,0), (0,-1)}: the lower-left corner of [-1,2]^2 is cut by the diagonal.
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [2, 0], [2, 2], [0, 2]]],
                                "robot": {"parts": [[[0, 0], [1, 0], [0, 1]]]}})"));
  ASSERT_EQ(c.cobstacles().size(), 1u);
  EXPECT_EQ(canonical(c.cobstacles()[0].outer),
            (Ring{pt("-1", "0"), pt("0", "-1"), pt("2", "-1"), pt("2", "2"), pt("-1", "2")}));
  EXPECT_EQ(area(c.cobstacles()[0]), Rational(17, 2));
}

TEST(Minkowski, ObstacleWithAHoleKeepsAShrunkHole) {
  // A 6x6 ring with a 2x2 hole; a centred unit square robot shrinks the hole to 1x1.
  const CSpace c(world_from(R"({"obstacles": [{"outer": [[0, 0], [6, 0], [6, 6], [0, 6]],
                                                "holes": [[[2, 2], [4, 2], [4, 4], [2, 4]]]}],
                                "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]}})"));
  ASSERT_EQ(c.cobstacles().size(), 1u);
  const PolygonWithHoles& cobstacle = c.cobstacles()[0];
  ASSERT_EQ(cobstacle.holes.size(), 1u);
  Ring hole = cobstacle.holes[0];
  std::reverse(hole.begin(), hole.end());
  EXPECT_EQ(canonical(hole), (Ring{pt("2.5", "2.5"), pt("3.5", "2.5"), pt("3.5", "3.5"), pt("2.5", "3.5")}));
  EXPECT_EQ(area(cobstacle), Rational(48));
  // The inside of the hole is a free component of its own: area exactly 1.
  ASSERT_EQ(c.free_components().size(), 2u);
  bool found_hole_component = false;
  for (const auto& f : c.free_components()) found_hole_component |= f.area && *f.area == 1;
  EXPECT_TRUE(found_hole_component);
}

TEST(Minkowski, RobotTooBigForTheHoleFillsIt) {
  const CSpace c(world_from(R"({"obstacles": [{"outer": [[0, 0], [6, 0], [6, 6], [0, 6]],
                                                "holes": [[[2, 2], [4, 2], [4, 4], [2, 4]]]}],
                                "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}})"));
  ASSERT_EQ(c.cobstacles().size(), 1u);
  EXPECT_TRUE(c.cobstacles()[0].holes.empty());
  EXPECT_EQ(area(c.cobstacles()[0]), Rational(64));
}

TEST(Minkowski, NonConvexLShape) {
  // L = [0,3]x[0,1] u [0,1]x[0,3] grown by a centred unit square: two 4x2 bars sharing 2x2.
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]]],
                                "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]}})"));
  ASSERT_EQ(c.cobstacles().size(), 1u);
  EXPECT_EQ(area(c.cobstacles()[0]), Rational(12));
  EXPECT_EQ(c.cobstacles()[0].outer.size(), 6u);
}

TEST(Minkowski, TwoPartRobotIsTheUnionOfThePartsSums) {
  // House-shaped robot: rectangle [0,2]x[0,1] and roof triangle (0,1) (2,1) (1,2). Obstacle
  // [0,1]^2. Rectangle's sum: [-2,1]x[-1,1], area 6. Roof's sum: hexagon of area 5 that overlaps
  // it in [-2,1]x[-1,0] (area 3). Union: 6 + 5 - 3 = 8.
  const std::string obstacle = R"("obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]]])";
  const CSpace both(world_from("{" + obstacle + R"(, "robot": {"parts": [[[0, 0], [2, 0], [2, 1], [0, 1]],
                                                                    [[0, 1], [2, 1], [1, 2]]]}})"));
  ASSERT_EQ(both.cobstacles().size(), 1u);
  EXPECT_EQ(area(both.cobstacles()[0]), Rational(8));
  const CSpace roof(world_from("{" + obstacle + R"(, "robot": {"parts": [[[0, 1], [2, 1], [1, 2]]]}})"));
  EXPECT_EQ(area(roof.cobstacles()[0]), Rational(5));
  EXPECT_EQ(canonical(roof.cobstacles()[0].outer),
            (Ring{pt("-2", "-1"), pt("-1", "-2"), pt("0", "-2"), pt("1", "-1"), pt("1", "0"), pt("-2", "0")}));
}

TEST(CSpace, TouchingObstaclesAreOneSolid) {
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]], [[1, 0], [2, 0], [2, 1], [1, 1]],
                                              [[5, 5], [6, 5], [6, 6], [5, 6]]]})"));
  EXPECT_EQ(c.solids().size(), 2u);
}

TEST(CSpace, BoundsAreWalls) {
  // A 1x1 robot in a 10x10 box: its reference point keeps to [0,9]^2 (reference at lower left).
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [],
                                "robot": {"parts": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}})"));
  ASSERT_TRUE(c.reference_box());
  EXPECT_EQ(c.reference_box()->xmax, Rational(9));
  ASSERT_EQ(c.free_components().size(), 1u);
  EXPECT_EQ(*c.free_components()[0].area, Rational(81));
  EXPECT_EQ(c.locate(pt("9", "9")).kind, Location::Kind::contact);
  EXPECT_EQ(c.locate(pt("9.5", "1")).kind, Location::Kind::blocked);
  EXPECT_EQ(*c.collision_at(pt("9.5", "1")), "the robot leaves the bounds");
}

TEST(CSpace, ExactFitCorridorClosesAndOneBillionthMoreOpensIt) {
  // Two walls 1 apart across the whole box; a unit square robot fits only exactly.
  const std::string walls =
      R"("bounds": [0, 0, 10, 9], "robot": {"parts": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]})";
  const CSpace exact(world_from(
      "{" + walls + R"(, "obstacles": [[[0, 3], [10, 3], [10, 4], [0, 4]], [[0, 5], [10, 5], [10, 6], [0, 6]]]})"));
  const CSpace wider(world_from(
      "{" + walls +
      R"(, "obstacles": [[[0, 3], [10, 3], [10, 4], [0, 4]], [[0, 5.000000001], [10, 5.000000001], [10, 6], )"
      R"([0, 6]]]})"));
  EXPECT_EQ(exact.free_components().size(), 2u);  // below and above the walls
  EXPECT_EQ(wider.free_components().size(), 3u);  // plus the corridor
  EXPECT_EQ(exact.locate(pt("5", "4.5")).kind, Location::Kind::blocked);
  EXPECT_EQ(wider.locate(pt("5", "4.5")).kind, Location::Kind::contact);  // on the lower wall's C-obstacle
  EXPECT_EQ(wider.locate(pt("5", "4.5000000005")).kind, Location::Kind::free);
  EXPECT_NE(exact.collision_at(pt("5", "4.5"))->find("only exactly"), std::string::npos);
}

namespace {

// A point robot in [0, 4]^2 with the unit obstacle [1, 2]^2.
const char* kSquareInABox = R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})";

Query query(const ExactPoint& start, const ExactPoint& goal) { return {start, goal, "q"}; }

}  // namespace

TEST(QueryNotFree, NamesTheStartAndTheObstacleItIsInside) {
  const CSpace c(world_from(kSquareInABox));
  EXPECT_EQ(c.query_not_free(query(pt("3/2", "3/2"), pt("3", "3"))),
            "the start [3/2, 3/2] is not free: it is inside obstacles[0]");
}

TEST(QueryNotFree, NamesTheGoalOutsideTheBounds) {
  const CSpace c(world_from(kSquareInABox));
  EXPECT_EQ(c.query_not_free(query(pt("1/2", "1/2"), pt("5", "-1/3"))),
            "the goal [5, -1/3] is not free: it is outside the bounds");
}

TEST(QueryNotFree, TheStartIsNamedBeforeTheGoal) {
  const CSpace c(world_from(kSquareInABox));
  EXPECT_EQ(c.query_not_free(query(pt("7", "0"), pt("1.5", "1.5"))),
            "the start [7, 0] is not free: it is outside the bounds");
}

TEST(QueryNotFree, ContactIsFree) {
  // On an obstacle's edge, at its corner, on the bounds: the closure of the free space.
  const CSpace c(world_from(kSquareInABox));
  EXPECT_EQ(c.query_not_free(query(pt("1", "3/2"), pt("2", "2"))), std::nullopt);
  EXPECT_EQ(c.query_not_free(query(pt("0", "0"), pt("4", "5/2"))), std::nullopt);
  EXPECT_EQ(c.query_not_free(query(pt("1/2", "1/2"), pt("3", "3"))), std::nullopt);
}

TEST(QueryNotFree, ARobotWithExtentOverlapsOrLeavesTheBounds) {
  // A unit square robot (reference at its lower-left corner) keeps its reference in [0, 3]^2 and
  // out of the open square (0, 2)^2.
  const CSpace c(world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]],
                                "robot": {"parts": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}})"));
  EXPECT_EQ(c.query_not_free(query(pt("1/2", "1/2"), pt("3", "3"))),
            "the start [1/2, 1/2] is not free: the robot overlaps obstacles[0]");
  EXPECT_EQ(c.query_not_free(query(pt("3", "0"), pt("3.5", "0"))),
            "the goal [7/2, 0] is not free: the robot leaves the bounds");
  EXPECT_EQ(c.query_not_free(query(pt("3", "0"), pt("2", "2"))), std::nullopt);  // touching the obstacle's corner
  // At (0, 0) the robot touches the obstacle's corner too, but it sits in the zero-width gap
  // between the bounds and the obstacle's C-obstacle [0, 2]^2: not in the closure of the open
  // free space.
  EXPECT_EQ(c.query_not_free(query(pt("0", "0"), pt("3", "3"))),
            "the start [0, 0] is not free: the robot fits there only exactly: the free space has zero width (obstacles "
            "touch around it)");
}

TEST(Locate, FreePointLiesInOneComponent) {
  const CSpace c(world_from(kSquareInABox));
  const Location at = c.locate(pt("1/2", "1/2"));
  EXPECT_EQ(at.kind, Location::Kind::free);
  ASSERT_EQ(c.free_components().size(), 1u);
  EXPECT_EQ(at.components, std::vector<std::size_t>{0});
  EXPECT_EQ(*c.free_components()[0].area, Rational(15));  // 16 minus the obstacle
}

TEST(Locate, PointOnAnEdgeIsInContactWithTheComponentBesideIt) {
  const CSpace c(world_from(kSquareInABox));
  for (const ExactPoint& p : {pt("1", "3/2"), pt("2", "2"), pt("0", "7/3")}) {
    const Location at = c.locate(p);
    EXPECT_EQ(at.kind, Location::Kind::contact) << to_string(p);
    EXPECT_EQ(at.components, std::vector<std::size_t>{0}) << to_string(p);
  }
}

TEST(Locate, PinchPointBetweenTwoComponentsTouchesBoth) {
  // data/worlds/touching_corners.json: the free squares [0,2]^2 and [2,4]^2 meet only at (2, 2).
  const CSpace c(world_from(R"({"bounds": [0, 0, 4, 4],
                                "obstacles": [[[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]]})"));
  ASSERT_EQ(c.free_components().size(), 2u);
  for (const FreeComponent& component : c.free_components()) EXPECT_EQ(*component.area, Rational(4));
  const Location low = c.locate(pt("1", "1")), high = c.locate(pt("3", "3"));
  ASSERT_EQ(low.components.size(), 1u);
  ASSERT_EQ(high.components.size(), 1u);
  EXPECT_NE(low.components[0], high.components[0]);
  const Location pinch = c.locate(pt("2", "2"));
  EXPECT_EQ(pinch.kind, Location::Kind::contact);
  std::vector<std::size_t> touched = pinch.components;
  std::sort(touched.begin(), touched.end());
  EXPECT_EQ(touched, (std::vector<std::size_t>{0, 1}));
}

TEST(Locate, PinchPointInsideOneComponentNamesItOnce) {
  // Two obstacles touching at a corner in an open world: the free space around them is one
  // component with two wedges at (1, 1).
  const CSpace c(world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]], [[1, 1], [2, 1], [2, 2], [1, 2]]]})"));
  ASSERT_EQ(c.free_components().size(), 1u);
  const Location pinch = c.locate(pt("1", "1"));
  EXPECT_EQ(pinch.kind, Location::Kind::contact);
  EXPECT_EQ(pinch.components, std::vector<std::size_t>{0});
}

TEST(Locate, InsideAnObstacleOrOutsideTheBoundsIsBlocked) {
  const CSpace c(world_from(kSquareInABox));
  for (const ExactPoint& p : {pt("3/2", "3/2"), pt("1.000000001", "1.999999999"), pt("-1/1000", "2"), pt("5", "5")}) {
    const Location at = c.locate(p);
    EXPECT_EQ(at.kind, Location::Kind::blocked) << to_string(p);
    EXPECT_TRUE(at.components.empty()) << to_string(p);
  }
}

// CSpace::locate never returned for (2, 3/2), a free point below the vertex (2, 2) where the
// square and the triangle touch: CGAL's Arr_landmarks_point_location walked from the landmark
// (2, 2) and found no face to cross into (CGAL issue #6594; with CGAL's assertions on it stops
// at "new_face != face"). CSpace now locates with the trapezoidal map (RIC), which terminates
// on every arrangement. The watchdog makes a regression fail in seconds instead of hanging.
TEST(Locate, NextToWhereObstaclesTouchReturns) {
  const auto c = std::make_shared<const CSpace>(
      world_from(R"({"obstacles": [[[2, 2], [3, 2], [3, 3], [2, 3]], [[0, 2], [1, 1], [2, 2]]]})"));
  std::promise<Location::Kind> kind;
  std::future<Location::Kind> answer = kind.get_future();
  std::thread([c, kind = std::move(kind)]() mutable { kind.set_value(c->locate(pt("2", "3/2")).kind); }).detach();
  ASSERT_EQ(answer.wait_for(std::chrono::seconds(10)), std::future_status::ready)
      << "CSpace::locate did not return in 10 s";
  EXPECT_EQ(answer.get(), Location::Kind::free);
}

namespace {

// Every point of the half-integer lattice of `bounds`, located with a watchdog of 20 s in all.
std::vector<Location::Kind> locate_lattice(const std::shared_ptr<const CSpace>& c, int lo, int hi) {
  std::promise<std::vector<Location::Kind>> kinds;
  std::future<std::vector<Location::Kind>> answer = kinds.get_future();
  std::thread([c, lo, hi, kinds = std::move(kinds)]() mutable {
    std::vector<Location::Kind> out;
    for (int x = 2 * lo; x <= 2 * hi; ++x)
      for (int y = 2 * lo; y <= 2 * hi; ++y) out.push_back(c->locate({Rational(x, 2), Rational(y, 2)}).kind);
    kinds.set_value(out);
  }).detach();
  if (answer.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    ADD_FAILURE() << "CSpace::locate did not return in 20 s";
    std::abort();  // the thread cannot be stopped; end the run rather than hang it
  }
  return answer.get();
}

}  // namespace

// The worlds of the hardening issue that never finished (plan, cspace and check hung in the
// landmark walk): a triangle whose apex touches a box's top edge, and a hole touching its outer
// boundary at a vertex. Every lattice point is located, and a few are checked by hand.
TEST(Locate, WorldsThatHungInTheLandmarkWalkAnswer) {
  const auto apex = std::make_shared<const CSpace>(
      world_from(R"({"bounds": [-1, -1, 7, 7], "obstacles": [[[0, 0], [6, 0], [6, 2], [0, 2]], [[3, 2], [4, 4], [2, )"
                 R"(4]]], "start": [3, -0.5], "goal": [6.5, 6.5]})"));
  EXPECT_EQ(locate_lattice(apex, -1, 7).size(), 17u * 17u);
  EXPECT_EQ(apex->locate(pt("3", "-0.5")).kind, Location::Kind::free);
  EXPECT_EQ(apex->locate(pt("3", "2")).kind, Location::Kind::contact);
  EXPECT_EQ(apex->locate(pt("3", "3")).kind, Location::Kind::blocked);
  EXPECT_EQ(apex->locate(pt("2", "2.5")).kind, Location::Kind::free);
  EXPECT_EQ(apex->free_components().size(), 1u);

  const auto hole = std::make_shared<const CSpace>(world_from(
      R"({"bounds": [0, 0, 10, 10], "obstacles": [{"outer": [[1, 1], [9, 1], [9, 9], [1, 9]], "holes": [[[1, )"
      R"(1], [3, 5], [5, 3]]]}]})"));
  EXPECT_EQ(locate_lattice(hole, 0, 10).size(), 21u * 21u);
  EXPECT_EQ(hole->locate(pt("3", "3")).kind, Location::Kind::free);
  EXPECT_EQ(hole->locate(pt("1", "1")).kind, Location::Kind::contact);
  EXPECT_EQ(hole->locate(pt("6", "6")).kind, Location::Kind::blocked);
  // The hole touches the outside at one point only: two free components meeting at a pinch.
  EXPECT_EQ(hole->free_components().size(), 2u);
  EXPECT_EQ(hole->locate(pt("1", "1")).components.size(), 2u);
}

// Two holes sharing an edge: the obstacle has zero width between them, so the two are one free
// region (the validation refuses a hole sharing an edge with its outer boundary instead, where
// CGAL kept the hole filled).
TEST(Locate, HolesSharingAnEdgeAreOneFreeRegion) {
  const auto c = std::make_shared<const CSpace>(world_from(
      R"({"bounds": [0, 0, 10, 10], "obstacles": [{"outer": [[1, 1], [9, 1], [9, 9], [1, 9]], "holes": [[[2, )"
      R"(2], [5, 2], [5, 5], [2, 5]], [[5, 2], [8, 2], [8, 5], [5, 5]]]}]})"));
  EXPECT_EQ(locate_lattice(c, 0, 10).size(), 21u * 21u);
  ASSERT_EQ(c->free_components().size(), 2u);
  const Location left = c->locate(pt("3", "3")), right = c->locate(pt("6", "3")), seam = c->locate(pt("5", "3"));
  EXPECT_EQ(left.kind, Location::Kind::free);
  EXPECT_EQ(seam.kind, Location::Kind::free);
  EXPECT_EQ(left.components, right.components);
  EXPECT_EQ(c->locate(pt("5", "6")).kind, Location::Kind::blocked);
}
