// polyplan plan on arm files, run as a user runs it: the course's two-link cases on the torus and
// the interval, the JSON, the pictures, one-line errors, and `polyplan arm`, the command's old name.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

namespace {

using namespace polyplan::test;
namespace fs = std::filesystem;

TEST(ArmCommand, HardCaseJsonOnTheTorusAndNoPathOnTheInterval) {
  const CliRun torus =
      run_polyplan("plan " + arm_file("two_link_points.json") + " --planner grid --resolution 5 --query hard --json -");
  ASSERT_EQ(torus.exit_code, 0) << torus.err;
  const auto j = nlohmann::json::parse(torus.out);
  for (const char* key : {"found", "path", "length", "cells_evaluated", "expanded", "seconds"})
    EXPECT_TRUE(j.contains(key)) << key;
  ASSERT_TRUE(j["found"].get<bool>());
  // The path starts exactly at the file's start configuration and ends exactly at its goal.
  EXPECT_EQ(j["path"].front(), nlohmann::json::parse("[3.30, 2.34]"));
  EXPECT_EQ(j["path"].back(), nlohmann::json::parse("[5.49, 1.07]"));
  EXPECT_EQ(j["grid"]["torus"], true);
  EXPECT_EQ(j["grid"]["evaluation"], "lazy");

  const CliRun interval =
      run_polyplan("plan " + arm_file("two_link_points.json") + " --resolution 5 --no-torus --query hard --json -");
  ASSERT_EQ(interval.exit_code, 0) << "no path is an answer: " << interval.err;
  const auto k = nlohmann::json::parse(interval.out);
  EXPECT_FALSE(k["found"].get<bool>());
  EXPECT_TRUE(k["length"].is_null());
  EXPECT_FALSE(k["why_not"].get<std::string>().empty());
}

// The sampling planners' flags, as the issue writes them: one seed, one path, and the facts.
TEST(ArmCommand, SamplingPlannersTakeTheirFlagsAndOneSeedGivesOnePath) {
  const std::string command =
      "arm " + arm_file("four_link_forest.json") +
      " --planner rrt --seed 7 --time 20 --iterations 50000 --goal-bias 0.1 --step 1 --extend e2 --json -";
  const CliRun once = run_polyplan(command), again = run_polyplan(command);
  ASSERT_EQ(once.exit_code, 0) << once.err;
  const auto a = nlohmann::json::parse(once.out), b = nlohmann::json::parse(again.out);
  ASSERT_TRUE(a["found"].get<bool>()) << a.dump();
  EXPECT_EQ(a["path"], b["path"]);
  for (const char* key :
       {"samples", "tree_size", "motions_checked", "first_solution_seconds", "raw_length", "iterations", "seed"})
    EXPECT_TRUE(a.contains(key)) << key;
  EXPECT_EQ(a["seed"], 7);
  EXPECT_EQ(a["roadmap"]["kind"], "rrt");
  EXPECT_LE(a["length"].get<double>(), a["raw_length"].get<double>());
  EXPECT_EQ(a["path"].front(), nlohmann::json::parse("[0.1, 0.2, 0.3, 0.4]"));

  const CliRun prm = run_polyplan("plan " + arm_file("two_link_points.json") +
                                  " --planner prm --k 15 --bidirectional --query hard --json -");
  ASSERT_EQ(prm.exit_code, 0) << prm.err;
  const auto p = nlohmann::json::parse(prm.out);
  EXPECT_TRUE(p["found"].get<bool>());
  EXPECT_TRUE(p["roadmap"].contains("vertices"));
  EXPECT_EQ(p["search"]["algorithm"], "bidirectional dijkstra");

  const CliRun bias = run_polyplan("plan " + arm_file("two_link_points.json") + " --planner rrt --goal-bias 2");
  EXPECT_EQ(bias.exit_code, 2);
  EXPECT_NE(bias.err.find("planner rrt: option goal-bias=2: expected a number in [0, 1]"), std::string::npos)
      << bias.err;
}

TEST(ArmCommand, EveryQueryOfAFileGivesAnArrayAndEagerMatchesLazy) {
  const CliRun lazy = run_polyplan("plan " + arm_file("two_link_points.json") + " --json -");
  const CliRun eager = run_polyplan("plan " + arm_file("two_link_points.json") + " --eager --json -");
  ASSERT_EQ(lazy.exit_code, 0) << lazy.err;
  ASSERT_EQ(eager.exit_code, 0) << eager.err;
  const auto a = nlohmann::json::parse(lazy.out), b = nlohmann::json::parse(eager.out);
  ASSERT_TRUE(a.is_array());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["query"], b[i]["query"]);
    EXPECT_NEAR(a[i]["length"].get<double>(), b[i]["length"].get<double>(), 1e-12);
    EXPECT_LT(a[i]["cells_evaluated"].get<int>(), b[i]["cells_evaluated"].get<int>());
  }
}

