// A translating polygon robot among discs and walls (geometry/round_cspace.hpp): the C-obstacle of
// a disc is the reflected robot round the disc's centre, grown by its radius (a rounded polygon);
// of a wall, the wall swept by the reflected robot. Against configurations decided by hand (an
// asymmetric robot, so that a C-obstacle built from R rather than −R fails), a shortest length
// computed by hand round a rounded square, a door exactly as wide as the robot (no path) and one
// 1e-12 wider (a path), and clear refusals.
#include "piece_path_check.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/robot_path_check.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

namespace polyplan {
namespace {

PlanReport<ExactPoint> plan(const Problem& problem, const std::string& planner = "visibility",
                            const OptionValues& options = {}) {
  const auto built = make_planner(planner, problem, options);
  const Report report = built->plan(0);
  const auto& typed = std::get<PlanReport<ExactPoint>>(report.typed());
  if (typed.found && !typed.pieces.empty())
    test::expect_valid_pieces(*problem.world(), typed,
                              [&](const auto& p) { return check_translating_path(problem, p); });
  if (typed.found && typed.pieces.empty()) EXPECT_TRUE(check_translating_path(problem, typed.path).valid);
  return typed;
}

TEST(PolygonRobotAmongDiscs, TheDiscsCObstacleIsTheReflectedRobotGrown) {
  // The triangle (0, 0), (2, 0), (0, 2) about its right-angle corner, a unit disc at the origin:
  // at (-2.5, 0) the triangle spans x -2.5..-0.5 on the axis, 0.5 from the disc's centre — it
  // overlaps; at (2.5, 0) it is 2.5 away, and at (0.5, -1.5) its hypotenuse passes
  // (1 + 1 − 1)/√2 ≈ 0.707 from the centre — overlaps; at (-3, -1) its hypotenuse x + y = -2 and its
  // corner (-1, -1) are √2 away — free. A C-obstacle of +R would swap the first two.
  const Problem problem = Problem::parse(R"({"bounds": [-10, -10, 10, 10],
      "robot": {"parts": [[[0, 0], [2, 0], [0, 2]]]}, "discs": [{"center": [0, 0], "radius": 1}],
      "start": [5, 5], "goal": [-5, -5]})",
                                         "triangle.json");
  const RoundWorld& round = problem.round_world();
  EXPECT_TRUE(round.config_not_free({Rational(-5, 2), 0}).has_value());
  EXPECT_FALSE(round.config_not_free({Rational(5, 2), 0}).has_value());
  EXPECT_TRUE(round.config_not_free({Rational(1, 2), Rational(-3, 2)}).has_value());
  EXPECT_FALSE(round.config_not_free({-3, -1}).has_value());
  EXPECT_NE(round.config_not_free({Rational(-5, 2), 0})->find("discs[0]"), std::string::npos);
}

TEST(PolygonRobotAmongDiscs, ShortestPathRoundARoundedSquare) {
  // A 2×2 square robot round a unit disc: the C-obstacle is the square [-1, 1]² rounded by 1. From
  // (-5, 0) to (5, 0): a tangent of 4 to the corner circle at (-1, 1), an arc of 2·atan(1/4) to
  // (-1, 2), the top side 2, and the same down the other side: 10 + 4·atan(1/4).
  const Problem problem = Problem::parse(R"({"bounds": [-10, -10, 10, 10],
      "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}, "discs": [{"center": [0, 0], "radius": 1}],
      "start": [-5, 0], "goal": [5, 0]})",
                                         "square.json");
  const auto report = plan(problem);
  ASSERT_TRUE(report.found) << report.why_not;
  const double expected = 10 + 4 * std::atan(0.25);
  EXPECT_NEAR(report.length, expected, 1e-12 * expected);
  EXPECT_LE(report.facts.at(FactKey<double>{"length_lower"}), expected * (1 + 1e-15));
  EXPECT_GE(report.facts.at(FactKey<double>{"length_upper"}), expected * (1 - 1e-15));
  EXPECT_EQ(report.pieces.size(), 5u);
}

