// Pictures of arms: the SMIL animation, the strobe and the two-joint C-space panel, checked on
// the SVG text itself (tags, keyframes, where the transforms put the arm, how the path is cut).
#include <polyplan/draw/arm_svg.hpp>

#include <polyplan/arm/arm.hpp>
#include <polyplan/geometry/angles.hpp>
#include "draw/svg_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using polyplan::CellGrid;
using polyplan::ArmPlanPicture;
using polyplan::ArmProblem;
using polyplan::JointAngles;
using polyplan::PlanGraph;
using polyplan::Rational;
using polyplan::test::attribute_at;
using polyplan::test::count;
using polyplan::test::legend_labels;
using polyplan::test::nesting_error;
using polyplan::test::numbers_in;

constexpr double kPi = std::numbers::pi;

// Every occurrence's start position of `needle`.
std::vector<std::size_t> positions(const std::string& text, const std::string& needle) {
  std::vector<std::size_t> out;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) out.push_back(pos);
  return out;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, separator)) out.push_back(item);
  return out;
}

// One rotation keyframe "angle cx cy" of an animateTransform.
struct Rotation {
  double degrees, cx, cy;
};

std::vector<std::vector<Rotation>> link_keyframes(const std::string& svg) {
  std::vector<std::vector<Rotation>> out;
  for (std::size_t pos : positions(svg, "<animateTransform")) {
    std::vector<Rotation> frames;
    for (const std::string& v : split(attribute_at(svg, pos, "values"), ';')) {
      const auto n = numbers_in(v);
      if (n.size() == 3) frames.push_back({n[0], n[1], n[2]});
    }
    out.push_back(frames);
  }
  return out;
}

struct Px {
  double x, y;
};

// SVG's rotate(a cx cy) in the picture's frame (y down): p' = c + R(a)·(p − c).
Px rotate(Px p, const Rotation& r) {
  const double a = r.degrees * kPi / 180, dx = p.x - r.cx, dy = p.y - r.cy;
  return {r.cx + std::cos(a) * dx - std::sin(a) * dy, r.cy + std::sin(a) * dx + std::cos(a) * dy};
}

ArmProblem problem_with_links(std::vector<double> links, double width) {
  ArmProblem p;
  p.source = "test arm";
  p.arm.links = std::move(links);
  p.arm.link_width = width;
  // A square obstacle with a square hole, right of the base, and two obstacle points.
  polyplan::PolygonWithHoles square;
  square.outer = {
      {Rational(4), Rational(-1)}, {Rational(6), Rational(-1)}, {Rational(6), Rational(1)}, {Rational(4), Rational(1)}};
  square.holes = {{{Rational(9, 2), Rational(-1, 2)},
                   {Rational(9, 2), Rational(1, 2)},
                   {Rational(11, 2), Rational(1, 2)},
                   {Rational(11, 2), Rational(-1, 2)}}};
  p.obstacles = {square};
  p.obstacle_names = {"obstacles[0]"};
  p.points = {{-2.5, 1.0}, {0.5, 3.0}};
  return p;
}

// `steps` + 1 configurations from `a` to `b`, every joint the short way round, angles in [0, 2π)
// as the planners return them.
std::vector<JointAngles> sweep(const JointAngles& a, const JointAngles& b, int steps) {
  std::vector<JointAngles> out;
  for (int i = 0; i <= steps; ++i) out.push_back(polyplan::interpolate_angles(a, b, steps > 0 ? double(i) / steps : 0));
  return out;
}

ArmPlanPicture picture_of(const ArmProblem& problem, std::vector<JointAngles> motion,
                          std::optional<CellGrid> cspace = std::nullopt) {
  ArmPlanPicture picture;
  picture.problem = &problem;
  picture.motion = std::move(motion);
  picture.cspace = std::move(cspace);
  return picture;
}

CellGrid uniform_image(std::size_t n, std::uint8_t state) {
  CellGrid image;
  image.columns = image.rows = n;
  image.states.assign(n * n, state);
  return image;
}

// ---------------------------------------------------------------------------------------------

