// roadmaps/plan_report: the named facts every planner reports — kinds kept, order of first
// setting kept, typed reads that refuse a missing fact or one of another kind.
#include <polyplan/plan/plan_report.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>

namespace polyplan {
namespace {

TEST(Facts, IntegersAreCountsFloatsAreMeasuresTextIsAWord) {
  Facts facts;
  facts.set("roadmap.kind", "visibility");
  facts.set("roadmap.vertices", std::size_t{58});
  facts.set("roadmap.seconds", 0.25);
  facts.set("grid.torus", true);
  facts.set("offset", -3);
  EXPECT_EQ(facts.text("roadmap.kind"), "visibility");
  EXPECT_EQ(facts.count("roadmap.vertices"), 58);
  EXPECT_EQ(facts.number("roadmap.vertices"), 58.0);  // a count reads as a number too
  EXPECT_EQ(facts.number("roadmap.seconds"), 0.25);
  EXPECT_TRUE(facts.flag("grid.torus"));
  EXPECT_EQ(facts.count("offset"), -3);
  EXPECT_TRUE(std::holds_alternative<std::string>(*facts.find("roadmap.kind")));
  EXPECT_TRUE(std::holds_alternative<bool>(*facts.find("grid.torus")));
}

TEST(Facts, NamesKeepTheOrderOfFirstSettingAndSettingAgainReplaces) {
  Facts facts;
  facts.set("b", 1);
  facts.set("a", 2);
  facts.set("b", 3);
  ASSERT_EQ(facts.entries().size(), 2u);
  EXPECT_EQ(facts.entries()[0].first, "b");
  EXPECT_EQ(facts.count("b"), 3);
  EXPECT_EQ(facts.entries()[1].first, "a");
}

TEST(Facts, MissingFactsAndOtherKindsAreRefusedByName) {
  Facts facts;
  facts.set("search.algorithm", "astar");
  EXPECT_EQ(facts.find("search.expanded"), nullptr);
  EXPECT_FALSE(facts.contains("search.expanded"));
  try {
    facts.count("search.expanded");
    ADD_FAILURE() << "read a missing fact";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "no fact \"search.expanded\"");
  }
  try {
    facts.number("search.algorithm");
    ADD_FAILURE() << "read a word as a number";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "the fact \"search.algorithm\" is not a number");
  }
  EXPECT_THROW(facts.flag("search.algorithm"), std::out_of_range);
}

TEST(CellGrid, StatesAreIndexedColumnFirst) {
  CellGrid cells;
  cells.columns = 3;
  cells.rows = 2;
  cells.states = {CellGrid::free, CellGrid::blocked, CellGrid::free, CellGrid::not_evaluated, CellGrid::free, CellGrid::blocked};
  EXPECT_EQ(cells.state(1, 0), CellGrid::blocked);
  EXPECT_EQ(cells.state(0, 1), CellGrid::not_evaluated);
  EXPECT_EQ(cells.state(2, 1), CellGrid::blocked);
}

}  // namespace
}  // namespace polyplan