TEST(ArmCommand, WritesTheAnimationAndTheStrobe) {
  const fs::path dir = fs::temp_directory_path() / ("polyplan_arm_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const CliRun run = run_polyplan("plan " + arm_file("two_link_points.json") + " --query medium --svg '" +
                                  (dir / "medium.svg").string() + "' --strobe '" + (dir / "strobe.svg").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string animation = slurp(dir / "medium.svg"), strobe = slurp(dir / "strobe.svg");
  EXPECT_NE(animation.find("repeatCount=\"indefinite\""), std::string::npos);
  EXPECT_EQ(animation.find("<script"), std::string::npos);
  EXPECT_NE(strobe.find("<svg"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ArmCommand, BadInputIsOneLineNamingTheProblem) {
  const CliRun resolution = run_polyplan("plan " + arm_file("two_link_points.json") + " --resolution 7");
  EXPECT_EQ(resolution.exit_code, 2);
  EXPECT_EQ(lines(resolution.err), 1u) << resolution.err;
  EXPECT_NE(resolution.err.find("must divide 360"), std::string::npos) << resolution.err;
  const CliRun query = run_polyplan("plan " + arm_file("two_link_points.json") + " --query nonsense");
  EXPECT_EQ(query.exit_code, 2);
  EXPECT_NE(query.err.find("no query named nonsense"), std::string::npos) << query.err;
  const CliRun method = run_polyplan("plan " + arm_file("two_link_points.json") + " --planner teleport");
  EXPECT_EQ(method.exit_code, 2);
  EXPECT_EQ(lines(method.err), 1u) << method.err;
  const CliRun missing = run_polyplan("plan /nonexistent/arm.json");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/arm.json"), std::string::npos) << missing.err;
  // Thirteen joints exited 3 ("internal error") from the grid's axis limit.
  const std::filesystem::path thirteen = std::filesystem::temp_directory_path() / "polyplan_arm13.json";
  std::ofstream(thirteen)
      << R"({"links": [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1], "start": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
                                 "goal": [1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]})";
  const CliRun joints = run_polyplan("plan '" + thirteen.string() + "'");
  EXPECT_EQ(joints.exit_code, 2) << joints.err;
  EXPECT_EQ(lines(joints.err), 1u) << joints.err;
  EXPECT_NE(joints.err.find("an arm of 13 joints needs a grid of as many axes; it has at most 12"), std::string::npos)
      << joints.err;
  std::filesystem::remove(thirteen);
}

}  // namespace

namespace {

TEST(ArmCommand, OptionsAndTheOldFlagsSetTheSamePlanner) {
  const CliRun flags = run_polyplan("plan " + arm_file("two_link_points.json") +
                                    " --planner grid --resolution 10 --no-torus --eager --json -");
  const CliRun options = run_polyplan("plan " + arm_file("two_link_points.json") +
                                      " --planner grid --option resolution=10 "
                                      "--option torus=false --option evaluation=eager --json -");
  ASSERT_EQ(flags.exit_code, 0) << flags.err;
  ASSERT_EQ(options.exit_code, 0) << options.err;
  const auto a = nlohmann::json::parse(flags.out), b = nlohmann::json::parse(options.out);
  ASSERT_EQ(a.size(), 3u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["grid"]["resolution_degrees"], 10.0);
    EXPECT_EQ(a[i]["grid"]["torus"], false);
    EXPECT_EQ(a[i]["grid"]["evaluation"], "eager");
    EXPECT_EQ(a[i]["cells_evaluated"], 36 * 36);
    EXPECT_EQ(a[i]["path"], b[i]["path"]);
  }
}

TEST(ArmCommand, PathsAreCertifiedAndCheckResolutionIsRefused) {
  const CliRun refused =
      run_polyplan("plan " + arm_file("two_link_points.json") + " --query easy --check-resolution 0.5");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--check-resolution is gone: every motion is certified"), std::string::npos)
      << refused.err;
  EXPECT_TRUE(refused.out.empty()) << refused.out;
  const CliRun run = run_polyplan("plan " + arm_file("two_link_points.json") + " --query easy --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["certified"], true);
  EXPECT_NE(j["certified_by"].get<std::string>().find("conservative advancement"), std::string::npos);
  EXPECT_TRUE(j.contains("moves_uncertified"));
  const CliRun both = run_polyplan("plan " + arm_file("two_link_points.json") + " --evaluation eager --eager");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("given twice"), std::string::npos) << both.err;
}

}  // namespace

