// The picture of a round world's C-space (draw/round_cspace_svg.hpp): a disc's C-obstacle is a
// circle of the grown radius, a rounded polygon and a grown wall are their shapes stroked 2r wide
// (r in the picture's pixels) inside a group that joins and caps round; the legends are the polygon
// C-space picture's.
#include <polyplan/draw/round_cspace_svg.hpp>

#include "draw/svg_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polyplan {
namespace {

using test::count;

TEST(RoundCSpaceSvg, GrownShapesAreStrokedTwiceTheRadiusWideWithRoundJoins) {
  const World world = test::world_from(R"({"bounds": [0, 0, 10, 10], "robot": {"disc": 0.5},
      "obstacles": [[[2, 2], [4, 2], [4, 4], [2, 4]]], "walls": [[[6, 1], [6, 8], [9, 8]]],
      "discs": [{"center": [3, 7], "radius": 1}], "start": [1, 1], "goal": [9, 1]})");
  const svg::Drawing drawing = round_cspace_picture(world, round_cspace(world));
  const std::string svg = drawing.str();
  const auto group = svg.find(R"(<g class="cobstacles" stroke-linejoin="round" stroke-linecap="round")");
  ASSERT_NE(group, std::string::npos);
  const std::string inside = svg.substr(group, svg.find("</g>\n</g>", group) - group);
  // The fill layer: stroked exactly 2r wide in pixels (the outline layer 2.4 px wider).
  const auto fill = inside.find(R"(fill="#f4a259")");
  ASSERT_NE(fill, std::string::npos);
  const double width = std::stod(test::attribute_at(inside, inside.rfind('<', fill), "stroke-width"));
  EXPECT_NEAR(width, 2 * 0.5 * drawing.scale(), 1e-6 * width);
  // The disc grown by the robot's radius: r = 1.5 world units.
  const auto circle = inside.find("<circle", fill);
  ASSERT_NE(circle, std::string::npos);
  EXPECT_NEAR(std::stod(test::attribute_at(inside, circle, "r")), 1.5 * drawing.scale(), 1e-3);
  EXPECT_EQ(count(inside, "<circle"), 3u);  // outline, white and fill layers
  const std::vector<std::string> legend{"free space",
                                        "bounds",
                                        "walls (robot would leave the bounds)",
                                        "C-obstacles",
                                        "obstacles and discs",
                                        "walls (zero thickness)",
                                        "robot at start",
                                        "start",
                                        "goal"};
  EXPECT_EQ(test::legend_labels(svg), legend);
}

}  // namespace
}  // namespace polyplan
