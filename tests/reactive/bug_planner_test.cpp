// Bug1 and Bug2 on the exact C-space: round the course's planning problem set's wall and out of the U-shaped trap,
// paths checked exactly, hit and leave points where the geometry puts them, the distance within the textbook's bound
// computed here from the obstacle's own perimeter; unreachable goals no_path.
#include "world_fixtures.hpp"

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/reactive_facts.hpp>
#include <polyplan/registry/registry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

using test::shipped;

PlanReport<ExactPoint> walk(const char* bug, const CSpace& cspace, const Query& q) {
  return planners<TranslatingRobot>().find(bug)->make(cspace, {})->plan(q);
}

// The wall x ∈ [0, 0.5], y ∈ [−100, 100]: perimeter 401. From (−3, 0.5) the line to (2, 0) hits
// it at (0, 0.2) (y = 0.5 − 0.1·3).
TEST(BugPlanners, GoRoundSeedTwosWallWithinTheirBounds) {
  const World world = shipped("seed002_wall");
  const CSpace cspace(world);
  const Query& q = world.queries[0];
  const double d = std::hypot(5.0, 0.5), perimeter = 401;
  for (const char* bug : {"bug1", "bug2"}) {
    SCOPED_TRACE(bug);
    const auto report = walk(bug, cspace, q);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.path.front(), q.start);
    EXPECT_EQ(report.path.back(), q.goal);
    EXPECT_TRUE(check_path(cspace, report.path).valid);
    EXPECT_EQ(report.facts.at(BugFacts::hits), (FactPoints{{0, 0.2}}));
    const double bound = std::string(bug) == "bug1" ? d + 1.5 * perimeter
                                                    : d + 0.5 * 2 * perimeter;  // the m-line crosses the wall twice
    EXPECT_NEAR(report.facts.at(BugFacts::bound), bound, 1e-9);
    EXPECT_LE(report.length, bound);
    EXPECT_GT(report.length, 200);  // round an end of the wall
  }
  // Bug2 leaves where the m-line comes out of the wall's far side, x = 0.5: y = 0.5 − 0.1·3.5.
  EXPECT_EQ(walk("bug2", cspace, q).facts.at(BugFacts::leaves), (FactPoints{{0.5, 0.15}}));
  // Bug1 leaves from the wall's point nearest the goal, the foot of the perpendicular on x = 0.5.
  EXPECT_EQ(walk("bug1", cspace, q).facts.at(BugFacts::leaves), (FactPoints{{0.5, 0}}));
}

// Both Bugs reach the goal of the world's first query along an exactly valid path within their
// bound, the first hit point where `first_hit` says.
void expect_both_walk_out(const CSpace& cspace, const Query& q, const FactPoint& first_hit) {
  for (const char* bug : {"bug1", "bug2"}) {
    SCOPED_TRACE(bug);
    const auto report = walk(bug, cspace, q);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_TRUE(check_path(cspace, report.path).valid);
    EXPECT_LE(report.length, report.facts.at(BugFacts::bound));
    const FactPoints hits = report.facts.at(BugFacts::hits);
    ASSERT_FALSE(hits.empty());
    EXPECT_EQ(hits.front(), first_hit);
  }
}

TEST(BugPlanners, WalkOutOfTheTrap) {
  const World world = shipped("u_trap");
  const CSpace cspace(world);
  expect_both_walk_out(cspace, world.queries[0], (FactPoint{10, 7}));  // the inside of the U's bottom
  // Bug2 leaves where the m-line x = 10 meets the U's outside bottom, y = 6.
  EXPECT_EQ(walk("bug2", cspace, world.queries[0]).facts.at(BugFacts::leaves), (FactPoints{{10, 6}}));
}

// Out of the spiral's heart (eight overlapping walls, one C-obstacle): both walk it out within
// their bounds, where the potential field is caught in a corner.
TEST(BugPlanners, WalkOutOfTheSpiral) {
  const World world = shipped("spiral");
  const CSpace cspace(world);
  expect_both_walk_out(cspace, world.queries[0], (FactPoint{7.5, 7.5}));  // the first wall the line to (1, 1) meets
  const auto field = planners<TranslatingRobot>().find("potential-field")->make(cspace, {})->plan(world.queries[0]);
  EXPECT_EQ(field.status, PlanStatus::local_minimum) << field.why_not;
}

TEST(BugPlanners, AnUnreachableGoalIsNoPath) {
  // office.json's query 3 starts inside the pillar's hole; wkt_obstacles' query 1 inside a ring.
  for (const auto& [name, index] : {std::pair{"office", 3}, std::pair{"wkt_obstacles", 1}}) {
    const World world = shipped(name);
    const CSpace cspace(world);
    for (const char* bug : {"bug1", "bug2"}) {
      SCOPED_TRACE(std::string(name) + " " + bug);
      const auto report = walk(bug, cspace, world.queries[static_cast<std::size_t>(index)]);
      EXPECT_EQ(report.status, PlanStatus::no_path) << report.why_not;
      EXPECT_NE(report.why_not.find("the goal is unreachable"), std::string::npos) << report.why_not;
    }
  }
}

}  // namespace
}  // namespace polyplan
