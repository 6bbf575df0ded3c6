// polyplan potential, run as a user runs it: the course's planning problem set's wall has one critical point, the
// minimum at (−0.68233, 0); the U-shaped trap's minimum lies above its bottom wall; the picture; one-line errors for a
// bad box and bad weights.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>

using namespace polyplan::test;

TEST(Potential, SeedTwosWallHasOneMinimum) {
  const CliRun run = run_polyplan("potential " + world("seed002_wall.json") + " --box=-3,-3,3,3 --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["critical_points"].size(), 1u);
  const auto& p = j["critical_points"][0];
  EXPECT_EQ(p["kind"], "minimum");
  EXPECT_NEAR(p["at"][0].get<double>(), -0.68233, 1e-5);
  EXPECT_NEAR(p["at"][1].get<double>(), 0, 1e-9);
  EXPECT_GT(p["eigenvalues"][0].get<double>(), 0);
  EXPECT_EQ(j["goal"], nlohmann::json::array({2.0, 0.0}));
  EXPECT_EQ(j["parameters"]["q_star"], 1.0);
}

TEST(Potential, TheTrapsMinimumAndThePicture) {
  const std::string svg = (std::filesystem::temp_directory_path() / "polyplan_potential_test.svg").string();
  const CliRun run = run_polyplan("potential " + world("u_trap.json") + " --svg '" + svg + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("minimum at (10.000000, 7.682328)"), std::string::npos) << run.out;
  const std::string picture = slurp(svg);
  for (const char* part : {"log(1 + potential)", "contour lines", "descent direction", "minimum ("})
    EXPECT_NE(picture.find(part), std::string::npos) << part;
}

TEST(Potential, MistakesAreOneLineAndExitTwo) {
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"--box=1,2,3", "--box 1,2,3: expected XMIN,YMIN,XMAX,YMAX"},
           {"--box=3,0,1,1", "--box 3,0,1,1: expected XMIN < XMAX and YMIN < YMAX"},
           {"--box=0,0,x,1", "\"x\" is not a finite number"},
           {"--eta -1", "--eta -1: expected a number in [0, inf)"},
           {"--zeta 0", "--zeta 0: expected a number in (0, inf)"},
           {"--cells 0", "--cells 0: expected a whole number in [1, 4096]"},
           {"--cells x", "--cells x: expected a whole number"}}) {
    SCOPED_TRACE(arguments);
    const CliRun run = run_polyplan("potential " + world("u_trap.json") + " " + arguments);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
  }
}
