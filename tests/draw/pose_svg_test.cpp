// Pictures of a rotating robot's plans (draw/pose_svg.cpp) from reports built by hand: the strobe
// of robots from start to goal, the turns marked where they happen, the orientation panel with the
// angles the path reaches, and nothing but the world for a report without a path.
#include <polyplan/draw/pose_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include "draw/svg_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace polyplan;
using polyplan::test::count;
using polyplan::test::legend_labels;
using polyplan::test::nesting_error;
using polyplan::test::world_from;

namespace {

// A 4×1 rod in a 20×20 box with one block.
const char* kRodWorld = R"({"bounds": [0, 0, 20, 20], "obstacles": [[[8, 8], [12, 8], [12, 12], [8, 12]]],
                            "robot": {"parts": [[[-2, -0.5], [2, -0.5], [2, 0.5], [-2, 0.5]]]},
                            "start": [3, 3, 0], "goal": [17, 17, 90]})";

Pose pose(int x, int y, double degrees) { return {{Rational(x), Rational(y)}, exact_rotation(degrees), degrees}; }

// Translate to (3, 16), turn there through 90° in two turns, translate to the goal.
PlanReport<Pose> turning_report() {
  PlanReport<Pose> report;
  report.found = true;
  report.path = {pose(3, 3, 0), pose(3, 16, 0), pose(3, 16, 45), pose(3, 16, 90), pose(17, 17, 90)};
  return report;
}

bool has(const std::vector<std::string>& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

TEST(PoseSvg, DrawsTheRobotAlongThePathAndMarksTheTurns) {
  const World world = world_from(kRodWorld);
  const std::string svg = draw_plan(world, {turning_report()}).str();
  EXPECT_EQ(nesting_error(svg), "");
  const auto labels = legend_labels(svg);
  for (const char* label :
       {"path (reference point)", "turns on the spot", "robot at start", "robot at goal", "obstacles"})
    EXPECT_TRUE(has(labels, label)) << label;
  // The strobe: the robot in the start's colour and in the goal's, and more than the five poses.
  EXPECT_GE(count(svg, "fill=\"" + theme::start_to_goal(0) + "\""), 2u);
  EXPECT_GE(count(svg, "fill=\"" + theme::start_to_goal(1) + "\""), 2u);
  EXPECT_GT(count(svg, "fill-rule=\"evenodd\""), 5u);
  // The panel says how far the path turns.
  EXPECT_NE(svg.find("orientation along the path"), std::string::npos);
  EXPECT_NE(svg.find(">90°<"), std::string::npos);
  EXPECT_NE(svg.find(">0°<"), std::string::npos);
}

TEST(PoseSvg, AReportWithoutAPathDrawsTheWorldOnly) {
  const World world = world_from(kRodWorld);
  PlanReport<Pose> none;
  none.why_not = "no path";
  const std::string svg = draw_plan(world, {none}).str();
  const auto labels = legend_labels(svg);
  EXPECT_TRUE(has(labels, "obstacles"));
  EXPECT_FALSE(has(labels, "turns on the spot"));
  EXPECT_EQ(svg.find("orientation along the path"), std::string::npos);
}

TEST(PoseSvg, LabelsSeveralPaths) {
  const World world = world_from(kRodWorld);
  const std::string svg = draw_plan(world, {turning_report(), turning_report()}, {"every 45°", "again"}).str();
  const auto labels = legend_labels(svg);
  EXPECT_TRUE(has(labels, "every 45° (reference point)"));
  EXPECT_TRUE(has(labels, "again (reference point)"));
}

}  // namespace
