// The SVG writer alone: no CGAL, no C-space.
#include <polyplan/draw/svg.hpp>
#include "draw/svg_fixtures.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using polyplan::svg::Box2;
using polyplan::svg::Drawing;
using polyplan::svg::Point2;
using polyplan::svg::Style;
using polyplan::test::attribute;
using polyplan::test::count;
using polyplan::test::numbers_in;

TEST(SvgDrawing, PictureShowsTheBoxWithASmallMargin) {
  for (const Box2 box :
       {Box2{0, 0, 10, 5}, Box2{-3, 2, 1, 3}, Box2{1000, -2000, 1001, -1999.5}, Box2{0, 0, 1e-6, 1e-6}}) {
    const Drawing d(box, 640);
    const std::string svg = d.str();
    // The file is in the picture's pixel frame.
    const auto vb = numbers_in(attribute(svg, "svg", "viewBox"));
    ASSERT_EQ(vb.size(), 4u) << svg;
    EXPECT_EQ(vb[0], 0);
    EXPECT_EQ(vb[1], 0);
    EXPECT_DOUBLE_EQ(vb[2], 640);
    EXPECT_NEAR(vb[3], d.height_px(), 1e-4);
    EXPECT_EQ(attribute(svg, "svg", "width"), "640");
    EXPECT_NEAR(std::stod(attribute(svg, "svg", "height")), d.height_px(), 1e-4);
    // The box's corners land inside the picture, 2% to 6% of its larger side from the edges.
    const Point2 top_left = d.to_screen({box.xmin, box.ymax});
    const Point2 bottom_right = d.to_screen({box.xmax, box.ymin});
    const double larger = std::max(bottom_right.x - top_left.x, bottom_right.y - top_left.y);
    for (const double gap : {top_left.x, top_left.y, d.width_px() - bottom_right.x, d.height_px() - bottom_right.y}) {
      EXPECT_GT(gap, 0.02 * larger);
      EXPECT_LT(gap, 0.06 * larger);
    }
    // The aspect ratio is kept: one world unit is as long across as up.
    EXPECT_NEAR((bottom_right.x - top_left.x) / (box.xmax - box.xmin),
                (bottom_right.y - top_left.y) / (box.ymax - box.ymin), 1e-6 * d.scale());
    // The view is the box plus the margin.
    EXPECT_LT(d.view().xmin, box.xmin);
    EXPECT_GT(d.view().ymax, box.ymax);
  }
}

TEST(SvgDrawing, DegenerateBoxStillGivesAPicture) {
  const Drawing point({2, 2, 2, 2});
  EXPECT_GT(point.view().xmax, point.view().xmin);
  EXPECT_GT(point.view().ymax, point.view().ymin);
  const Drawing flat({0, 0, 100, 0});
  EXPECT_GT(flat.height_px(), 10);
}

TEST(SvgDrawing, HigherWorldPointsAreDrawnHigher) {
  const Drawing d({0, 0, 10, 10}, 800);
  const Point2 low = d.to_screen({5, 1});
  const Point2 high = d.to_screen({5, 9});
  EXPECT_LT(high.y, low.y);
  EXPECT_DOUBLE_EQ(high.x, low.x);
}

TEST(SvgDrawing, EmittedCoordinatesAreFlipped) {
  Drawing d({0, 0, 10, 10});
  Style s;
  s.fill = "#f00";
  d.points({{3, 9}}, 4, s);
  d.points({{3, 1}}, 4, s);
  const std::string svg = d.str();
  const std::regex cy_re("cy=\"([^\"]*)\"");
  std::vector<double> cys;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), cy_re); it != std::sregex_iterator(); ++it) {
    cys.push_back(std::stod((*it)[1]));
  }
  ASSERT_EQ(cys.size(), 2u) << svg;
  EXPECT_LT(cys[0], cys[1]);  // y = 9 is nearer the top of the picture than y = 1
  EXPECT_NEAR(cys[0], d.to_screen({3, 9}).y, 1e-4);
  EXPECT_LT(cys[0], 0.2 * d.height_px());
}

TEST(SvgDrawing, RadiiAndStrokesArePixelsAtAnyScale) {
  for (const double size : {1e-6, 1.0, 1000.0}) {
    Drawing d({0, 0, size, size}, 800);
    Style s;
    s.fill = "#0a0";
    s.stroke_px = 2;
    d.points({{size / 2, size / 2}}, 5, s);
    const std::string svg = d.str();
    EXPECT_EQ(attribute(svg, "circle", "r"), "5");
    EXPECT_EQ(attribute(svg, "g", "stroke-width"), "2");
  }
}

