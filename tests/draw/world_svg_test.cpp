// Pictures of worlds and C-spaces (draw/world_svg.cpp), checked on the SVG text: the box a
// picture shows, what is drawn in which of the theme's colours, the legend's entries in order.
#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>
#include "draw/svg_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace polyplan;
using polyplan::test::body_of;
using polyplan::test::count;
using polyplan::test::dots_in_group;
using polyplan::test::fill_is;
using polyplan::test::stroke_is;
using polyplan::test::legend_labels;
using polyplan::test::nesting_error;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

using Labels = std::vector<std::string>;

// A unit square robot (reference at its lower-left corner) in [0, 6]^2 with the obstacle [2, 3]^2.
const char* kRobotWorld = R"({"bounds": [0, 0, 6, 6], "obstacles": [[[2, 2], [3, 2], [3, 3], [2, 3]]],
                              "robot": {"parts": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}, "start": [0, 0], )"
                          R"("goal": [5, 5]})";

// A point robot whose free space is two squares meeting at (2, 2) (data/worlds/touching_corners.json).
const char* kTwoComponents = R"({"bounds": [0, 0, 4, 4],
                                 "obstacles": [[[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]],
                                 "start": [1, 1], "goal": [3, 3]})";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace

TEST(ViewBox, IsTheBoundsWhenThereAreBounds) {
  const World w = world_from(kRobotWorld);
  const svg::Box2 box = view_box(w, CSpace(w));
  EXPECT_EQ(box.xmin, 0);
  EXPECT_EQ(box.ymin, 0);
  EXPECT_EQ(box.xmax, 6);
  EXPECT_EQ(box.ymax, 6);
}

TEST(ViewBox, WithoutBoundsHoldsObstaclesCObstaclesQueriesAndTheRobotAtTheStart) {
  // Obstacle [1, 2]^2; its C-obstacle for the robot [0, 1]^2 is [0, 2]^2; the goal (-3, 1); the
  // robot at the start (5, 5) reaches (6, 6).
  const World w = world_from(R"({"obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]],
                                 "robot": {"parts": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}, "start": [5, 5], )"
                             R"("goal": [-3, 1]})");
  const svg::Box2 box = view_box(w, CSpace(w));
  EXPECT_EQ(box.xmin, -3);
  EXPECT_EQ(box.ymin, 0);
  EXPECT_EQ(box.xmax, 6);
  EXPECT_EQ(box.ymax, 6);
}

TEST(ViewBox, EmptyWorldIsTheUnitSquare) {
  const World w = world_from(R"({"obstacles": []})");
  const svg::Box2 box = view_box(w, CSpace(w));
  EXPECT_EQ(box.xmin, 0);
  EXPECT_EQ(box.ymin, 0);
  EXPECT_EQ(box.xmax, 1);
  EXPECT_EQ(box.ymax, 1);
}

TEST(DrawWorld, ShowsBoundsObstaclesRobotAndQueriesWithALegendEntryEach) {
  const World w = world_from(kRobotWorld);
  svg::Drawing d(view_box(w, CSpace(w)));
  draw_world(d, w);
  const std::string svg = d.str();
  EXPECT_EQ(nesting_error(svg), "");
  EXPECT_EQ(legend_labels(svg), (Labels{"bounds", "obstacles", "robot at start", "start", "goal"}));
  const std::string body = body_of(svg);
  EXPECT_EQ(count(body, fill_is(theme::obstacle_fill)), 1u);
  // The robot is translucent (the start's dots share its green).
  EXPECT_EQ(count(body, fill_is(theme::robot_fill) + " fill-opacity=\"0.18\""), 1u);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::start) + " stroke=\"#fff\""), 1u);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::goal) + " stroke=\"#fff\""), 1u);
  // The world as its file describes it: no C-space.
  EXPECT_EQ(body.find(theme::cobstacle_fill), std::string::npos);
}

TEST(DrawWorld, SeveralQueriesAreLabelledAndCoincidingGoalsShareALabel) {
  const World w = world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [],
                                 "queries": [{"start": [1, 1], "goal": [9, 9]}, {"start": [2, 1], "goal": [9, 9]},
                                             {"start": [3, 1], "goal": [5, 9]}]})");
  svg::Drawing d(view_box(w, CSpace(w)));
  draw_world(d, w);
  const std::string svg = d.str();
  EXPECT_EQ(legend_labels(svg), (Labels{"bounds", "starts", "goals"}));
  const std::string body = body_of(svg);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::start) + " stroke=\"#fff\""), 3u);
  EXPECT_EQ(dots_in_group(body, fill_is(theme::goal) + " stroke=\"#fff\""), 3u);
  for (const char* label : {">s0<", ">s1<", ">s2<", ">g0,1<", ">g2<"}) EXPECT_EQ(count(body, label), 1u) << label;
  EXPECT_EQ(count(body, ">g1<"), 0u);
}

