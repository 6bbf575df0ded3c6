// The tangent visibility graph (`visibility` on worlds with discs, walls or a disc robot) against
// lengths computed by hand: round one disc, between two discs of equal and of unequal radii, a disc
// robot round a square; through a gap 1e-12 wider than the robot (a path) and one exactly as wide
// (none), polygons touching at a corner (no passing there). Each found path is checked again
// independently (piece_path_check.hpp) and its certified bounds must hold the hand-computed length.
#include "piece_path_check.hpp"

#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/robot_path_check.hpp>
#include <polyplan/roadmaps/tangent_visibility.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace polyplan {
namespace {

constexpr double pi = 3.14159265358979323846;

PlanReport<ExactPoint> plan(const std::string& world_text) {
  const Problem problem = Problem::parse(world_text, "test.json");
  const auto planner = make_planner("visibility", problem, {});
  const Report report = planner->plan(0);
  const auto& typed = std::get<PlanReport<ExactPoint>>(report.typed());
  if (typed.found)
    test::expect_valid_pieces(*problem.world(), typed,
                              [&](const auto& p) { return check_translating_path(problem, p); });
  return typed;
}

// The report's length and its certified bounds hold `expected` (within 1e-12 relative), and the
// bounds are 1e-12 tight.
void expect_length(const PlanReport<ExactPoint>& report, double expected) {
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_NEAR(report.length, expected, 1e-12 * expected);
  const double lower = report.facts.at(FactKey<double>{"length_lower"});
  const double upper = report.facts.at(FactKey<double>{"length_upper"});
  EXPECT_LE(lower, expected * (1 + 1e-15));
  EXPECT_GE(upper, expected * (1 - 1e-15));
  EXPECT_LE(upper - lower, 1e-12 * expected);
}

TEST(TangentVisibility, RoundOneDisc) {
  // From (-3, 0) to (3, 0) round the unit disc: two tangents of √8 and the arc between their
  // touching points, π − 2·acos(1/3).
  const auto report = plan(R"({"bounds": [-10, -10, 10, 10], "discs": [{"center": [0, 0], "radius": 1}],
                               "start": [-3, 0], "goal": [3, 0]})");
  expect_length(report, 2 * std::sqrt(8.0) + pi - 2 * std::acos(1.0 / 3));
  ASSERT_EQ(report.pieces.size(), 3u);
  EXPECT_EQ(report.pieces[1].kind, PathPiece::Kind::arc);
  EXPECT_DOUBLE_EQ(report.pieces[1].radius, 1.0);
}

TEST(TangentVisibility, BetweenTwoEqualDiscs) {
  // Unit discs at (-1, 0) and (2, 0), from (-4, 0) to (5, 0): tangents of √8 at each end, the
  // outer tangent of 3 between the tops, two arcs of π/2 − acos(1/3).
  const auto report = plan(R"({"bounds": [-10, -10, 10, 10],
      "discs": [{"center": [-1, 0], "radius": 1}, {"center": [2, 0], "radius": 1}],
      "start": [-4, 0], "goal": [5, 0]})");
  expect_length(report, 2 * std::sqrt(8.0) + 3 + 2 * (pi / 2 - std::acos(1.0 / 3)));
  EXPECT_EQ(report.pieces.size(), 5u);
}

TEST(TangentVisibility, BetweenTwoUnequalDiscs) {
  // Discs of radius 1 at (0, 0) and 2 at (4, 0), from (-3, 0) to (8, 0). The outer tangent touches
  // both where the unit normal n = (-1/4, √15/4) points (n·(4, 0) = 1 − 2), and is √(16 − 1) long;
  // the start's tangent is √8, the goal's √(16 − 4), touching at angles π − acos(1/3) and π/3.
  const auto report = plan(R"({"bounds": [-10, -10, 10, 10],
      "discs": [{"center": [0, 0], "radius": 1}, {"center": [4, 0], "radius": 2}], "start": [-3, 0], "goal": [8, 0]})");
  const double normal = pi - std::acos(0.25);
  const double arcs = 1 * ((pi - std::acos(1.0 / 3)) - normal) + 2 * (normal - pi / 3);
  expect_length(report, std::sqrt(8.0) + std::sqrt(15.0) + std::sqrt(12.0) + arcs);
}

TEST(TangentVisibility, DiscRobotRoundASquare) {
  // A robot of radius 1/2 round the square [-1, 1]²: tangent √(5 − 1/4) from (-3, 0) to the circle
  // about the corner (-1, 1), the arc to the top, the top edge's offset (2), and back down alike.
  const auto report = plan(R"({"bounds": [-10, -10, 10, 10], "robot": {"disc": 0.5},
      "obstacles": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]], "start": [-3, 0], "goal": [3, 0]})");
  const double towards_start = std::atan2(-1.0, -2.0) + 2 * pi;  // from the corner
  const double touching = towards_start - std::acos(0.5 / std::sqrt(5.0));
  expect_length(report, 2 * (std::sqrt(4.75) + 0.5 * (touching - pi / 2)) + 2);
}

