#pragma once
// What the conformance tests of the registries iterate over (the shipped data files of a folder
// and the names a registry holds) and the promises every report keeps whatever its space.
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/registry.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace polyplan::test {

// The stems of the .json files in data/FOLDER ("maze" for data/worlds/maze.json), sorted.
inline std::vector<std::string> shipped(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(POLYPLAN_SOURCE_DIR) + "/data/" + folder))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The shipped worlds (data/worlds) whose round_features are empty (`round` false: polygons and a
// polygon or point robot only) or not (`round` true: discs, walls, disc bounds, a disc robot).
inline std::vector<std::string> shipped_worlds(bool round) {
  std::vector<std::string> names;
  for (const std::string& name : shipped("worlds"))
    if (round_features(read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json")).empty() !=
        round)
      names.push_back(name);
  return names;
}

template <class Space>
std::vector<std::string> registered_planners() {
  std::vector<std::string> names;
  for (const auto& entry : planners<Space>().entries()) names.push_back(entry.name);
  return names;
}

// A test name from a planner's and a file's names: letters, digits and underscores only.
inline std::string test_name(const std::string& planner, const std::string& file) {
  std::string name = planner + "_on_" + file;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

// A report's answer agrees with itself and with its JSON: found exactly when solved, a path
// exactly when found, a reason and no path otherwise, a limit that names what stopped it.
template <class Configuration>
void expect_consistent_answer(const PlanReport<Configuration>& report, const std::string& query) {
  EXPECT_EQ(report.found, report.status == PlanStatus::solved) << to_string(report.status);
  if (report.found) {
    EXPECT_TRUE(report.why_not.empty()) << report.why_not;
    EXPECT_TRUE(report.certificate.certified);
    EXPECT_FALSE(report.certificate.method.empty());
  } else {
    EXPECT_FALSE(report.why_not.empty());
    // Empty, or the walk of a reactive planner up to where it stopped: never a certified answer.
    if (!report.path.empty()) {
      EXPECT_NE(report.status, PlanStatus::invalid_query);
      EXPECT_FALSE(report.certificate.certified);
    }
  }
  if (report.status == PlanStatus::limit) {  // braces: EXPECT_TRUE is an if-else of its own
    EXPECT_TRUE(report.facts.contains(QueryFacts::stopped_by));
  }
  const nlohmann::json json = plan_json(report, query);
  EXPECT_EQ(json["found"], report.found);
  EXPECT_EQ(json["status"], std::string(to_string(report.status)));
  EXPECT_EQ(json["length"].is_null(), !report.found);
  EXPECT_EQ(json["path"].size(), report.path.size());
}

// A time limit cuts where the machine's speed says: such answers are not compared.
template <class Configuration>
bool cut_by_time(const PlanReport<Configuration>& report) {
  return report.facts.contains(QueryFacts::stopped_by) && report.facts.at(QueryFacts::stopped_by) == "time limit";
}

// The same queries asked in turn of two planners built alike give the same answers (docs/design.md:
// the same input gives the same answer every time) until a time limit cuts a query of either:
// where the machine's speed stopped it, a roadmap planner has grown a different roadmap, and the
// queries after use it. (Each query draws its own random stream, so a tree planner's later
// answers would not change; a roadmap's do.)
class SameAnswers {
 public:
  template <class Configuration>
  void expect(const PlanReport<Configuration>& first, const PlanReport<Configuration>& again) {
    cut_ = cut_ || cut_by_time(first) || cut_by_time(again);
    if (cut_) return;
    EXPECT_EQ(again.found, first.found);
    EXPECT_EQ(again.status, first.status);
    EXPECT_EQ(again.path, first.path);
    EXPECT_EQ(again.length, first.length);
  }

 private:
  bool cut_ = false;
};

}  // namespace polyplan::test