TEST(SvgDrawing, SmallWorldsAreNotRoundedFlat) {
  // A world 1e-6 wide, far from the origin: its points stay apart in the file.
  Drawing d({1000, 1000, 1000.000001, 1000.000001});
  Style s;
  d.polyline({{1000.0000001, 1000.0000002}, {1000.0000009, 1000.0000008}}, s);
  const std::string svg = d.str();
  const auto xy = numbers_in(std::regex_replace(attribute(svg, "path", "d"), std::regex("[ML]"), " "));
  ASSERT_EQ(xy.size(), 4u) << svg;
  const Point2 a = d.to_screen({1000.0000001, 1000.0000002});
  const Point2 b = d.to_screen({1000.0000009, 1000.0000008});
  EXPECT_NEAR(xy[0], a.x, 1e-3);
  EXPECT_NEAR(xy[1], a.y, 1e-3);
  EXPECT_NEAR(xy[2], b.x, 1e-3);
  EXPECT_NEAR(xy[3], b.y, 1e-3);
  EXPECT_GT(xy[2] - xy[0], 500);  // 0.8 of the world's width
}

TEST(SvgDrawing, TextIsEscaped) {
  Drawing d({0, 0, 1, 1});
  d.text({0.5, 0.5}, "a<b & c>\"d\" 'e'", 12);
  d.legend("x < y & z", Style{});
  const std::string svg = d.str();
  EXPECT_NE(svg.find("a&lt;b &amp; c&gt;&quot;d&quot; &apos;e&apos;"), std::string::npos) << svg;
  EXPECT_NE(svg.find("x &lt; y &amp; z"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_EQ(polyplan::svg::escape_xml(std::string("ok\x01")), "ok");
}

TEST(SvgDrawing, TextIsNotMirrored) {
  Drawing d({0, 0, 1, 1});
  d.text({0.5, 0.75}, "upright", 12);
  const std::string svg = d.str();
  // No transform at all anywhere: y is flipped by the coordinates, not by a mirroring matrix.
  EXPECT_EQ(svg.find("transform"), std::string::npos) << svg;
  EXPECT_NEAR(std::stod(attribute(svg, "text", "y")), d.to_screen({0.5, 0.75}).y, 1e-4);
  EXPECT_EQ(attribute(svg, "text", "font-size"), "12");
}

TEST(SvgDrawing, PolygonWithHoleIsOneEvenOddPath) {
  Drawing d({0, 0, 10, 10});
  Style s;
  s.fill = "#ccc";
  d.polygon({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 3}, {3, 6}, {6, 6}, {6, 3}}}, s);
  const std::string svg = d.str();
  EXPECT_EQ(count(svg, "<path"), 1u);
  EXPECT_EQ(attribute(svg, "path", "fill-rule"), "evenodd");
  EXPECT_EQ(count(attribute(svg, "path", "d"), "M"), 2u);
  EXPECT_EQ(count(attribute(svg, "path", "d"), "Z"), 2u);
}

TEST(SvgDrawing, SegmentsAreOnePath) {
  Drawing d({0, 0, 100, 100});
  std::vector<std::pair<Point2, Point2>> edges;
  for (int i = 0; i < 1000; ++i) edges.push_back({{double(i % 100), 0}, {double(i % 100), 100}});
  d.segments(edges, Style{});
  const std::string svg = d.str();
  EXPECT_EQ(count(svg, "<path"), 1u);
  EXPECT_EQ(count(attribute(svg, "path", "d"), "M"), 1000u);
}

TEST(SvgDrawing, LegendEntriesAppearInOrder) {
  Drawing d({0, 0, 1, 1});
  Style free;
  free.fill = "#e8f4ea";
  Style edge;
  edge.stroke = "#1f77b4";
  edge.dash = "4 3";
  d.legend("free space", free);
  d.legend("roadmap", edge);
  const std::string svg = d.str();
  const auto a = svg.find(">free space<");
  const auto b = svg.find(">roadmap<");
  ASSERT_NE(a, std::string::npos) << svg;
  ASSERT_NE(b, std::string::npos);
  EXPECT_LT(a, b);
  EXPECT_NE(svg.find("#e8f4ea"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray=\"4 3\""), std::string::npos);  // legend samples are in px
}