// Two unit discs 3 apart with walls closing the sides: a gap of 1 between them.
std::string gap_world(const std::string& robot) {
  return R"({"bounds": [-5, -3, 5, 3], "discs": [{"center": [0, 1.5], "radius": 1}, {"center": [0, -1.5], "radius": 1}],
             "walls": [[[0, 2.5], [0, 3]], [[0, -2.5], [0, -3]]], "robot": {"disc": )" +
         robot + R"(}, "start": [-4, 1], "goal": [4, -1]})";
}

TEST(TangentVisibility, AGapExactlyAsWideAsTheRobotHasNoPassage) {
  const auto report = plan(gap_world("0.5"));
  EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
}

TEST(TangentVisibility, AGapOneTrillionthWiderHasOne) {
  const auto report = plan(gap_world("0.4999999999995"));
  ASSERT_TRUE(report.found) << report.why_not;
  // Through the gap's middle: nearly the straight line, bending round both discs' grown circles.
  EXPECT_LT(report.length, 8.3);
  EXPECT_GT(report.length, std::hypot(8.0, 2.0));
}

TEST(TangentVisibility, PolygonsTouchingAtACornerLeaveNoPassage) {
  // A point robot: squares [0, 1]² and [1, 2]² meet at (1, 1), on the straight line from (0, 2)
  // to (2, 0); the way round either square is 4. A disc far off makes it a round world.
  const auto report = plan(R"({"bounds": [-5, -5, 5, 5], "discs": [{"center": [4, 4], "radius": 0.5}],
      "obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]], [[1, 1], [2, 1], [2, 2], [1, 2]]],
      "start": [0, 2], "goal": [2, 0]})");
  expect_length(report, 4);
}

TEST(TangentVisibility, AWallIsPassedRoundItsEnd) {
  // A point robot and the wall x = 0, y in [-1, 3]: from (-1, 0) to (1, 0) over its top end (0, 3).
  const auto report =
      plan(R"({"bounds": [-5, -5, 5, 5], "walls": [[[0, -5], [0, 3]]], "start": [-1, 0], "goal": [1, 0]})");
  expect_length(report, 2 * std::sqrt(10.0));
}

TEST(TangentVisibility, AClosedRingOfWallsIsGoneRoundAndNeverEntered) {
  // The walls round the square [1, 3]²: a robot sliding along one of them keeps to its face, so the
  // path from outside to a goal inside is none (the graph's corners hold a node per sector between
  // the walls); round it, over two corners: √2 + 2 + √2; inside, straight.
  const std::string ring = R"({"walls": [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]], "start": [0, 2], )";
  expect_length(plan(ring + R"("goal": [4, 2]})"), 2 + 2 * std::sqrt(2.0));
  const auto inside = plan(ring + R"("goal": [2, 2]})");
  EXPECT_EQ(inside.status, PlanStatus::no_path) << inside.why_not;
  const auto along =
      plan(R"({"walls": [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]], "start": [2, 1.5], "goal": [2.5, 2.5]})");
  expect_length(along, std::sqrt(1.25));
}

TEST(TangentVisibility, DecimalsThatDoublesGetWrong) {
  // The robot (radius 0.1) slides along y = 0.3 past a disc of radius 0.2 centred at (0, 0): exactly
  // tangent in decimals (0.1 + 0.2 = 0.3), though 0.1 + 0.2 > 0.3 in doubles: the straight line.
  const auto report = plan(R"({"bounds": [-5, -5, 5, 5], "robot": {"disc": 0.1},
      "discs": [{"center": [0, 0], "radius": 0.2}], "start": [-1, 0.3], "goal": [1, 0.3]})");
  expect_length(report, 2);
  EXPECT_EQ(report.pieces.size(), 1u);
}

TEST(TangentVisibility, AStartInsideADiscIsAnInvalidQuery) {
  // Asked directly (the library, Python), not through a world file's checked queries.
  const Problem problem = Problem::parse(R"({"bounds": [-5, -5, 5, 5], "discs": [{"center": [0, 0], "radius": 1}],
                                            "start": [-3, 0], "goal": [3, 0]})",
                                         "test.json");
  TangentVisibilityGraph graph(problem.round_world());
  const auto report = graph.plan(Query{{Rational(1, 2), 0}, {3, 0}, "inside"});
  EXPECT_EQ(report.status, PlanStatus::invalid_query) << report.why_not;
  EXPECT_NE(report.why_not.find("discs[0]"), std::string::npos) << report.why_not;
}

}  // namespace
}  // namespace polyplan
