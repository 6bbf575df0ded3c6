// plan/plan_report: the facts every planner reports through typed keys — each key's type kept,
// the order of first setting kept, a missing fact none or refused by name.
#include <polyplan/plan/plan_report.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>

namespace polyplan {
namespace {

constexpr FactKey<std::int64_t> offset{"offset"}, b{"b"}, a{"a"};
constexpr FactKey<bool> torus{"grid.torus"};

TEST(Facts, EachKeyKeepsItsTypeIntegersAreCountsNumbersAreMeasures) {
  Facts facts;
  facts.set(RoadmapFacts::kind, "visibility");
  facts.set(RoadmapFacts::vertices, std::size_t{58});
  facts.set(RoadmapFacts::seconds, 0.25);
  facts.set(QueryFacts::seconds, 2);  // a measure from an integer
  facts.set(torus, true);
  facts.set(offset, -3);
  EXPECT_EQ(facts.at(RoadmapFacts::kind), "visibility");
  EXPECT_EQ(facts.at(RoadmapFacts::vertices), 58);
  EXPECT_EQ(facts.at(RoadmapFacts::seconds), 0.25);
  EXPECT_EQ(facts.at(QueryFacts::seconds), 2.0);
  EXPECT_TRUE(facts.at(torus));
  EXPECT_EQ(facts.at(offset), -3);
  EXPECT_TRUE(std::holds_alternative<std::string>(*facts.value_named("roadmap.kind")));
  EXPECT_TRUE(std::holds_alternative<double>(*facts.value_named("query_seconds")));
  EXPECT_TRUE(std::holds_alternative<bool>(*facts.value_named("grid.torus")));
}

TEST(Facts, NamesKeepTheOrderOfFirstSettingAndSettingAgainReplaces) {
  Facts facts;
  facts.set(b, 1);
  facts.set(a, 2);
  facts.set(b, 3);
  ASSERT_EQ(facts.entries().size(), 2u);
  EXPECT_EQ(facts.entries()[0].first, "b");
  EXPECT_EQ(facts.at(b), 3);
  EXPECT_EQ(facts.entries()[1].first, "a");
}

TEST(Facts, AMissingFactIsNoneOrRefusedByName) {
  Facts facts;
  facts.set(SearchFacts::algorithm, "astar");
  EXPECT_EQ(facts.find(SearchFacts::expanded), std::nullopt);
  EXPECT_FALSE(facts.contains(SearchFacts::expanded));
  EXPECT_EQ(facts.find(SearchFacts::algorithm), "astar");
  try {
    facts.at(SearchFacts::expanded);
    ADD_FAILURE() << "read a missing fact";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "no fact \"search.expanded\"");
  }
}

TEST(CellGrid, StatesAreIndexedColumnFirst) {
  CellGrid cells;
  cells.columns = 3;
  cells.rows = 2;
  cells.states = {CellGrid::free,          CellGrid::blocked, CellGrid::free,
                  CellGrid::not_evaluated, CellGrid::free,    CellGrid::blocked};
  EXPECT_EQ(cells.state(1, 0), CellGrid::blocked);
  EXPECT_EQ(cells.state(0, 1), CellGrid::not_evaluated);
  EXPECT_EQ(cells.state(2, 1), CellGrid::blocked);
}

}  // namespace
}  // namespace polyplan
