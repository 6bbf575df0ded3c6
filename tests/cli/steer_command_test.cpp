// polyplan steer, run as a user runs it: the shortest curve's length, word and segments as JSON
// (the segments add up to the length), its picture, and one-line errors for bad poses and radii.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace polyplan::test;

TEST(Steer, PrintsTheShortestCurveAsJson) {
  // A U-turn onto the lane 2R to the left: half a circle for Dubins.
  const CliRun dubins = run_polyplan("steer --model dubins --radius 2 --from 0,0,0 --to 0,4,180 --json -");
  ASSERT_EQ(dubins.exit_code, 0) << dubins.err;
  const auto d = nlohmann::json::parse(dubins.out);
  EXPECT_EQ(d["word"], "L");
  EXPECT_NEAR(d["length"].get<double>(), 2 * M_PI, 1e-12);
  ASSERT_EQ(d["segments"].size(), 1u);
  EXPECT_EQ(d["segments"][0]["steer"], "L");
  EXPECT_EQ(d["segments"][0]["gear"], 1);
  // Straight back: Reeds–Shepp reverses, Dubins must loop.
  const auto rs =
      nlohmann::json::parse(run_polyplan("steer --model reeds-shepp --from 0,0,0 --to -3,0,0 --json -").out);
  EXPECT_EQ(rs["word"], "S-");
  EXPECT_EQ(rs["segments"][0]["gear"], -1);
  EXPECT_DOUBLE_EQ(rs["length"].get<double>(), 3);
  const auto loop = nlohmann::json::parse(run_polyplan("steer --model dubins --from 0,0,0 --to -3,0,0 --json -").out);
  EXPECT_GT(loop["length"].get<double>(), 3 + M_PI);
  double sum = 0;
  for (const auto& s : loop["segments"]) sum += s["length"].get<double>();
  EXPECT_NEAR(sum, loop["length"].get<double>(), 1e-12);
}

TEST(Steer, DrawsTheCurve) {
  const std::string svg = (std::filesystem::temp_directory_path() / "polyplan_steer_test.svg").string();
  const CliRun run = run_polyplan("steer --model reeds-shepp --radius 2 --from 0,0,0 --to 1,4,180 --svg '" + svg + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("reeds-shepp R+L-S-L-: length 6.40629"), std::string::npos) << run.out;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("<svg"), std::string::npos);
  EXPECT_NE(picture.find("reverse"), std::string::npos);
  std::filesystem::remove(svg);
}

TEST(Steer, ListsEveryWord) {
  // Ten radii straight ahead: RLR and LRL cannot reach (their circles lie more than 4R apart).
  const CliRun text = run_polyplan("steer --from 0,0,0 --to 10,0,0 --all-words");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("dubins S: length 10\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("  RLR          infeasible\n  LRL          infeasible\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" 10  shortest\n"), std::string::npos) << text.out;
  EXPECT_EQ(std::count(text.out.begin(), text.out.end(), '\n'), 7) << text.out;

  const auto d = nlohmann::json::parse(run_polyplan("steer --from 1,2,30 --to -3,5,-120 --all-words --json -").out);
  ASSERT_EQ(d["words"].size(), 6u);
  int marked = 0;
  double least = HUGE_VAL;
  for (const auto& w : d["words"]) {
    marked += w["shortest"].get<bool>();
    if (!w["length"].is_null()) least = std::min(least, w["length"].get<double>());
    if (w["shortest"].get<bool>()) EXPECT_NEAR(w["length"].get<double>(), d["length"].get<double>(), 1e-12);
  }
  EXPECT_EQ(marked, 1);
  EXPECT_NEAR(least, d["length"].get<double>(), 1e-12);
  EXPECT_EQ(d["words"][0]["name"], "LSL");

  const auto rs = nlohmann::json::parse(
      run_polyplan("steer --model reeds-shepp --from 0,0,0 --to -3,0,0 --all-words --json -").out);
  ASSERT_EQ(rs["words"].size(), 44u);
  EXPECT_EQ(rs["words"][0]["name"], "L+S+L+");
  EXPECT_FALSE(nlohmann::json::parse(run_polyplan("steer --from 0,0,0 --to 1,1,0 --json -").out).contains("words"));
}

TEST(Steer, RefusesBadInputInOneLine) {
  const struct {
    const char* arguments;
    const char* expected;
  } cases[] = {
      {"steer --from 0,0 --to 1,1,0", "--from 0,0: expected X,Y,THETA (theta in degrees)"},
      {"steer --from 0,0,0 --to 1,y,0", "--to 1,y,0: \"y\" is not a finite number"},
      {"steer --from 0,0,nan --to 1,1,0", "is not a finite number"},
      {"steer --radius 0 --from 0,0,0 --to 1,1,0", "--radius 0: expected a number in [1e-100, 1e+100]"},
      {"steer --radius -2 --model reeds-shepp --from 0,0,0 --to 1,1,0",
       "--radius -2: expected a number in [1e-100, 1e+100]"},
      {"steer --model car --from 0,0,0 --to 1,1,0", "--model car: expected one of dubins|reeds-shepp"},
      {"steer --to 1,1,0", "--from is required"},
  };
  for (const auto& c : cases) {
    const CliRun run = run_polyplan(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << c.arguments;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << c.arguments << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
}