TEST(SvgDrawing, LegendAvoidsPointsOrMovesBelowThePicture) {
  Style dot;
  dot.fill = "#0a0";
  auto legend_box = [](const std::string& svg) {
    // The legend's box is the only rounded rectangle.
    const std::regex re("<rect x=\"([^\"]*)\" y=\"([^\"]*)\" width=\"([^\"]*)\" height=\"([^\"]*)\" rx=");
    std::smatch m;
    EXPECT_TRUE(std::regex_search(svg, m, re)) << svg;
    return Box2{std::stod(m[1]), std::stod(m[2]), std::stod(m[1]) + std::stod(m[3]), std::stod(m[2]) + std::stod(m[4])};
  };
  auto covers = [](const Box2& b, Point2 p) {
    return p.x >= b.xmin && p.x <= b.xmax && p.y >= b.ymin && p.y <= b.ymax;
  };
  {
    // A point in the top-left corner: the legend goes elsewhere, inside the picture.
    Drawing d({0, 0, 10, 10});
    d.points({{0, 10}}, 4, dot);
    d.legend("start", dot, polyplan::svg::Swatch::dot);
    const std::string svg = d.str();
    const Box2 box = legend_box(svg);
    EXPECT_FALSE(covers(box, d.to_screen({0, 10})));
    EXPECT_LE(box.ymax, d.height_px());
    EXPECT_NEAR(std::stod(attribute(svg, "svg", "height")), d.height_px(), 1e-4);
  }
  {
    // A point in every corner: the legend goes in a band below, the picture grows.
    Drawing d({0, 0, 10, 10});
    d.points({{0, 10}, {10, 10}, {0, 0}, {10, 0}}, 4, dot);
    d.legend("corners", dot, polyplan::svg::Swatch::dot);
    const std::string svg = d.str();
    const Box2 box = legend_box(svg);
    EXPECT_GE(box.ymin, d.height_px() - 1e-6);
    EXPECT_GT(std::stod(attribute(svg, "svg", "height")), box.ymax);
  }
}

TEST(SvgDrawing, NoLegendWithoutEntries) {
  const Drawing d({0, 0, 1, 1});
  EXPECT_EQ(d.str().find("<text"), std::string::npos);
}

TEST(SvgDrawing, WriteToAnUnwritablePathThrowsNamingIt) {
  const Drawing d({0, 0, 1, 1});
  const std::string path = "/nonexistent-polyplan-dir/sub/picture.svg";
  try {
    d.write(path);
    FAIL() << "write() did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(SvgDrawing, WriteProducesTheSameTextAsStr) {
  Drawing d({0, 0, 1, 1});
  d.text({0.5, 0.5}, "hello", 10);
  const std::string path = ::testing::TempDir() + "polyplan_svg_test.svg";
  d.write(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::string content;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) content.append(buffer, n);
  std::fclose(f);
  std::remove(path.c_str());
  EXPECT_EQ(content, d.str());
}

}  // namespace

TEST(SvgDrawing, GroupsHoldWhatIsDrawnInsideThemAfterTheirChildren) {
  Drawing d({0, 0, 10, 10});
  Style s;
  s.fill = "#0a0";
  d.begin_group("class=\"moving\" transform=\"rotate(30 5 5)\"", "<animate attributeName=\"opacity\"/>",
                Drawing::GroupContent::moves);
  d.points({{1, 1}}, 3, s);
  d.end_group();
  d.raw("<circle id=\"raw\" cx=\"1\" cy=\"2\" r=\"3\"/>");
  const std::string svg = d.str();
  const auto group =
      svg.find("<g class=\"moving\" transform=\"rotate(30 5 5)\">\n<animate attributeName=\"opacity\"/>\n");
  ASSERT_NE(group, std::string::npos) << svg;
  const auto circle = svg.find("<circle", group);
  const auto close = svg.find("</g>\n</g>\n", group);  // the points' own group, then ours
  const auto raw = svg.find("<circle id=\"raw\" cx=\"1\" cy=\"2\" r=\"3\"/>\n");
  ASSERT_NE(close, std::string::npos) << svg;
  EXPECT_LT(circle, close);
  EXPECT_GT(raw, close);
  EXPECT_EQ(count(svg, "<g"), count(svg, "</g>"));
  EXPECT_THROW(d.end_group(), std::logic_error);
}