TEST(ArmAnimationSvg, IsWellFormedAndRepeatsForEver) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  ArmPlanPicture picture = picture_of(problem, sweep({0.3, 1.0}, {2.5, -1.0}, 40), uniform_image(36, CellGrid::free));
  picture.title = "test";
  const std::string svg = polyplan::arm_animation_svg(picture);
  EXPECT_EQ(nesting_error(svg), "") << svg;
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  // Two links, each its own rotating group, and the C-space dot's two coordinates.
  EXPECT_EQ(count(svg, "<animateTransform"), 2u);
  EXPECT_EQ(count(svg, "<animate attributeName=\"c"), 2u);
  EXPECT_EQ(count(svg, "<animate"), count(svg, "repeatCount=\"indefinite\""));
  EXPECT_EQ(count(svg, "class=\"arm-link\""), 2u);
  EXPECT_EQ(count(svg, "class=\"cspace-dot\""), 1u);
  EXPECT_NE(svg.find(">test</text>"), std::string::npos);
  EXPECT_NE(svg.find("(a torus: opposite edges meet)</text>"), std::string::npos);
  picture.torus = false;
  EXPECT_NE(polyplan::arm_animation_svg(picture).find("(intervals [0, 2π))</text>"), std::string::npos);
}

TEST(ArmAnimationSvg, KeyframesFollowTheMotionSubsampledWithRestsAtBothEnds) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0);
  for (const auto& [configurations, expected] : {std::pair{50, 50}, std::pair{5000, 600}}) {
    ArmPlanPicture picture = picture_of(problem, sweep({0, 0}, {3, 1}, configurations - 1));
    const std::string svg = polyplan::arm_animation_svg(picture);
    for (std::size_t pos : positions(svg, "<animateTransform")) {
      const auto values = split(attribute_at(svg, pos, "values"), ';');
      const auto times = numbers_in(attribute_at(svg, pos, "keyTimes"));
      // The kept configurations, the first and the last once more for the rests.
      EXPECT_EQ(values.size(), std::size_t(expected) + 2) << configurations;
      ASSERT_EQ(times.size(), values.size());
      EXPECT_EQ(times.front(), 0);
      EXPECT_EQ(times.back(), 1);
      for (std::size_t i = 1; i < times.size(); ++i) EXPECT_LE(times[i - 1], times[i]);
      // Rests: 0.5 s of a period of 0.5 + 4 + 1 s (4 rad of joint turns at 1 s per radian).
      EXPECT_EQ(attribute_at(svg, pos, "dur"), "5.5s");
      EXPECT_NEAR(times[1], 0.5 / 5.5, 1e-7);
      EXPECT_NEAR(times[times.size() - 2], 4.5 / 5.5, 1e-7);
    }
  }
}

TEST(ArmAnimationSvg, RotationsAreUnwrappedAcrossTwoPi) {
  // θ1 goes 5.9 → 0.4 through 2π (0.7832 rad counter-clockwise), θ2 0.2 → 6.0 through 0 (0.4832 rad
  // clockwise): the wrapped values jump by almost 2π, the keyframes must not.
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const auto motion = sweep({5.9, 0.2}, {0.4, 6.0}, 30);
  ASSERT_GT(motion[0][0], 5);
  ASSERT_LT(motion.back()[0], 1);
  const ArmPlanPicture picture = picture_of(problem, motion);
  const auto links = link_keyframes(polyplan::arm_animation_svg(picture));
  ASSERT_EQ(links.size(), 2u);
  for (const auto& frames : links) {
    ASSERT_EQ(frames.size(), motion.size() + 2);
    for (std::size_t i = 1; i < frames.size(); ++i) EXPECT_LE(std::abs(frames[i].degrees - frames[i - 1].degrees), 180);
  }
  // Counter-clockwise in the world is a negative SVG rotation (the picture's y axis points down).
  const double deg = 180 / kPi;
  EXPECT_NEAR(links[0].back().degrees - links[0].front().degrees, -(0.4 + 2 * kPi - 5.9) * deg, 1e-4);
  EXPECT_NEAR(links[1].back().degrees - links[1].front().degrees, (0.2 + 2 * kPi - 6.0) * deg, 1e-4);
}

