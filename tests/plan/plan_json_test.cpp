// plan/plan_json: the one writer of the object `polyplan plan --json` prints (docs/design.md), for reports over points
// and over joint angles: the fixed keys, exact rationals for points, facts nested by their dots.
#include <polyplan/plan/plan_json.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace polyplan {
namespace {

TEST(PlanJson, AFoundPointPathHasDoublesExactRationalsTheCertificateAndNestedFacts) {
  PlanReport<ExactPoint> report;
  report.found = true;
  report.path = {{Rational(7, 10), Rational(23, 10)}, {Rational(3), Rational(-1, 3)}};
  report.length = 2.5;
  report.certificate = {true, "exact path check"};
  report.facts.set(RoadmapFacts::kind, "visibility");
  report.facts.set(RoadmapFacts::vertices, 120);
  report.facts.set(SearchFacts::seconds, 0.001);
  report.facts.set(QueryFacts::seconds, 0.002);
  const nlohmann::json j = plan_json(report, "start/goal");
  EXPECT_EQ(j["query"], "start/goal");
  EXPECT_EQ(j["found"], true);
  EXPECT_EQ(j["length"], 2.5);
  EXPECT_EQ(j["path"][0][0].get<double>(), 0.7);
  EXPECT_EQ(j["path"][1][1].get<double>(), -1.0 / 3);
  EXPECT_EQ(j["path_exact"], nlohmann::json::parse(R"([["7/10", "23/10"], ["3", "-1/3"]])"));
  EXPECT_EQ(j["certified"], true);
  EXPECT_EQ(j["certified_by"], "exact path check");
  EXPECT_EQ(j["roadmap"], nlohmann::json::parse(R"({"kind": "visibility", "vertices": 120})"));
  EXPECT_EQ(j["search"]["seconds"], 0.001);
  EXPECT_EQ(j["query_seconds"], 0.002);
  EXPECT_FALSE(j.contains("why_not"));
}

TEST(PlanJson, NoPathIsNullLengthEmptyPathsAndTheReason) {
  PlanReport<ExactPoint> report;
  report.why_not = "start and goal lie in different components of the free space";
  const nlohmann::json j = plan_json(report);
  EXPECT_FALSE(j.contains("query"));
  EXPECT_EQ(j["found"], false);
  EXPECT_TRUE(j["length"].is_null());
  EXPECT_EQ(j["path"], nlohmann::json::array());
  EXPECT_EQ(j["path_exact"], nlohmann::json::array());
  EXPECT_EQ(j["why_not"], report.why_not);
  EXPECT_EQ(j["certified"], false);
  EXPECT_FALSE(j.contains("certified_by"));
}

TEST(PlanJson, JointAnglePathsAreListsOfAnglesWithoutExactCoordinates) {
  PlanReport<JointAngles> report;
  report.found = true;
  report.path = {{0.5, 1.0}, {0.6, 1.0}};
  report.length = 0.1;
  report.facts.set(FactKey<bool>{"grid.torus"}, true);
  report.facts.set(FactKey<std::int64_t>{"expanded"}, 12);
  const nlohmann::json j = plan_json(report, "easy");
  EXPECT_EQ(j["path"], nlohmann::json::parse("[[0.5, 1.0], [0.6, 1.0]]"));
  EXPECT_FALSE(j.contains("path_exact"));
  EXPECT_EQ(j["grid"]["torus"], true);
  EXPECT_EQ(j["expanded"], 12);
}

TEST(PlanJson, AFactInsideAFactThatIsAValueIsRefused) {
  PlanReport<ExactPoint> report;
  report.facts.set(FactKey<std::string>{"search"}, "astar");
  report.facts.set(SearchFacts::expanded, 3);
  EXPECT_THROW(plan_json(report), std::logic_error);
}

}  // namespace
}  // namespace polyplan