// A square robot of half-width h between two walls along x = 0 that leave a door 2 wide (y -1..1)
// and reach the bounds: from (-3, 0) to (3, 0).
Problem door(const std::string& h) {
  return Problem::parse(R"({"bounds": [-5, -10, 5, 10], "robot": {"parts": [[[-)" + h + ", -" + h + "], [" + h + ", -" +
                            h + "], [" + h + ", " + h + "], [-" + h + ", " + h + R"(]]]},
      "walls": [[[0, -10], [0, -1]], [[0, 1], [0, 10]]], "start": [-3, 0], "goal": [3, 0]})",
                        "door.json");
}

TEST(PolygonRobotAmongWalls, ADoorExactlyAsWideAsTheRobotIsNoPassage) {
  // h = 1: the walls' sums [-1, 1] × [-11, 0] and [-1, 1] × [0, 11] meet along y = 0: one solid.
  for (const std::string planner : {"visibility", "raster"}) {
    SCOPED_TRACE(planner);
    const auto closed = plan(door("1"), planner);
    EXPECT_FALSE(closed.found);
  }
  const auto open = plan(door("0.999999999999"));
  ASSERT_TRUE(open.found) << open.why_not;
  EXPECT_NEAR(open.length, 6, 1e-12);
  EXPECT_TRUE(check_translating_path(door("0.999999999999"), {{-3, 0}, {3, 0}}).valid);
  const PathCheck through = check_translating_path(door("1"), {{-3, 0}, {3, 0}});
  EXPECT_FALSE(through.valid);
  EXPECT_NE(through.reason.find("walls["), std::string::npos) << through.reason;
}

TEST(PolygonRobotAmongWalls, TheSamplingPlannersCertifyTheirMotions) {
  for (const std::string planner : {"rrtconnect", "prm"}) {
    SCOPED_TRACE(planner);
    const auto report = plan(door("0.5"), planner, {{"seed", "1"}});
    EXPECT_TRUE(report.found) << report.why_not;
  }
}

TEST(PolygonRobotAmongDiscs, RefusedInDiscBoundsAndByTheNavigationFunction) {
  try {
    Problem::parse(R"({"bounds": {"center": [0, 0], "radius": 10}, "robot": {"parts": [[[0, 0], [1, 0], [0, 1]]]},
                       "obstacles": [], "start": [1, 1], "goal": [-1, -1]})",
                   "in_a_disc.json")
        .round_world();
    ADD_FAILURE() << "a polygon robot in disc bounds";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("in_a_disc.json: bounds: a polygon robot in disc bounds"), std::string::npos)
        << e.what();
  }
  const Problem square = Problem::parse(R"({"bounds": [-10, -10, 10, 10],
      "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}, "discs": [{"center": [0, 0], "radius": 1}],
      "start": [-5, 0], "goal": [5, 0]})",
                                        "square.json");
  const auto report = plan(square, "navigation-function");
  EXPECT_FALSE(report.found);
  EXPECT_NE(report.why_not.find("polygon"), std::string::npos) << report.why_not;
}

TEST(PolygonRobotAmongWalls, ExactRootsLeaveNoDiagnosticsFile) {
  // The floor plan's tangents take square roots of numbers that are 0 exactly or nearly, whose
  // filter doubles CORE once rounded below 0: it then wrote "Core_Diagnostics" into the working
  // directory (and exits where it cannot write). The roots (roadmaps/detail/algebraic.hpp) keep
  // it quiet.
  const std::filesystem::path here = std::filesystem::current_path();
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("polyplan_core_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  std::filesystem::current_path(scratch);
  const Problem floor = Problem::read(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/polygon_robot_floor_plan.json");
  EXPECT_TRUE(plan(floor).found);
  EXPECT_FALSE(std::filesystem::exists(scratch / "Core_Diagnostics"));
  std::filesystem::current_path(here);
  std::filesystem::remove_all(scratch);
}

}  // namespace
}  // namespace polyplan