TEST(ArmAnimationSvg, NestedRotationsPutTheEndEffectorWhereKinematicsSays) {
  // Three links: apply each keyframe's nested rotations to the end-effector dot (drawn at the
  // zero configuration) and compare with forward kinematics mapped into the picture.
  const ArmProblem problem = problem_with_links({2.0, 1.5, 1.0}, 0.15);
  const JointAngles start{0.5, -0.3, 2.0}, goal{2.8, 1.2, -1.0};
  const ArmPlanPicture picture = picture_of(problem, sweep(start, goal, 20));
  const std::string svg = polyplan::arm_animation_svg(picture);
  const auto links = link_keyframes(svg);
  ASSERT_EQ(links.size(), 3u);
  // The picture's frame from the rotation centres: the base, and joint 1 at (2, 0) when all angles are 0.
  const Px base{links[0][0].cx, links[0][0].cy};
  const double scale = (links[1][0].cx - base.x) / 2.0;
  ASSERT_GT(scale, 0);
  EXPECT_NEAR(links[1][0].cy, base.y, 1e-6);
  EXPECT_NEAR(links[2][0].cx, base.x + 3.5 * scale, 1e-4);
  // The end effector's dot is the last circle of the innermost group, at (4.5, 0) unrotated.
  const std::size_t innermost = positions(svg, "class=\"arm-link\"").back();
  const std::size_t tip_at = svg.rfind("<circle", svg.find("r=\"3.5\"", innermost));
  const Px tip{std::stod(attribute_at(svg, tip_at, "cx")), std::stod(attribute_at(svg, tip_at, "cy"))};
  EXPECT_NEAR(tip.x, base.x + 4.5 * scale, 1e-4);
  EXPECT_NEAR(tip.y, base.y, 1e-4);

  for (const auto& [frame, q] : {std::pair{std::size_t(0), start}, std::pair{links[0].size() - 1, goal}}) {
    Px p = tip;
    for (std::size_t j = links.size(); j-- > 0;) p = rotate(p, links[j][frame]);
    const Eigen::Vector2d expected = polyplan::joint_positions(problem.arm, q).back();
    EXPECT_NEAR(p.x, base.x + expected.x() * scale, 1e-3) << frame;
    EXPECT_NEAR(p.y, base.y - expected.y() * scale, 1e-3) << frame;
  }
  // Without animation (rsvg-convert) the groups' own transforms show the start.
  const auto first_group = positions(svg, "class=\"arm-link\"");
  for (std::size_t j = 0; j < 3; ++j) {
    const auto n = numbers_in(attribute_at(svg, first_group[j], "transform").substr(6));
    ASSERT_EQ(n.size(), 3u);
    EXPECT_NEAR(std::remainder(n[0] + start[j] * 180 / kPi, 360), 0, 1e-5);  // −0.3 may show as 2π − 0.3
  }
}

TEST(ArmAnimationSvg, CSpacePathIsCutWhereItCrossesASeam) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  auto path_pieces = [&](const std::vector<JointAngles>& motion) {
    const ArmPlanPicture picture = picture_of(problem, motion, uniform_image(72, CellGrid::free));
    const std::string svg = polyplan::arm_animation_svg(picture);
    const auto group = svg.find("<g class=\"cspace-path\">");
    EXPECT_NE(group, std::string::npos);
    std::vector<std::vector<double>> pieces;
    for (auto pos = svg.find("<path", group); pos < svg.find("</g>", group); pos = svg.find("<path", pos + 1)) {
      pieces.push_back(numbers_in(attribute_at(svg, pos, "d")));
    }
    return pieces;
  };
  // θ2 from 6.2 up through 2π to 0.1, θ1 fixed: leaves at the top edge, comes back at the bottom.
  const auto crossing = path_pieces(sweep({1.0, 6.2}, {1.0, 0.1}, 20));
  ASSERT_EQ(crossing.size(), 2u);
  const auto& a = crossing[0];
  const auto& b = crossing[1];
  const double top = a[a.size() - 1], bottom = b[1];
  EXPECT_GT(bottom - top, 400);              // the whole panel lies between the two ends (520 px)
  EXPECT_NEAR(a[a.size() - 2], b[0], 1e-6);  // at the same θ1
  for (std::size_t i = 1; i < a.size(); i += 2) EXPECT_GE(a[i], top - 1e-9);
  for (std::size_t i = 1; i < b.size(); i += 2) EXPECT_LE(b[i], bottom + 1e-9);
  // The path starts (2π − 6.2)/2π of the panel's height below its top edge.
  EXPECT_NEAR((a[1] - top) / (bottom - top), (2 * kPi - 6.2) / (2 * kPi), 1e-6);
  // The same motion the other way round is cut the same; one that stays inside is not cut.
  EXPECT_EQ(path_pieces(sweep({1.0, 0.1}, {1.0, 6.2}, 20)).size(), 2u);
  EXPECT_EQ(path_pieces(sweep({1.0, 0.3}, {2.0, 6.0}, 20)).size(), 2u);  // θ2 0.3 → 6.0 through 0
  EXPECT_EQ(path_pieces(sweep({1.0, 1.0}, {2.0, 3.0}, 20)).size(), 1u);
  // Both joints across their seams: three pieces.
  EXPECT_EQ(path_pieces(sweep({6.1, 6.0}, {0.5, 0.2}, 20)).size(), 3u);
}

