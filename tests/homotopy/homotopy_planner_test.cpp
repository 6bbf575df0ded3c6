// The K shortest homotopy classes round one square: pass above, pass below, then once round each
// way, with lengths computed here from the corners the taut paths bend round; every path exactly
// valid, its word recomputed from its polyline; the words distinct and the lengths increasing.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/homotopy/h_signature.hpp>
#include <polyplan/homotopy/homotopy_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace polyplan {
namespace {

World one_square() {
  World world;
  world.bounds = Bounds{-10, -10, 10, 10};
  world.obstacles.push_back({{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, {}});
  world.obstacle_names.push_back("obstacles[0]");
  world.queries.push_back({{-3, Rational(1, 2)}, {3, Rational(1, 2)}, "start/goal"});
  return world;
}

PlanReport<ExactPoint> classes(const CSpace& cspace, const Query& q, const std::string& k) {
  return planners<TranslatingRobot>().find("homotopy")->make(cspace, {{"classes", k}})->plan(q);
}

TEST(HomotopyPlanner, TheFirstFourClassesRoundOneSquare) {
  const World world = one_square();
  const CSpace cspace(world);
  const auto report = classes(cspace, world.queries[0], "4");
  ASSERT_TRUE(report.found) << report.why_not;
  ASSERT_EQ(report.paths.size(), 4u);
  // Above: to (−1, 1), along the top, down to the goal; below: the same round (±1, −1).
  const double above = 2 * std::sqrt(4 + 0.25) + 2, below = 2 * std::sqrt(4 + 2.25) + 2;
  EXPECT_NEAR(report.paths[0].length, above, 1e-12);
  EXPECT_NEAR(report.paths[1].length, below, 1e-12);
  // Once more round the square (perimeter 8) before leaving above, or below.
  EXPECT_NEAR(report.paths[2].length, above + 8, 1e-12);
  EXPECT_NEAR(report.paths[3].length, below + 8, 1e-12);
  EXPECT_EQ(report.path, report.paths[0].path);
  const HSignature h(cspace);
  std::set<std::string> words;
  for (std::size_t i = 0; i < report.paths.size(); ++i) {
    const auto& p = report.paths[i];
    EXPECT_TRUE(check_path(cspace, p.path).valid);
    EXPECT_EQ(word_text(h.polyline(p.path)), p.facts.at(HomotopyFacts::path_word));
    words.insert(p.facts.at(HomotopyFacts::path_word));
    if (i > 0) {  // braces: EXPECT_LT is an if-else of its own
      EXPECT_LT(report.paths[i - 1].length, p.length);
    }
  }
  EXPECT_EQ(words.size(), 4u);
  EXPECT_EQ(report.facts.at(HomotopyFacts::classes), 4);
}

TEST(HomotopyPlanner, FewerClassesWithinMaxLength) {
  const World world = one_square();
  const CSpace cspace(world);
  const auto report = planners<TranslatingRobot>()
                          .find("homotopy")
                          ->make(cspace, {{"classes", "4"}, {"max-length", "10"}})
                          ->plan(world.queries[0]);
  ASSERT_TRUE(report.found);
  EXPECT_EQ(report.paths.size(), 2u);
  const auto none =
      planners<TranslatingRobot>().find("homotopy")->make(cspace, {{"max-length", "5"}})->plan(world.queries[0]);
  EXPECT_EQ(none.status, PlanStatus::not_found);
}

// A thin diamond between (0, 0) and (1.02, 0): over its top apex the path is 0.85 + 0.85 = 1.7
// long, under its bottom apex longer or shorter by 1.6e-16 — the same double, 1.7000000000000002,
// both ways. The classes come in their exact order, and max-length = 1.7 admits the 1.7 exactly.
World diamond(const char* top, const char* bottom) {
  return test::world_from(std::string(R"({"bounds": [-0.5, -1, 1.5, 1], "obstacles": [[[0.51, )") + top +
                          "], [0.41, 0], [0.51, -" + bottom + R"(], [0.61, 0]]], "start": [0, 0], "goal": [1.02, 0]})");
}

TEST(HomotopyPlanner, ClassesWhoseLengthsDoublesTieComeInTheirExactOrder) {
  for (const bool top_shorter : {true, false}) {
    const World world = top_shorter ? diamond("0.68", "0.6800000000000001") : diamond("0.6800000000000001", "0.68");
    const CSpace cspace(world);
    const auto report = classes(cspace, world.queries[0], "2");
    ASSERT_EQ(report.paths.size(), 2u) << report.why_not;
    ASSERT_EQ(report.paths[0].path.size(), 3u);
    EXPECT_EQ(sgn(report.paths[0].path[1].y), top_shorter ? 1 : -1) << "the shorter class first";
    EXPECT_EQ(report.paths[0].length, report.paths[1].length) << "doubles tie";
  }
}

TEST(HomotopyPlanner, MaxLengthIsComparedExactly) {
  const World world = diamond("0.68", "0.6800000000000001");
  const CSpace cspace(world);
  const auto within = [&](const std::string& max) {
    return planners<TranslatingRobot>()
        .find("homotopy")
        ->make(cspace, {{"classes", "2"}, {"max-length", max}})
        ->plan(world.queries[0]);
  };
  EXPECT_EQ(within("1.7").paths.size(), 1u);
  EXPECT_EQ(within("1.700000000000001").paths.size(), 2u);
  const auto none = within("1.699999999999999");
  EXPECT_EQ(none.status, PlanStatus::not_found);
  EXPECT_NE(none.why_not.find("max-length (1.699999999999999)"), std::string::npos) << none.why_not;
}

}  // namespace
}  // namespace polyplan