namespace {

// Goals in the workspace: the JSON names the IK solution reached and the hand's error there, the
// summary line says it, an unreachable point is an answer (no_path, why), the picture marks the
// point; a query with both goal and goal_point is bad input.
TEST(ArmCommand, AGoalPointIsPlannedToItsIkSolutions) {
  const CliRun run = run_polyplan("plan " + arm_file("two_link_reach.json") + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto all = nlohmann::json::parse(run.out);
  ASSERT_EQ(all.size(), 5u);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& answer : all) by_name[answer["query"].get<std::string>()] = answer;
  const std::map<std::string, int> candidates{
      {"outer_boundary", 1}, {"inner_boundary", 1}, {"two_elbows", 2}, {"one_elbow_free", 1}};
  for (const auto& [name, count] : candidates) {
    SCOPED_TRACE(name);
    const auto& j = by_name.at(name);
    ASSERT_TRUE(j["found"].get<bool>()) << j.dump();
    EXPECT_EQ(j["goal"]["candidates"], count);
    EXPECT_LT(j["goal"]["reached"].get<int>(), count);
    EXPECT_LE(j["goal"]["error"].get<double>(), 1e-12);
    EXPECT_EQ(j["goal"]["solutions"], name == "one_elbow_free" ? 2 : count);
  }
  const auto& beyond = by_name.at("one_ulp_beyond");
  EXPECT_FALSE(beyond["found"].get<bool>());
  EXPECT_EQ(beyond["status"], "no_path");
  EXPECT_EQ(beyond["why_not"],
            "the point (0, 5.000000000000001) is out of reach: the arm reaches distances 1 to 5 from its base");
  EXPECT_FALSE(beyond.contains("goal"));

  const CliRun text =
      run_polyplan("plan " + arm_file("two_link_reach.json") + " --query two_elbows --planner rrtconnect");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("two_elbows: length "), std::string::npos) << text.out;
  EXPECT_TRUE(std::regex_search(
      text.out,
      std::regex(R"(, ends at IK solution ([12]) of 2 \(goal\.reached [01]\), the hand \S+ from the goal point\n)")))
      << text.out;
}

TEST(ArmCommand, APictureMarksTheGoalPoint) {
  const fs::path dir = fs::temp_directory_path() / ("polyplan_arm_goal_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const CliRun run = run_polyplan("plan " + arm_file("four_link_reach.json") + " --planner rrtconnect --svg '" +
                                  (dir / "reach.svg").string() + "' --strobe '" + (dir / "strobe.svg").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* picture : {"reach-oriented.svg", "strobe-near_the_base.svg", "reach-out_of_reach.svg"}) {
    const std::string svg = slurp(dir / picture);
    EXPECT_NE(svg.find("class=\"goal-point\""), std::string::npos) << picture;
  }
  EXPECT_NE(slurp(dir / "reach-oriented.svg").find("goal point and orientation (the hand&apos;s target)"),
            std::string::npos);
  EXPECT_NE(slurp(dir / "reach-near_the_base.svg").find("goal point (the hand&apos;s target)"), std::string::npos);
  EXPECT_EQ(slurp(dir / "reach-near_the_base.svg").find("goal point and orientation"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ArmCommand, BothGoalAndGoalPointIsBadInput) {
  const fs::path file = fs::temp_directory_path() / ("polyplan_arm_both_" + std::to_string(::getpid()) + ".json");
  std::ofstream(file)
      << R"({"links": [1, 1], "queries": [{"name": "q", "start": [0, 0], "goal": [1, 1], "goal_point": [1, 1]}]})";
  const CliRun run = run_polyplan("plan '" + file.string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find(file.string() + ": queries[0]: both \"goal\" and \"goal_point\" given"), std::string::npos)
      << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  fs::remove(file);
}

TEST(ArmCommand, TheOldNameRunsPlanAndSaysSo) {
  const CliRun old = run_polyplan("arm " + arm_file("two_link_points.json") + " --method grid --query easy");
  const CliRun now = run_polyplan("plan " + arm_file("two_link_points.json") + " --planner grid --query easy");
  ASSERT_EQ(old.exit_code, 0) << old.err;
  ASSERT_EQ(now.exit_code, 0) << now.err;
  EXPECT_EQ(old.out, now.out);
  EXPECT_NE(old.err.find("note: polyplan arm is polyplan plan now"), std::string::npos) << old.err;
  EXPECT_EQ(now.err, "");
}

}  // namespace