TEST(ArmAnimationSvg, CSpaceDotJumpsAcrossTheSeamInStepWithTheArm) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const auto motion = sweep({1.0, 6.2}, {1.0, 0.1}, 20);
  const ArmPlanPicture picture = picture_of(problem, motion, uniform_image(72, CellGrid::free));
  const std::string svg = polyplan::arm_animation_svg(picture);
  const auto dot = svg.find("class=\"cspace-dot\"");
  ASSERT_NE(dot, std::string::npos);
  const auto cy_at = svg.find("attributeName=\"cy\"", dot);
  const auto ys = numbers_in(attribute_at(svg, cy_at, "values"));
  const auto times = numbers_in(attribute_at(svg, cy_at, "keyTimes"));
  const auto arm_times = numbers_in(attribute_at(svg, svg.find("<animateTransform"), "keyTimes"));
  // The arm's keyframes plus two at the seam: leaving at the top and entering at the bottom at
  // the same moment.
  ASSERT_EQ(ys.size(), motion.size() + 2 + 2);
  ASSERT_EQ(times.size(), ys.size());
  EXPECT_EQ(attribute_at(svg, cy_at, "dur"), attribute_at(svg, svg.find("<animateTransform"), "dur"));
  std::size_t jumps = 0;
  for (std::size_t i = 1; i < ys.size(); ++i) {
    EXPECT_LE(times[i - 1], times[i]);
    if (std::abs(ys[i] - ys[i - 1]) > 100) {
      ++jumps;
      EXPECT_EQ(times[i], times[i - 1]);
    }
  }
  EXPECT_EQ(jumps, 1u);
  // Apart from the two seam frames, the dot's times are the arm's.
  std::vector<double> without_seam;
  for (double t : times)
    if (std::find(arm_times.begin(), arm_times.end(), t) != arm_times.end()) without_seam.push_back(t);
  EXPECT_EQ(without_seam.size(), arm_times.size());
}

TEST(ArmAnimationSvg, CellsAreMergedIntoRunsOfEqualState) {
  // 36 × 36 cells, θ1 cells 10..19 blocked, 0..4 of row 0 not evaluated, the rest free. Cell 0
  // straddles the seam (half at each edge), so a row's runs over the extended index 0..36 are
  // free 0–9, blocked 10–19, free 20–36; row 0 shows at the bottom and at the top (37 rows) with
  // runs unknown 0–4, free 5–9, blocked 10–19, free 20–35, unknown 36. Equal runs in consecutive
  // rows are one rectangle: blocked 10–19 once for all rows; rows 1..35 two free ones; the two
  // halves of row 0 four each.
  const std::size_t n = 36;
  CellGrid image = uniform_image(n, CellGrid::free);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 10; i < 20; ++i) image.states[i + j * n] = CellGrid::blocked;
  for (std::size_t i = 0; i < 5; ++i) image.states[i] = CellGrid::not_evaluated;
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const ArmPlanPicture picture = picture_of(problem, sweep({0, 0}, {1, 1}, 5), image);
  const std::string svg = polyplan::arm_animation_svg(picture);
  const auto group = svg.find("<g class=\"cspace-cells\">");
  const auto group_end = svg.find("</g>", group);
  ASSERT_NE(group, std::string::npos);
  std::size_t rects = 0;
  std::vector<double> area;  // per path: free, blocked, not evaluated
  for (auto pos = svg.find("<path", group); pos < group_end; pos = svg.find("<path", pos + 1)) {
    const std::string d = attribute_at(svg, pos, "d");
    rects += count(d, "M");
    double total = 0;
    for (const std::string& ring : split(d, 'Z')) {
      const auto xy = numbers_in(ring);  // "M x0 y0 H x1 V y1 H x0 Z"
      if (xy.size() != 5) continue;
      total += std::abs(xy[2] - xy[0]) * std::abs(xy[3] - xy[1]);
    }
    area.push_back(total);
  }
  EXPECT_LT(rects, n * n);
  EXPECT_EQ(rects, 1u + 2 + 2 * 4);
  ASSERT_EQ(area.size(), 3u);
  const double whole = area[0] + area[1] + area[2];
  EXPECT_NEAR(whole, 520.0 * 520.0, 1e-2);
  // Coordinates are printed to 8 significant digits: 1e-5 px on a 520 px panel.
  EXPECT_NEAR(area[1] / whole, 10.0 / 36, 1e-6);
  EXPECT_NEAR(area[2] / whole, 5.0 / (36 * 36), 1e-6);
  EXPECT_NE(svg.find("not evaluated configurations (5 cells)"), std::string::npos);
  EXPECT_NE(svg.find("blocked configurations (360 cells)"), std::string::npos);
}

