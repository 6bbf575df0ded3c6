// The tethered robot of the course's sampling-planner homework in tether_pillar.json (a pillar [3, 9] × [−4, 6], the
// base at (0, 0)): from behind the pillar with its tether round the bottom (16 long), to a goal above the pillar, it
// goes straight up the near side when L allows the 24.6 that winds the tether round two sides, and unwinds back under
// the pillar when L = 20 does not; the class of length exactly 16 is allowed at L = 16 and not at 15.99; L below the
// start's tether is no_path. Every path is re-checked exactly and its word recomputed from the polylines.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/homotopy/h_signature.hpp>
#include <polyplan/homotopy/homotopy_facts.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/fact_points.hpp>
#include <polyplan/registry/registry.hpp>

#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

World pillar() { return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/tether_pillar.json"); }

PlanReport<ExactPoint> tethered(const CSpace& cspace, const Query& q, const std::string& length) {
  return planners<TranslatingRobot>()
      .find("tether")
      ->make(cspace, {{"tether-base", "0,0"}, {"tether-length", length}, {"list-classes", "true"}})
      ->plan(q, QueryOptions{true});  // recorded: the marks hold the taut tethers exactly
}

// The tether at the goal exactly: the last of the taut tethers the picture marks.
std::vector<ExactPoint> tether_at_goal(const PlanReport<ExactPoint>& report) {
  for (const auto& mark : report.recording.marks)
    if (mark.legend == "taut tether at the path's corners" && !mark.parts.empty()) return mark.parts.back();
  ADD_FAILURE() << "no taut tether marked";
  return {};
}

// The tether at the goal is the taut tether of the robot's class: its word is the word of the
// start's tether followed by the robot's path, and its length the fact's.
void expect_consistent_tether(const CSpace& cspace, const PlanReport<ExactPoint>& report,
                              const std::vector<ExactPoint>& start_tether) {
  const HSignature h(cspace);
  const auto at_goal = tether_at_goal(report);
  ASSERT_GE(at_goal.size(), 2u);
  EXPECT_EQ(report.facts.at(TetherFacts::at_goal), fact_points(at_goal));
  EXPECT_TRUE(check_path(cspace, at_goal).valid);
  std::vector<ExactPoint> dragged = start_tether;
  dragged.insert(dragged.end(), report.path.begin() + 1, report.path.end());
  EXPECT_EQ(word_text(h.polyline(dragged)), report.facts.at(TetherFacts::word));
  EXPECT_EQ(word_text(h.polyline(at_goal)), report.facts.at(TetherFacts::word));
  EXPECT_NEAR(euclidean_length(at_goal), report.facts.at(TetherFacts::length), 1e-12);
  EXPECT_LE(report.facts.at(TetherFacts::length), report.facts.at(TetherFacts::largest));
}

TEST(TetherPlanner, UnwindsRoundThePillarWhenTheTetherIsTooShortForTheNearSide) {
  const World world = pillar();
  const CSpace cspace(world);
  const Query& q = world.queries[0];  // (12, 0) behind the pillar to (6, 8) above it
  const std::vector<ExactPoint> start_tether{{0, 0}, {3, -4}, {9, -4}, {12, 0}};  // the shortest: below, 16
  const auto free = tethered(cspace, q, "25");
  ASSERT_TRUE(free.found) << free.why_not;
  EXPECT_EQ(free.path, (std::vector<ExactPoint>{{12, 0}, {9, 6}, {6, 8}}));
  EXPECT_NEAR(free.facts.at(TetherFacts::length), 5 + 6 + 10 + std::sqrt(13.0),
              1e-12);  // round the bottom and the right side
  expect_consistent_tether(cspace, free, start_tether);
  const auto unwound = tethered(cspace, q, "20");
  ASSERT_TRUE(unwound.found) << unwound.why_not;
  EXPECT_EQ(unwound.path, (std::vector<ExactPoint>{{12, 0}, {9, -4}, {3, -4}, {3, 6}, {6, 8}}));
  EXPECT_NEAR(unwound.length, 5 + 6 + 10 + std::sqrt(13.0), 1e-12);
  EXPECT_NEAR(unwound.facts.at(TetherFacts::length), std::sqrt(45.0) + std::sqrt(13.0),
              1e-12);  // straight past the left side
  EXPECT_LE(unwound.facts.at(TetherFacts::largest), 20);
  EXPECT_TRUE(check_path(cspace, unwound.path).valid);
  expect_consistent_tether(cspace, unwound, start_tether);
}

TEST(TetherPlanner, ATetherExactlyLongEnoughIsAllowed) {
  const World world = pillar();
  const CSpace cspace(world);
  const Query& q = world.queries[1];  // (0, 0), the base, to (12, 0): round the bottom, 5 + 6 + 5
  const auto exact = tethered(cspace, q, "16");
  ASSERT_TRUE(exact.found) << exact.why_not;
  EXPECT_EQ(exact.facts.at(TetherFacts::length), 16);
  EXPECT_EQ(exact.facts.at(TetherFacts::largest), 16);
  EXPECT_EQ(exact.facts.at(TetherFacts::classes), "[] 16");
  expect_consistent_tether(cspace, exact, {{0, 0}});
  const auto shorter = tethered(cspace, q, "15.99");
  EXPECT_EQ(shorter.status, PlanStatus::no_path) << shorter.why_not;
  EXPECT_FALSE(shorter.found);
}

// A triangle whose apex (0.51, 0.68) the tether from the base (0, 0) to the goal (1.02, 0) bends
// round: 0.85 + 0.85 = 1.7 exactly, which doubles make 1.7000000000000002. L = 1.7 lets the robot
// reach the goal; 1e-15 less does not, 1e-15 more does.
TEST(TetherPlanner, ATetherExactlyLongEnoughIsAllowedWhereDoublesMakeItLonger) {
  const World world = test::world_from(R"({"bounds": [-0.5, -1, 1.5, 1.5],
    "obstacles": [[[0.51, 0.68], [0.31, -1], [0.71, -1]]], "start": [0, 0], "goal": [1.02, 0]})");
  const CSpace cspace(world);
  const Query& q = world.queries[0];
  const auto exact = tethered(cspace, q, "1.7");
  ASSERT_TRUE(exact.found) << exact.why_not;
  EXPECT_EQ(exact.path,
            (std::vector<ExactPoint>{{0, 0}, {Rational(51, 100), Rational(17, 25)}, {Rational(51, 50), 0}}));
  EXPECT_DOUBLE_EQ(exact.facts.at(TetherFacts::length), 1.7);
  EXPECT_TRUE(tethered(cspace, q, "1.700000000000001").found);
  const auto shorter = tethered(cspace, q, "1.699999999999999");
  EXPECT_EQ(shorter.status, PlanStatus::no_path) << shorter.why_not;
  EXPECT_NE(shorter.why_not.find("tether-length (1.699999999999999)"), std::string::npos) << shorter.why_not;
}

TEST(TetherPlanner, ATetherShorterThanEveryClassIsNoPath) {
  const World world = pillar();
  const CSpace cspace(world);
  const auto report = tethered(cspace, world.queries[0], "10");
  EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
  EXPECT_NE(report.why_not.find("the tether at the start is 16 long"), std::string::npos) << report.why_not;
}

TEST(TetherPlanner, ABadBaseIsNamed) {
  const World world = pillar();
  const CSpace cspace(world);
  EXPECT_THROW(planners<TranslatingRobot>().find("tether")->make(cspace, {{"tether-base", "1;2"}}), InputError);
  const auto inside =
      planners<TranslatingRobot>().find("tether")->make(cspace, {{"tether-base", "5,0"}})->plan(world.queries[0]);
  EXPECT_EQ(inside.status, PlanStatus::invalid_query);
  EXPECT_NE(inside.why_not.find("the tether base [5, 0] is not free"), std::string::npos) << inside.why_not;
}

}  // namespace
}  // namespace polyplan
