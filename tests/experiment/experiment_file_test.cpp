// Reading experiment files: what a good one gives, and the one-line error for each kind of bad one.
#include <polyplan/experiment/experiment_file.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <gtest/gtest.h>

#include <string>

namespace polyplan {
namespace {

// As if the file were data/experiments/test.json: problem files resolve against that folder.
const std::string kName = std::string(POLYPLAN_SOURCE_DIR) + "/data/experiments/test.json";

Experiment parse(const std::string& text) { return parse_experiment(text, kName); }

// The message of the InputError that parsing `text` throws ("" when it throws none).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A good experiment with one field replaced by `field` (a JSON member, or "" for none).
std::string with(const std::string& problems, const std::string& planners,
                 const std::string& rest = R"("seeds": [1, 2], "time_limit": 1)") {
  return R"({"name": "t", "problems": )" + problems + R"(, "planners": )" + planners + ", " + rest + "}";
}

const std::string kOffice = R"([{"name": "office", "file": "../worlds/office.json"}])";
const std::string kArm = R"([{"name": "arm", "file": "../arms/three_link_forest.json"}])";
const std::string kRrt = R"([{"name": "rrt-e1", "planner": "rrt", "options": {"extend": "e1", "goal-bias": 0.2}}])";

TEST(ExperimentFile, ReadsProblemsPlannersSeedsAndLimits) {
  const Experiment e = parse(with(R"([{"name": "office", "file": "../worlds/office.json", "query": "queries[1]"},
                                      {"name": "arm", "file": "../arms/three_link_forest.json"}])",
                                  R"([{"name": "star", "planner": "rrtstar", "options": {"k": 11, "shortcut": false}},
                                      {"name": "prm", "planner": "prm"}])",
                                  R"("seeds": [3, 4, 5], "time_limit": 2, "cost_times": [0.5, 1, 2])"));
  EXPECT_EQ(e.name, "t");
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(e.problems[0].kind, ProblemKind::world);
  EXPECT_EQ(e.problems[0].query, "queries[1]");
  EXPECT_EQ(e.problems[1].kind, ProblemKind::arm);  // it has "links"
  EXPECT_EQ(e.problems[1].query, "start/goal");     // the file's first
  EXPECT_EQ(e.problems[1].file, std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/three_link_forest.json");
  ASSERT_EQ(e.planners.size(), 2u);
  EXPECT_EQ(e.planners[0].options, (OptionValues{{"k", "11"}, {"shortcut", "false"}}));
  EXPECT_TRUE(e.planners[0].anytime);
  EXPECT_FALSE(e.planners[1].anytime);
  EXPECT_EQ(e.seeds, (std::vector<std::uint64_t>{3, 4, 5}));
  EXPECT_EQ(e.time_limit, 2);
  EXPECT_EQ(e.cost_times, (std::vector<double>{0.5, 1, 2}));
  EXPECT_EQ(e.cells(), 12u);
}

TEST(ExperimentFile, CostTimesDefaultToEvenStepsUpToTheLimit) {
  const Experiment e = parse(with(kOffice, kRrt, R"("seeds": [1], "time_limit": 4)"));
  ASSERT_EQ(e.cost_times.size(), 20u);
  EXPECT_EQ(e.cost_times.front(), 0.2);
  EXPECT_EQ(e.cost_times.back(), 4);
}

TEST(ExperimentFile, AnUnknownOptionIsNamedWithThePlannersOptions) {
  const std::string message = error_of(
      with(kOffice, R"([{"name": "a", "planner": "rrt"}, {"name": "b", "planner": "rrt", "options": {"k": 3}}])"));
  EXPECT_EQ(
      message.rfind(kName + ": planners[1].options.k: unknown option for rrt (options: goal-bias, step, extend", 0), 0u)
      << message;
}

TEST(ExperimentFile, ABadOptionValueIsTheRegistrysMessage) {
  const std::string message =
      error_of(with(kOffice, R"([{"name": "a", "planner": "rrt", "options": {"goal-bias": "often"}}])"));
  EXPECT_NE(message.find("planners[0]: planner rrt: option goal-bias=often"), std::string::npos) << message;
}