TEST(ArmAnimationSvg, WithoutAMotionShowsTheWorldAndSaysSo) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const ArmPlanPicture picture = picture_of(problem, {}, uniform_image(8, CellGrid::blocked));
  const std::string svg = polyplan::arm_animation_svg(picture);
  EXPECT_EQ(nesting_error(svg), "");
  EXPECT_EQ(svg.find("<animate"), std::string::npos);
  EXPECT_NE(svg.find("no path</text>"), std::string::npos);
}

TEST(ArmAnimationSvg, InconsistentPicturesAreRefused) {
  const ArmProblem two = problem_with_links({2.0, 1.5}, 0.2);
  const ArmProblem three = problem_with_links({2.0, 1.5, 1.0}, 0.2);
  EXPECT_THROW(polyplan::arm_animation_svg(ArmPlanPicture{}), std::invalid_argument);
  // A configuration with the wrong number of joints.
  EXPECT_THROW(polyplan::arm_animation_svg(picture_of(two, {{0, 0}, {1, 1, 1}})), std::invalid_argument);
  // A C-space picture of an arm that has not two joints, or whose states are not n·n or not states.
  EXPECT_THROW(polyplan::arm_animation_svg(picture_of(three, {{0, 0, 0}}, uniform_image(4, CellGrid::free))),
               std::invalid_argument);
  CellGrid short_image = uniform_image(4, CellGrid::free);
  short_image.states.pop_back();
  EXPECT_THROW(polyplan::arm_animation_svg(picture_of(two, {{0, 0}}, short_image)), std::invalid_argument);
  CellGrid odd_image = uniform_image(4, CellGrid::free);
  odd_image.states[3] = 7;
  EXPECT_THROW(polyplan::arm_animation_svg(picture_of(two, {{0, 0}}, odd_image)), std::invalid_argument);
  EXPECT_THROW(polyplan::arm_strobe_svg(picture_of(two, {{0, 0}}), 0), std::invalid_argument);
}

TEST(ArmAnimationSvg, WriteToAnUnwritablePathThrowsNamingIt) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const ArmPlanPicture picture = picture_of(problem, sweep({0, 0}, {1, 1}, 5));
  const std::string path = "/nonexistent-polyplan-dir/arm.svg";
  for (int strobe = 0; strobe < 2; ++strobe) {
    try {
      if (strobe) {
        polyplan::write_arm_strobe_svg(path, picture, 2);
      } else {
        polyplan::write_arm_animation_svg(path, picture);
      }
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

TEST(ArmStrobeSvg, DrawsEveryKthConfigurationAndTheGoal) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  // (configurations, k, copies): ⌈N/k⌉ configurations 0, k, 2k, …, and the goal when N − 1 is
  // not among them.
  const struct {
    int configurations;
    std::size_t k, copies;
  } cases[] = {{23, 5, 6}, {21, 5, 5}, {10, 1, 10}, {10, 100, 2}, {1, 3, 1}};
  for (const auto& c : cases) {
    const ArmPlanPicture picture = picture_of(problem, sweep({0.2, 0.4}, {2.0, -1.0}, c.configurations - 1));
    ASSERT_EQ(picture.motion.size(), std::size_t(c.configurations));
    const std::string svg = polyplan::arm_strobe_svg(picture, c.k);
    EXPECT_EQ(nesting_error(svg), "");
    EXPECT_EQ(count(svg, "<g class=\"strobe-configuration"), c.copies) << c.configurations << " / " << c.k;
    EXPECT_EQ(svg.find("<animate"), std::string::npos);
  }
}

TEST(ArmStrobeSvg, ColoursRampFromBlueAtTheStartToRedAtTheGoal) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  const ArmPlanPicture picture = picture_of(problem, sweep({0.2, 0.4}, {2.0, -1.0}, 20));
  const std::string svg = polyplan::arm_strobe_svg(picture, 5);
  const auto fill_of = [&](const std::string& group) {
    return attribute_at(svg, svg.find("<path", svg.find(group)), "fill");
  };
  EXPECT_EQ(fill_of("strobe-start"), "#1f77b4");
  EXPECT_EQ(fill_of("strobe-goal"), "#d62728");
  // Configurations 5, 10, 15 of 20: a quarter, half and three quarters of the way to red.
  const auto groups = positions(svg, "<g class=\"strobe-configuration\"");
  ASSERT_EQ(groups.size(), 3u);
  std::vector<int> reds;
  for (std::size_t g : groups)
    reds.push_back(std::stoi(attribute_at(svg, svg.find("<path", g), "fill").substr(1, 2), nullptr, 16));
  // 0x1f + 183·t, rounded: 76.75, 122.5, 168.25.
  EXPECT_EQ(reds, (std::vector<int>{77, 123, 168}));
  EXPECT_NE(svg.find("every 5th configuration (3 of 21)"), std::string::npos) << svg;
}