TEST(DrawCspace, LegendFollowsTheDrawingOrder) {
  const CSpace c(world_from(kRobotWorld));
  svg::Drawing d(view_box(c.world(), c));
  draw_cspace(d, c);
  const std::string svg = d.str();
  EXPECT_EQ(nesting_error(svg), "");
  EXPECT_EQ(legend_labels(svg), (Labels{"free space (1 component)", "bounds", "walls (robot would leave the bounds)",
                                        "C-obstacles", "obstacles", "robot at start", "start", "goal"}));
  const std::string body = body_of(svg);
  // Free space under walls under C-obstacles under obstacles.
  const auto free = body.find(fill_is(theme::free_tints[0].fill));
  const auto walls = body.find(fill_is(theme::walls_fill));
  const auto cobstacles = body.find(fill_is(theme::cobstacle_fill));
  const auto obstacles = body.find(fill_is(theme::obstacle_fill));
  ASSERT_NE(obstacles, std::string::npos);
  EXPECT_LT(free, walls);
  EXPECT_LT(walls, cobstacles);
  EXPECT_LT(cobstacles, obstacles);
}

TEST(DrawCspace, PointRobotHasNoWallsAndSaysItsCObstaclesAreTheObstacles) {
  const CSpace c(world_from(kTwoComponents));
  svg::Drawing d(view_box(c.world(), c));
  draw_cspace(d, c);
  const std::string svg = d.str();
  EXPECT_EQ(legend_labels(svg), (Labels{"free space (2 components)", "bounds", "C-obstacles (= obstacles, point robot)",
                                        "obstacles", "start", "goal"}));
  // One tint per component, the first the legend's.
  const std::string body = body_of(svg);
  EXPECT_EQ(count(body, fill_is(theme::free_tints[0].fill)), 1u);
  EXPECT_EQ(count(body, fill_is(theme::free_tints[1].fill)), 1u);
  EXPECT_EQ(body.find(theme::walls_fill), std::string::npos);
  // The two obstacles touch: one solid, one C-obstacle; two obstacles as the file has them.
  EXPECT_EQ(count(body, fill_is(theme::cobstacle_fill)), 1u);
  EXPECT_EQ(count(body, fill_is(theme::obstacle_fill)), 2u);
}

TEST(DrawCspace, UnfilledLeavesTheFreeSpaceOut) {
  const CSpace c(world_from(kTwoComponents));
  svg::Drawing d(view_box(c.world(), c));
  draw_cspace(d, c, FreeSpace::unfilled);
  const std::string svg = d.str();
  EXPECT_EQ(legend_labels(svg),
            (Labels{"bounds", "C-obstacles (= obstacles, point robot)", "obstacles", "start", "goal"}));
  for (const theme::Tint& tint : theme::free_tints) EXPECT_EQ(svg.find(tint.fill), std::string::npos) << tint.fill;
}

TEST(DrawPath, LineAndDotsInTheGivenColour) {
  const CSpace c(world_from(kTwoComponents));
  svg::Drawing d(view_box(c.world(), c));
  draw_path(d, {pt("1", "1"), pt("2", "2"), pt("1", "3/2")}, "touch and back", theme::path_colour(3));
  const std::string svg = d.str();
  EXPECT_EQ(legend_labels(svg), Labels{"touch and back"});
  const std::string body = body_of(svg);
  EXPECT_EQ(count(body, stroke_is(theme::path_colour(3))), 1u);                             // the line
  EXPECT_EQ(dots_in_group(body, fill_is(theme::path_colour(3)) + " stroke=\"none\""), 3u);  // its vertices
}

TEST(DrawPath, EmptyPathDrawsNothing) {
  const svg::Drawing before({0, 0, 4, 4});
  svg::Drawing d({0, 0, 4, 4});
  draw_path(d, {}, "nothing");
  EXPECT_EQ(d.str(), before.str());
}

TEST(WriteCspaceSvg, WritesTheCSpacePictureWithThePath) {
  const CSpace c(world_from(kRobotWorld));
  const std::vector<ExactPoint> path{pt("0", "0"), pt("1", "3"), pt("5", "5")};
  const std::string file = polyplan::test::temp_path("world_svg_cspace.svg");
  write_cspace_svg(c, file, &path);
  svg::Drawing expected(view_box(c.world(), c));
  draw_cspace(expected, c);
  draw_path(expected, path, "path");
  EXPECT_EQ(slurp(file), expected.str());
  EXPECT_EQ(legend_labels(slurp(file)).back(), "path");
  write_cspace_svg(c, file);
  EXPECT_EQ(legend_labels(slurp(file)).back(), "goal");
  std::remove(file.c_str());
}

TEST(WriteCspaceSvg, UnwritablePathThrowsNamingIt) {
  const CSpace c(world_from(kRobotWorld));
  const std::string file = "/nonexistent-polyplan-dir/cspace.svg";
  try {
    write_cspace_svg(c, file);
    FAIL() << "wrote to " << file;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
}
