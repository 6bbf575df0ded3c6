// polyplan replan, run as a user runs it: the drive as JSON (each algorithm planning the same
// costs, D* Lite with far fewer expansions than A* from scratch), an unreachable goal, the trace as
// JSON lines and as the seed's tables, the picture, and one-line errors.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace polyplan::test;

namespace {

const std::string den312d = "'" + kSource + "/data/movingai/maps/den312d.map'";
const std::string closed_room = "'" + kSource + "/tests/data/replan/closed_room.map'";

nlohmann::json drive(const std::string& algorithm) {
  const CliRun run = run_polyplan("replan " + den312d + " --start 60,12 --goal 63,76 --sensor 1.5 --algorithm " +
                                  algorithm + " --json -");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

}  // namespace

TEST(Replan, EachAlgorithmDrivesTheSameCostsWithDifferentWork) {
  const auto dstar = drive("dstar-lite"), lpa = drive("lpastar"), astar = drive("astar");
  for (const auto* r : {&dstar, &lpa, &astar}) {
    EXPECT_EQ((*r)["status"], "solved");
    EXPECT_EQ((*r)["found"], true);
    EXPECT_EQ((*r)["traversed_cost_exact"], dstar["traversed_cost_exact"]);
    EXPECT_EQ((*r)["replans"], dstar["replans"]);
    ASSERT_EQ((*r)["steps"].size(), (*r)["moves"].get<std::size_t>());
    ASSERT_EQ((*r)["traversed"].size(), (*r)["moves"].get<std::size_t>() + 1);
    EXPECT_EQ((*r)["traversed"][0], nlohmann::json::parse("[60, 12]"));
    EXPECT_EQ((*r)["traversed"].back(), nlohmann::json::parse("[63, 76]"));
    for (std::size_t i = 0; i < (*r)["steps"].size(); ++i) {
      EXPECT_EQ((*r)["steps"][i]["at"], (*r)["traversed"][i]);
      EXPECT_EQ((*r)["steps"][i]["cost_to_goal_exact"], dstar["steps"][i]["cost_to_goal_exact"]) << i;
    }
  }
  // The optimal cost from the start on an empty map (nothing known yet) is the octile distance.
  EXPECT_EQ(dstar["steps"][0]["cost_to_goal_exact"], "61 + 3√2");
  EXPECT_LT(10 * dstar["expanded"].get<std::size_t>(), astar["expanded"].get<std::size_t>());
}

TEST(Replan, AnUnreachableGoalEndsWithNoPath) {
  const CliRun run = run_polyplan("replan " + closed_room + " --start 0,0 --goal 7,2 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto r = nlohmann::json::parse(run.out);
  EXPECT_EQ(r["status"], "no_path");
  EXPECT_EQ(r["found"], false);
  EXPECT_EQ(r["steps"].back()["cost_to_goal"], nullptr);
  EXPECT_EQ(r["why_not"], "the goal is unreachable on what the robot knows after " +
                              std::to_string(r["moves"].get<int>()) + " moves");
}

TEST(Replan, RhsTraceWritesEveryPassAsJsonLinesOrAsTables) {
  const std::string file = (std::filesystem::temp_directory_path() / "polyplan_replan_trace.jsonl").string();
  // Along the room's wall, which the robot discovers a few cells at a time.
  const CliRun run = run_polyplan("replan " + closed_room + " --start 3,4 --goal 9,0 --rhs-trace '" + file + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::istringstream lines(slurp(file));
  std::string line;
  std::size_t replans = 0, passes = 0, open_entries = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    if (j.contains("pass")) {
      ++passes;
      EXPECT_EQ(j["replan"], replans);
      for (const auto& e : j["open"]) {
        ++open_entries;
        EXPECT_TRUE(e["state"] == "over" || e["state"] == "under") << e;
      }
    } else {
      EXPECT_EQ(j["replan"], ++replans);
    }
  }
  EXPECT_GT(replans, 1u);
  EXPECT_GT(passes, replans);
  EXPECT_GT(open_entries, passes);
  std::filesystem::remove(file);

  const CliRun tables = run_polyplan("replan " + closed_room + " --start 3,4 --goal 9,0 --rhs-trace -");
  ASSERT_EQ(tables.exit_code, 0) << tables.err;
  EXPECT_NE(tables.out.find("replan 1 at (3,4)"), std::string::npos) << tables.out;
  // The goal first, its key the octile distance 2 + 4√2 from the start.
  EXPECT_NE(tables.out.find("pass 1: pops (9,0) key [7.657; 0] (over): g ∞ -> 0, rhs 0"), std::string::npos)
      << tables.out;
  EXPECT_NE(tables.out.find("(under)"), std::string::npos) << "a replan raises some g to ∞";
  EXPECT_NE(tables.out.find("open list:"), std::string::npos);
}

// --trace: one line per expansion of every replan, with search's keys: the steps of a replan
// count 1, 2, ..., and f is the key (g's and rhs's min + h + k_m).
TEST(Replan, TraceWritesEveryExpansionOfEveryReplan) {
  const CliRun run = run_polyplan("replan " + closed_room +
                                  " --start 3,4 --goal 9,0 --json - --trace /dev/null --rhs-trace /dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::size_t expanded = nlohmann::json::parse(run.out)["expanded"].get<std::size_t>();
  const CliRun traced = run_polyplan("replan " + closed_room + " --start 3,4 --goal 9,0 --trace -");
  ASSERT_EQ(traced.exit_code, 0) << traced.err;
  std::istringstream lines(traced.out);
  std::string line;
  std::size_t count = 0, replan = 0, step = 0, raised = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    for (const char* key : {"step", "vertex", "g", "h", "f", "backpointer", "open", "replan", "kind"})
      EXPECT_TRUE(j.contains(key)) << key << ": " << line;
    if (j["replan"] != replan) {
      replan = j["replan"].get<std::size_t>();
      step = 0;
    }
    EXPECT_EQ(j["step"], ++step) << line;
    if (j["kind"] != "stale key") ++count;
    if (j["g"].is_null()) ++raised;
    if (count == 1) {  // the goal, popped first: its g 0, its f the octile distance 2 + 4√2, no backpointer
      EXPECT_EQ(j["vertex"], nlohmann::json::parse("[9, 0]"));
      EXPECT_EQ(j["g"], 0.0);
      EXPECT_NEAR(j["f"].get<double>(), 2 + 4 * std::sqrt(2.0), 1e-6);
      EXPECT_EQ(j["backpointer"], nullptr);
    }
  }
  EXPECT_EQ(count, expanded);  // stale keys are put back, not expanded
  EXPECT_GT(replan, 1u);
  EXPECT_GT(raised, 0u) << "a replan raises some g to ∞";
}

TEST(Replan, DrawsWhatTheRobotKnew) {
  const std::string svg = (std::filesystem::temp_directory_path() / "polyplan_replan_test.svg").string();
  const CliRun run = run_polyplan("replan " + closed_room + " --start 0,0 --goal 4,4 --svg '" + svg + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("dstar-lite: solved after"), std::string::npos) << run.out;
  const std::string picture = slurp(svg);
  for (const char* word : {"<svg", "blocked, seen", "blocked, never seen", "traversed"})
    EXPECT_NE(picture.find(word), std::string::npos) << word;

  // Animated: the robot's dot keyed once per cell it stood on (its start, each move, and the
  // hold at the end), and cells appearing as they are sensed.
  const CliRun animated =
      run_polyplan("replan " + closed_room + " --start 0,4 --goal 9,0 --json - --svg '" + svg + "' --animate");
  ASSERT_EQ(animated.exit_code, 0) << animated.err;
  const auto moves = nlohmann::json::parse(animated.out)["moves"].get<std::size_t>();
  const std::string frames = slurp(svg);
  const auto cx = frames.find("attributeName=\"cx\"");
  ASSERT_NE(cx, std::string::npos);
  const auto values = frames.find("values=\"", cx), end = frames.find('"', values + 8);
  const std::string xs = frames.substr(values + 8, end - values - 8);
  EXPECT_EQ(static_cast<std::size_t>(std::count(xs.begin(), xs.end(), ';')), moves + 1) << xs;
  EXPECT_NE(frames.find("blocked, not yet seen"), std::string::npos);
  EXPECT_GT(std::count(frames.begin(), frames.end(), '\n'), 10);
  std::filesystem::remove(svg);
}

TEST(Replan, RefusesBadInputInOneLine) {
  const struct {
    std::string arguments;
    const char* expected;
  } cases[] = {
      {"replan " + closed_room + " --start 0,0 --goal 4,4 --algorithm dijkstra",
       "--algorithm dijkstra: expected one of dstar-lite|lpastar|astar"},
      {"replan " + closed_room + " --start 0 --goal 4,4", "--start 0: expected X,Y"},
      {"replan " + closed_room + " --start 6,1 --goal 4,4", "the start (6, 1) is a blocked cell"},
      {"replan " + closed_room + " --start 0,0 --goal 10,4", "the goal (10, 4) is outside the 10 x 5 map"},
      {"replan " + closed_room + " --start 0,0 --goal 4,4 --sensor 1",
       "--sensor 1: expected a number in [1.4142135623730951, inf)"},
      {"replan " + closed_room + " --start 0,0 --goal 4,4 --json - --trace -",
       "only one of them can go to standard output"},
      {"replan /nonexistent.map --start 0,0 --goal 4,4", "/nonexistent.map"},
      {"replan " + closed_room + " --start 0,0 --goal 4,4 --animate", "--animate: give --svg OUT.svg"},
  };
  for (const auto& c : cases) {
    const CliRun run = run_polyplan(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << c.arguments;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << c.arguments << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
}