// ---------------------------------------------------------------------------------------------
// A planner's graph (report.recording.graph) under the path

std::shared_ptr<const PlanGraph<JointAngles>> graph_of(std::vector<JointAngles> vertices,
                                                       std::vector<std::pair<std::size_t, std::size_t>> edges) {
  auto graph = std::make_shared<PlanGraph<JointAngles>>();
  graph->kind = "tree";
  graph->vertices = std::move(vertices);
  graph->edges = std::move(edges);
  return graph;
}

// The sub-paths ("M x y L x y ...") of the first <path> of the group whose start tag has `class_name`.
std::vector<std::vector<double>> subpaths_in_group(const std::string& svg, const std::string& class_name) {
  std::vector<std::vector<double>> out;
  const auto group = svg.find("<g class=\"" + class_name + "\">");
  if (group == std::string::npos) return out;
  const auto path = svg.find("<path", group);
  if (path > svg.find("</g>", group)) return out;
  for (const std::string& piece : split(attribute_at(svg, path, "d"), 'M'))
    if (!piece.empty()) out.push_back(numbers_in(piece));
  return out;
}

bool has_label(const std::string& svg, const std::string& label) {
  const auto labels = legend_labels(svg);
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

TEST(ArmGraphSvg, TwoJointGraphIsDrawnOnThePanelCutAtTheSeamAndInTheWorkspace) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  // θ2 from 5.9 up through 2π to 0.3 (vertex 1 given as 0.3 − 2π: any finite angle), and two
  // edges to (2, 3) that stay inside the square. In this order no edge begins where the one
  // before ended, so each piece is one move-to.
  ArmPlanPicture picture = picture_of(problem, sweep({1.0, 5.9}, {2.0, 3.0}, 20), uniform_image(72, CellGrid::free));
  picture.graph = graph_of({{1.0, 5.9}, {1.0, 0.3 - 2 * kPi}, {2.0, 3.0}}, {{0, 1}, {0, 2}, {1, 2}});
  for (int strobe = 0; strobe < 2; ++strobe) {
    const std::string svg = strobe ? polyplan::arm_strobe_svg(picture, 5) : polyplan::arm_animation_svg(picture);
    EXPECT_EQ(nesting_error(svg), "");
    EXPECT_TRUE(has_label(svg, "tree edges (3) in C-space")) << strobe;
    EXPECT_TRUE(has_label(svg, "tree edges (3): end-effector traces")) << strobe;
    EXPECT_TRUE(has_label(svg, "tree vertices (3)")) << strobe;

    // The seam-crossing edge is two pieces, the others one each; no piece runs across the panel.
    const auto pieces = subpaths_in_group(svg, "cspace-graph");
    ASSERT_EQ(pieces.size(), 4u) << strobe;
    for (const auto& piece : pieces) {
      ASSERT_EQ(piece.size(), 4u);                    // a straight line: two points
      EXPECT_LT(std::abs(piece[3] - piece[1]), 260);  // half the 520 px panel
    }
    // The first edge: from θ2 = 5.9 up to the top edge, then from the bottom edge up to θ2 = 0.3, at θ1 = 1.
    const double top = pieces[0][3], bottom = pieces[1][1];
    EXPECT_NEAR(bottom - top, 520, 1e-3);
    EXPECT_NEAR(pieces[0][0], pieces[1][0], 1e-6);
    EXPECT_NEAR((pieces[0][1] - top) / 520, (2 * kPi - 5.9) / (2 * kPi), 1e-6);
    EXPECT_NEAR((bottom - pieces[1][3]) / 520, 0.3 / (2 * kPi), 1e-6);
    // Vertex 1's dot where 0.3 is, on the second piece's end.
    const auto group = svg.find("<g class=\"cspace-graph\">");
    const auto dot = positions(svg.substr(group, svg.find("</g>\n</g>", group) - group), "<circle");
    ASSERT_EQ(dot.size(), 3u);
    EXPECT_NEAR(std::stod(attribute_at(svg, group + dot[1], "cy")), pieces[1][3], 1e-4);

    // Under the path, on the panel and in the workspace.
    EXPECT_LT(group, svg.find("<g class=\"cspace-path\">"));
    const auto workspace = svg.find("<g class=\"workspace-graph\">");
    ASSERT_NE(workspace, std::string::npos);
    EXPECT_LT(workspace, svg.find("stroke-dasharray=\"2 3\""));  // the end-effector path
    EXPECT_EQ(subpaths_in_group(svg, "workspace-graph").size(), 3u);
  }
}

