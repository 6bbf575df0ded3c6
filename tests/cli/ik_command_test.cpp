// polyplan ik, run as a user runs it: the two-link arm of two_link_points.json (links 5 and 5)
// reaches (6, 4) with both elbows, the hand checked here by forward kinematics; (6, 8) is 10
// away, exactly its reach: one solution; beyond it none, said; the six-link arm of the forest
// (links 0.75) with an orientation: several free solutions; bad targets are one line and exit 2.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace polyplan::test;

namespace {

// The hand of a two-link arm with links 5 and 5.
std::pair<double, double> hand(const nlohmann::json& angles) {
  double x = 0, y = 0, heading = 0;
  for (const auto& a : angles) heading += a.get<double>(), x += 5 * std::cos(heading), y += 5 * std::sin(heading);
  return {x, y};
}

}  // namespace

TEST(Ik, TwoLinksReachAPointWithBothElbowsAndTheirReachWithOne) {
  const CliRun run = run_polyplan("ik " + arm_file("two_link_points.json") + " --target 6,4 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_TRUE(j["found"]);
  ASSERT_EQ(j["solutions"].size(), 2u);
  for (const auto& s : j["solutions"]) {
    const auto [x, y] = hand(s["angles"]);
    EXPECT_NEAR(x, 6, 1e-12);
    EXPECT_NEAR(y, 4, 1e-12);
    EXPECT_LT(s["error"].get<double>(), 1e-12);
  }
  const auto edge =
      nlohmann::json::parse(run_polyplan("ik " + arm_file("two_link_points.json") + " --target 6,8 --json -").out);
  EXPECT_EQ(edge["solutions"].size(), 1u);
  const CliRun beyond = run_polyplan("ik " + arm_file("two_link_points.json") + " --target 6,8.01");
  EXPECT_EQ(beyond.exit_code, 0);
  EXPECT_NE(beyond.out.find("no solution (the target is farther from the base than the two links reach"),
            std::string::npos)
      << beyond.out;
}

TEST(Ik, SixLinksWithAnOrientationAndCollisionFreeSolutions) {
  const std::string svg = (std::filesystem::temp_directory_path() / "polyplan_ik_test.svg").string();
  const CliRun run =
      run_polyplan("ik " + arm_file("six_link_forest.json") +
                   " --target -1.2,-0.8 --orientation 30 --all --collision-free --json - --svg '" + svg + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_TRUE(j["found"]);
  EXPECT_GE(j["solutions"].size(), 2u);
  {
    for (const auto& s : j["solutions"]) {
      EXPECT_TRUE(s["free"]);
      EXPECT_LE(s["error"].get<double>(), 1e-9);
      double sum = 0;
      for (const auto& a : s["angles"]) sum += a.get<double>();
      EXPECT_NEAR(std::remainder(sum - 30 * M_PI / 180, 2 * M_PI), 0, 1e-9);
    }
  }
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
}

TEST(Ik, BadTargetsAreOneLineAndExitTwo) {
  for (const char* target : {"1", "1,2,3", "a,b"}) {
    const CliRun run = run_polyplan("ik " + arm_file("two_link_points.json") + " --target " + target);
    EXPECT_EQ(run.exit_code, 2) << target;
    EXPECT_NE(run.err.find("--target"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
}