TEST(SvgDrawing, OpenGroupsAreClosedBeforeTheLegend) {
  Drawing d({0, 0, 10, 10});
  d.begin_group("class=\"a\"");
  d.begin_group("class=\"b\"");
  d.polyline({{1, 1}, {2, 2}}, Style{});
  d.legend("line", Style{});
  const std::string svg = d.str();
  EXPECT_EQ(count(svg, "<g"), count(svg, "</g>")) << svg;
  // Both closed before the legend's group opens: the legend is never transformed with them.
  const auto legend = svg.find("<g font-size=");
  ASSERT_NE(legend, std::string::npos);
  EXPECT_EQ(svg.rfind("</g>\n</g>\n", legend) + 10, legend) << svg;
}

TEST(SvgDrawing, MovingGroupsDoNotPushTheLegendAway) {
  Style dot;
  dot.fill = "#0a0";
  auto legend_x = [](const Drawing& d) {
    const std::string svg = d.str();
    const auto at = svg.find("<g font-size=");
    return std::stod(attribute(svg.substr(at), "rect", "x"));
  };
  // A point in the top-left corner drawn in place pushes the legend out of that corner ...
  Drawing still({0, 0, 10, 10});
  still.begin_group("class=\"still\"");
  still.points({{0, 10}}, 4, dot);
  still.end_group();
  still.legend("dot", dot, polyplan::svg::Swatch::dot);
  EXPECT_GT(legend_x(still), still.width_px() / 2);
  // ... but not when it sits in a group that moves it elsewhere.
  Drawing moving({0, 0, 10, 10});
  moving.begin_group("transform=\"translate(400 400)\"", {}, Drawing::GroupContent::moves);
  moving.points({{0, 10}}, 4, dot);
  moving.end_group();
  moving.legend("dot", dot, polyplan::svg::Swatch::dot);
  EXPECT_LT(legend_x(moving), moving.width_px() / 2);
  // keep_clear marks where it moves to, drawing nothing.
  Drawing kept({0, 0, 10, 10});
  kept.begin_group("transform=\"translate(400 400)\"", {}, Drawing::GroupContent::moves);
  kept.points({{0, 10}}, 4, dot);
  kept.end_group();
  kept.keep_clear({{0, 10}, {1, 9}});
  kept.legend("dot", dot, polyplan::svg::Swatch::dot);
  EXPECT_GT(legend_x(kept), kept.width_px() / 2);
  EXPECT_EQ(count(kept.str(), "<path"), 0u);
}

TEST(SvgDrawing, BoxesAreOnePathOfRectangles) {
  Drawing d({0, 0, 10, 10});
  Style s;
  s.fill = "#ccc";
  d.boxes({{1, 2, 3, 5}, {6, 6, 7, 9}}, s);
  const std::string svg = d.str();
  EXPECT_EQ(count(svg, "<path"), 1u);
  const std::string path = attribute(svg, "path", "d");
  EXPECT_EQ(count(path, "M"), 2u);
  EXPECT_EQ(count(path, "Z"), 2u);
  // "M x0 y0 H x1 V y1 H x0 Z" in the pixel frame: the first box's corners.
  std::string first = path.substr(0, path.find('Z'));
  for (char& c : first)
    if (c == 'M' || c == 'H' || c == 'V') c = ' ';
  const auto xy = numbers_in(first);
  ASSERT_EQ(xy.size(), 5u) << path;
  const Point2 low = d.to_screen({1, 2}), high = d.to_screen({3, 5});
  EXPECT_NEAR(xy[0], low.x, 1e-4);
  EXPECT_NEAR(xy[1], low.y, 1e-4);
  EXPECT_NEAR(xy[2], high.x, 1e-4);
  EXPECT_NEAR(xy[3], high.y, 1e-4);
  EXPECT_NEAR(xy[4], low.x, 1e-4);
}

TEST(SvgDrawing, FormatNumberPrintsLikeCoordinates) {
  EXPECT_EQ(polyplan::svg::format_number(0.5), "0.5");
  EXPECT_EQ(polyplan::svg::format_number(-0.0), "0");
  EXPECT_EQ(polyplan::svg::format_number(1.0 / 3), "0.33333333");
  EXPECT_EQ(polyplan::svg::format_number(std::numeric_limits<double>::quiet_NaN()), "0");
}