TEST(ArmGraphSvg, WithoutAGraphThePictureHasNoneOfIt) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  ArmPlanPicture picture = picture_of(problem, sweep({1.0, 5.9}, {2.0, 3.0}, 20), uniform_image(72, CellGrid::free));
  const std::string animation = polyplan::arm_animation_svg(picture);
  const std::string strobe = polyplan::arm_strobe_svg(picture, 5);
  for (const std::string& svg : {animation, strobe}) {
    EXPECT_EQ(svg.find("-graph\""), std::string::npos);
    EXPECT_EQ(svg.find("tree "), std::string::npos);
    EXPECT_EQ(svg.find("#2a7ab0"), std::string::npos);  // theme::roadmap
  }
  // A graph with nothing in it draws nothing.
  picture.graph = graph_of({}, {});
  EXPECT_EQ(polyplan::arm_animation_svg(picture), animation);
  EXPECT_EQ(polyplan::arm_strobe_svg(picture, 5), strobe);
}

TEST(ArmGraphSvg, ThreeJointWorkspaceShowsEachEdgesEndEffectorTrace) {
  const ArmProblem problem = problem_with_links({2.0, 1.5, 1.0}, 0.15);
  ArmPlanPicture picture = picture_of(problem, sweep({0.5, -0.3, 2.0}, {2.8, 1.2, -1.0}, 20));
  // Edge (0, 1) turns joint 1 alone by 1.5 rad: the tip runs along the reach circle, a point every
  // 5° (⌈85.9° / 5°⌉ = 18 steps). Edge (2, 0) turns joints 2 and 3 by 1 rad: ⌈57.3° / 5°⌉ = 12 steps.
  picture.graph = graph_of({{0, 0, 0}, {1.5, 0, 0}, {0, 1, -1}}, {{0, 1}, {2, 0}});
  for (int strobe = 0; strobe < 2; ++strobe) {
    const std::string svg = strobe ? polyplan::arm_strobe_svg(picture, 5) : polyplan::arm_animation_svg(picture);
    EXPECT_EQ(nesting_error(svg), "");
    EXPECT_TRUE(has_label(svg, "tree edges (2): end-effector traces"));
    EXPECT_TRUE(has_label(svg, "tree vertices (3)"));
    EXPECT_EQ(svg.find("cspace-graph"), std::string::npos);  // no panel for three joints
    const auto traces = subpaths_in_group(svg, "workspace-graph");
    ASSERT_EQ(traces.size(), 2u);
    EXPECT_EQ(traces[0].size(), 2u * 19);
    EXPECT_EQ(traces[1].size(), 2u * 13);
    // The base is the circle of radius 5.5; the first trace keeps the reach (4.5) from it.
    const auto base = svg.rfind("<circle", svg.find("r=\"5.5\""));
    const double bx = std::stod(attribute_at(svg, base, "cx")), by = std::stod(attribute_at(svg, base, "cy"));
    const double reach = traces[0][0] - bx;  // the zero configuration: straight along +x
    EXPECT_GT(reach, 100);
    for (std::size_t i = 0; i < traces[0].size(); i += 2)
      EXPECT_NEAR(std::hypot(traces[0][i] - bx, traces[0][i + 1] - by), reach, 1e-3);
    EXPECT_NEAR(traces[0][traces[0].size() - 2], bx + reach * std::cos(1.5), 1e-3);  // y up: screen y down
    EXPECT_NEAR(traces[0].back(), by - reach * std::sin(1.5), 1e-3);
    EXPECT_EQ(polyplan::test::dots_in_group(svg, "class=\"workspace-graph\""), 3u);
  }
}