TEST(ExperimentFile, SeedAndTimeAreTheExperimentsNotOptions) {
  EXPECT_EQ(error_of(with(kOffice, R"([{"name": "a", "planner": "rrt", "options": {"seed": 3}}])")),
            kName + ": planners[0].options.seed: the experiment's seeds set it");
  EXPECT_EQ(error_of(with(kOffice, R"([{"name": "a", "planner": "rrt", "options": {"time": 3}}])")),
            kName + ": planners[0].options.time: the experiment's time_limit sets it");
}

TEST(ExperimentFile, APlannerMustPlanEveryProblem) {
  const std::string message = error_of(with(kArm, R"([{"name": "v", "planner": "visibility"}])"));
  EXPECT_EQ(message.rfind(kName + ": planners[0].planner: no planner \"visibility\" plans problems[0]", 0), 0u)
      << message;
  EXPECT_NE(message.find("its planners: grid, prm"), std::string::npos) << message;
}

TEST(ExperimentFile, ProblemsAreCheckedAgainstTheirFiles) {
  EXPECT_EQ(
      error_of(with(R"([{"name": "o", "file": "../worlds/office.json", "query": "nowhere"}])", kRrt))
          .rfind(kName + ": problems[0].query: no query named \"nowhere\" (queries: start/goal, queries[0], queries[1]",
                 0),
      0u);
  EXPECT_EQ(error_of(with(R"([{"name": "o", "file": "../worlds/office.json", "query": 9}])", kRrt))
                .rfind(kName + ": problems[0].query: no query 9", 0),
            0u);
  const std::string missing = error_of(with(R"([{"name": "o", "file": "missing.json"}])", kRrt));
  EXPECT_EQ(missing.rfind(kName + ": problems[0].file: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("missing.json: cannot open file"), std::string::npos) << missing;
  EXPECT_EQ(error_of(with(R"([{"name": "o", "file": "../worlds/office.json", "kind": "arm"}])", kRrt)),
            kName + ": problems[0].kind: \"arm\", but the file is a world file");
  EXPECT_EQ(error_of(with(R"([{"name": "o", "file": "../worlds/office.json", "kind": "car"}])", kRrt)),
            kName + ": problems[0].kind: expected \"world\" or \"arm\"");
}

TEST(ExperimentFile, KeysAndValuesAreChecked) {
  EXPECT_EQ(error_of("[]"),
            kName + ": experiment: expected a JSON object with problems, planners, seeds and time_limit");
  EXPECT_EQ(error_of("{").rfind(kName + ": not JSON", 0), 0u);
  EXPECT_EQ(
      error_of(with(kOffice, kRrt, R"("seeds": [1], "time_limt": 1)")).rfind(kName + ": time_limt: unknown key", 0),
      0u);
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [1])")), kName + ": time_limit: missing");
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [], "time_limit": 1)")),
            kName + ": seeds: expected a non-empty array");
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [-1], "time_limit": 1)")),
            kName + ": seeds[0]: expected a whole number >= 0");
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [1], "time_limit": 0)")),
            kName + ": time_limit: expected a positive number of seconds");
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [1], "time_limit": 1, "cost_times": [0.5, 2])")),
            kName + ": cost_times[1]: after the time limit (2 > 1)");
  EXPECT_EQ(error_of(with(kOffice, kRrt, R"("seeds": [1], "time_limit": 1, "cost_times": [0.5, 0.5])")),
            kName + ": cost_times[1]: the times must increase");
  EXPECT_EQ(error_of(with(kOffice, R"([{"name": "a", "planner": "rrt"}, {"name": "a", "planner": "prm"}])")),
            kName + ": planners[1].name: \"a\" names two planner entries");
  EXPECT_EQ(error_of(with(kOffice, R"([{"name": "a", "planner": "rrt", "options": {"step": [1]}}])")),
            kName + ": planners[0].options.step: expected a number, text or true/false");
  EXPECT_EQ(error_of(with(kOffice, R"([{"planner": "rrt"}])")), kName + ": planners[0].name: missing");
}

}  // namespace
}  // namespace polyplan
