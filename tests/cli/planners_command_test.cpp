// polyplan planners, run as a user runs it: every planner of every registry, with its one-line
// description and its options, as text and as JSON.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

using namespace polyplan::test;

TEST(Planners, ListsEveryPlannerOfEverySpaceWithOptionsAndDefaults) {
  const CliRun run = run_polyplan("planners --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto spaces = nlohmann::json::parse(run.out);
  ASSERT_EQ(spaces.size(), 5u);
  EXPECT_EQ(spaces[4]["command"], "polyplan plan WORLD.json --planner NAME");  // discs and walls
  EXPECT_EQ(spaces[4]["planners"][0]["name"], "visibility");                   // the tangent visibility graph
  EXPECT_EQ(spaces[0]["command"], "polyplan plan WORLD.json --planner NAME");
  EXPECT_EQ(spaces[1]["command"], "polyplan plan WORLD.json --planner NAME");
  EXPECT_EQ(spaces[1]["planners"][0]["name"], "rotation");
  EXPECT_EQ(spaces[1]["planners"][0]["options"][0]["name"], "rotation-step");
  EXPECT_EQ(spaces[1]["planners"][0]["options"][0]["default"], "5");
  EXPECT_EQ(spaces[2]["command"], "polyplan plan CAR_WORLD.json --planner NAME");
  std::vector<std::string> car_names;
  for (const auto& p : spaces[2]["planners"]) car_names.push_back(p["name"]);
  EXPECT_EQ(car_names,
            (std::vector<std::string>{"hybrid-astar", "car-rrt", "prm", "lazyprm", "rrt", "rrtstar", "rrtconnect"}));
  EXPECT_EQ(spaces[3]["command"], "polyplan plan ARM.json --planner NAME");
  std::vector<std::string> names;
  for (const auto& p : spaces[0]["planners"]) names.push_back(p["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"visibility",
                                             "visibility-full",
                                             "raster",
                                             "trapezoid",
                                             "voronoi",
                                             "gvd-grid",
                                             "dstar-lite",
                                             "lpastar",
                                             "repeated-astar",
                                             "potential-field",
                                             "navigation-function",
                                             "bug1",
                                             "bug2",
                                             "tangent-bug",
                                             "homotopy",
                                             "tether",
                                             "prm",
                                             "lazyprm",
                                             "rrt",
                                             "rrtstar",
                                             "rrtconnect"}));
  std::vector<std::string> arm_names;
  for (const auto& p : spaces[3]["planners"]) arm_names.push_back(p["name"]);
  EXPECT_EQ(arm_names, (std::vector<std::string>{"grid", "prm", "lazyprm", "rrt", "rrtstar", "rrtconnect"}));
  const auto& grid = spaces[3]["planners"][0];
  EXPECT_EQ(grid["name"], "grid");
  EXPECT_EQ(grid["options"][0]["name"], "resolution");
  EXPECT_EQ(grid["options"][0]["default"], "5");
  for (const auto& space : spaces)
    for (const auto& p : space["planners"]) {
      EXPECT_FALSE(p["description"].get<std::string>().empty()) << p["name"];
      for (const auto& o : p["options"]) EXPECT_FALSE(o["description"].get<std::string>().empty()) << o["name"];
    }
}

TEST(Planners, TextNamesEveryPlannerAndHowToSetAnOption) {
  const CliRun run = run_polyplan("planners");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* text : {"visibility-full", "raster", "grid", "--resolution", "--no-", "--option NAME=VALUE"})
    EXPECT_NE(run.out.find(text), std::string::npos) << text << " in\n" << run.out;
}