TEST(ArmGraphSvg, ManyEdgesAreCappedAndTheLegendSaysHowMany) {
  const ArmProblem problem = problem_with_links({2.0, 1.5, 1.0}, 0.15);
  ArmPlanPicture picture = picture_of(problem, sweep({0.5, -0.3, 2.0}, {2.8, 1.2, -1.0}, 20));
  // 4000 vertices, 5000 half-turn edges: at 5° that would be 37 points each.
  std::vector<JointAngles> vertices;
  for (int i = 0; i < 4000; ++i) vertices.push_back({0.001 * i, kPi * (i % 2), 0.5});
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (std::size_t i = 0; i < 5000; ++i) edges.push_back({i % 4000, (i + 1) % 4000});
  picture.graph = graph_of(std::move(vertices), std::move(edges));
  const std::string svg = polyplan::arm_animation_svg(picture);
  EXPECT_TRUE(has_label(svg, "tree edges (3000 of 5000): end-effector traces"));
  EXPECT_TRUE(has_label(svg, "tree vertices (3000 of 4000)"));
  const auto traces = subpaths_in_group(svg, "workspace-graph");
  std::size_t points = 0;
  for (const auto& trace : traces) points += trace.size() / 2;
  EXPECT_LE(traces.size(), 3000u);  // consecutive edges may chain
  EXPECT_GT(points, 3000u * 10);
  EXPECT_LE(points, 40000u);
  EXPECT_EQ(polyplan::test::dots_in_group(svg, "class=\"workspace-graph\""), 3000u);
  EXPECT_LT(svg.size(), 2'000'000u);
}

TEST(ArmGraphSvg, InconsistentGraphsAreRefused) {
  const ArmProblem problem = problem_with_links({2.0, 1.5}, 0.2);
  ArmPlanPicture picture = picture_of(problem, sweep({0, 0}, {1, 1}, 5));
  picture.graph = graph_of({{0, 0}, {1, 1}}, {{0, 2}});  // no vertex 2
  EXPECT_THROW(polyplan::arm_animation_svg(picture), std::invalid_argument);
  picture.graph = graph_of({{0, 0}, {1, 1, 1}}, {{0, 1}});  // three angles
  EXPECT_THROW(polyplan::arm_strobe_svg(picture, 2), std::invalid_argument);
  picture.graph = graph_of({{0, 0}, {1, std::nan("")}}, {{0, 1}});
  EXPECT_THROW(polyplan::arm_animation_svg(picture), std::invalid_argument);
}

TEST(ArmGraphSvg, DrawPlanDrawsTheReportsGraphOnACheckedCSpace) {
  // A sampling planner's report: a path and a tree, no cells. Two joints get a C-space panel
  // checked cell by cell (the obstacle points block some configurations); three joints none.
  const ArmProblem two = problem_with_links({2.0, 1.5}, 0.2);
  polyplan::PlanReport<JointAngles> report;
  report.found = true;
  report.path = {{0.3, 1.0}, {1.0, 0.5}, {2.5, 6.0}};
  using Kind = polyplan::ArmPictureOptions::Kind;
  const std::string without = polyplan::draw_plan(two, report, {Kind::animation, "t"}).str();
  EXPECT_EQ(without.find("C-space"), std::string::npos);
  report.recording.graph = graph_of(report.path, {{0, 1}, {1, 2}});
  for (const Kind kind : {Kind::animation, Kind::strobe}) {
    const std::string svg = polyplan::draw_plan(two, report, {kind, "t"}).str();
    EXPECT_EQ(nesting_error(svg), "");
    EXPECT_NE(svg.find("<g class=\"cspace-graph\">"), std::string::npos);
    EXPECT_NE(svg.find("<g class=\"workspace-graph\">"), std::string::npos);
    EXPECT_TRUE(has_label(svg, "tree edges (2) in C-space"));
    const auto labels = legend_labels(svg);
    EXPECT_TRUE(std::any_of(labels.begin(), labels.end(),
                            [](const std::string& label) { return label.starts_with("blocked configurations ("); }));
  }
  const ArmProblem three = problem_with_links({2.0, 1.5, 1.0}, 0.15);
  report.path = {{0.3, 1.0, 0.0}, {1.0, 0.5, 0.2}};
  report.recording.graph = graph_of(report.path, {{0, 1}});
  const std::string svg = polyplan::draw_plan(three, report, {Kind::strobe, "t"}).str();
  EXPECT_EQ(svg.find("C-space"), std::string::npos);
  EXPECT_TRUE(has_label(svg, "tree edges (1): end-effector traces"));
}

}  // namespace
