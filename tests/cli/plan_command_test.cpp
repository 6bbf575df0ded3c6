// polyplan plan, run as a user runs it: docs/design.md's JSON with exact paths, every search, every
// registered planner by --planner (and --roadmap), options by --option and --NAME, the picture.
#include "cli_runner.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace polyplan::test;
namespace fs = std::filesystem;

TEST(Plan, PrintsDesignsJsonWithExactPath) {
  const CliRun run = run_polyplan("plan " + world("decimal.json") + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto plans = nlohmann::json::parse(run.out);
  ASSERT_TRUE(plans.is_array());  // start/goal and one query
  ASSERT_EQ(plans.size(), 2u);
  const auto& first = plans[0];
  EXPECT_TRUE(first["found"].get<bool>());
  EXPECT_DOUBLE_EQ(first["length"].get<double>(), std::sqrt(117.0));
  EXPECT_EQ(first["path_exact"][0], nlohmann::json::array({"7/10", "23/10"}));
  EXPECT_EQ(first["path_exact"].back(), nlohmann::json::array({"97/10", "83/10"}));
  EXPECT_EQ(first["path"][0][0].get<double>(), 0.7);
  EXPECT_EQ(first["roadmap"]["kind"], "visibility");
  EXPECT_EQ(first["search"]["algorithm"], "astar");
}

TEST(Plan, OneQueryIsAnObjectAndNoPathIsAnAnswer) {
  const CliRun run = run_polyplan("plan " + world("touching_corners.json") + " --json -");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto plan = nlohmann::json::parse(run.out);
  ASSERT_TRUE(plan.is_object());
  EXPECT_FALSE(plan["found"].get<bool>());
  EXPECT_TRUE(plan["length"].is_null());
}

TEST(Plan, EverySearchAndTheFullGraph) {
  for (const char* search : {"astar", "dijkstra", "bfs", "dfs", "greedy", "wastar --weight 2"}) {
    SCOPED_TRACE(search);
    const CliRun run =
        run_polyplan("plan " + world("maze.json") + " --roadmap visibility-full --search " + search + " --json -");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto plan = nlohmann::json::parse(run.out);
    EXPECT_TRUE(plan["found"].get<bool>());
    EXPECT_EQ(plan["roadmap"]["kind"], "visibility-full");
    EXPECT_EQ(plan["search"]["algorithm"], std::string(search).substr(0, std::string(search).find(' ')));
  }
  EXPECT_EQ(run_polyplan("plan " + world("maze.json") + " --search teleport").exit_code, 2);
  EXPECT_EQ(run_polyplan("plan " + world("maze.json") + " --search wastar --weight 0.5").exit_code, 2);
}

TEST(Plan, DrawsRoadmapAndPath) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_plan.svg";
  const CliRun run = run_polyplan("plan " + world("seed004.json") + " --svg '" + svg.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("supporting bitangents"), std::string::npos);  // the visibility graph's edges, by kind
  EXPECT_NE(picture.find("path"), std::string::npos);
  fs::remove(svg);
}

TEST(Plan, EveryRegisteredPlannerAnswersByNameAndRoadmapIsAnAlias) {
  const CliRun planners = run_polyplan("planners --json -");
  ASSERT_EQ(planners.exit_code, 0) << planners.err;
  const auto spaces = nlohmann::json::parse(planners.out);
  std::size_t answered = 0;
  for (const auto& planner : spaces[0]["planners"]) {
    const std::string name = planner["name"];
    SCOPED_TRACE(name);
    for (const char* flag : {"--planner", "--roadmap"}) {
      const CliRun run = run_polyplan("plan " + world("maze.json") + " " + flag + " " + name + " --json -");
      ASSERT_EQ(run.exit_code, 0) << run.err;
      const auto plan = nlohmann::json::parse(run.out);
      EXPECT_EQ(plan["roadmap"]["kind"], name);
      if (name ==
          "potential-field") {  // a reactive planner that stops in one of the maze's local minima: an answer, no path
        EXPECT_EQ(plan["status"], "local_minimum") << plan.dump();
        continue;
      }
      if (name == "navigation-function") {  // the maze's walls are no discs
        EXPECT_EQ(plan["why_not"].get<std::string>().rfind("not a sphere world", 0), 0u) << plan.dump();
        continue;
      }
      ASSERT_TRUE(plan["found"].get<bool>()) << plan.dump();
      EXPECT_TRUE(plan["certified"].get<bool>());
      EXPECT_EQ(plan["path_exact"][0], nlohmann::json::array({"1", "1"}));
      EXPECT_EQ(plan["path_exact"].back(), nlohmann::json::array({"19", "19"}));
    }
    ++answered;
  }
  EXPECT_GE(answered, 3u);
}

TEST(Plan, OptionsBySpelledOutAssignmentOrByTheirOwnFlag) {
  const CliRun flag = run_polyplan("plan " + world("sphere_world_polygons.json") +
                                   " --planner raster --resolution 40 --search dijkstra --json -");
  const CliRun option = run_polyplan("plan " + world("sphere_world_polygons.json") +
                                     " --planner raster --option resolution=40 "
                                     "--option search=dijkstra --json -");
  ASSERT_EQ(flag.exit_code, 0) << flag.err;
  ASSERT_EQ(option.exit_code, 0) << option.err;
  const auto a = nlohmann::json::parse(flag.out), b = nlohmann::json::parse(option.out);
  ASSERT_EQ(a.size(), 10u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["raster"]["cells_per_axis"], 40);
    EXPECT_EQ(a[i]["search"]["algorithm"], "dijkstra");
    EXPECT_EQ(a[i]["path_exact"], b[i]["path_exact"]);
    EXPECT_EQ(a[i]["query"], "queries[" + std::to_string(i) + "]");
  }
}

TEST(Plan, BadPlannersAndOptionsAreOneLineNamingThem) {
  struct Case {
    std::string arguments, message;
  } cases[] = {
      {"--planner teleport",
       "--planner: unknown planner \"teleport\" (visibility, visibility-full, raster, trapezoid, voronoi, gvd-grid, "
       "dstar-lite, lpastar, repeated-astar, potential-field, navigation-function, bug1, bug2, tangent-bug, homotopy, "
       "tether, prm, lazyprm, rrt, rrtstar, rrtconnect, rotation, hybrid-astar, car-rrt, grid)"},
      {"--roadmap teleport", "--planner: unknown planner \"teleport\""},
      {"--resolution 40",
       "--resolution: the planner visibility has no option resolution (its options: search weight reopen)"},
      {"--planner raster --resolution forty", "planner raster: option resolution=forty: expected a whole number"},
      {"--option resolution", "--option resolution: expected NAME=VALUE"},
      {"--option search=bfs --search astar", "--search: the option search is given twice"},
      {"--planner raster --connectivity 6", "planner raster: option connectivity=6: expected one of 8|4"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments);
    const CliRun run = run_polyplan("plan " + world("maze.json") + " " + c.arguments);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
  }
}

TEST(Plan, RotationPrintsPosesWithExactRotationsAndDrawsTheStrobe) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_plan_rotation.svg";
  const CliRun run = run_polyplan("plan " + world("rotation_piano.json") +
                                  " --planner rotation --rotation-step 10 --json - --svg " + svg.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto plan = nlohmann::json::parse(run.out);
  EXPECT_TRUE(plan["found"].get<bool>());
  EXPECT_TRUE(plan["certified"].get<bool>());
  EXPECT_EQ(plan["path"][0], nlohmann::json::array({8.0, 10.0, 0.0}));
  EXPECT_EQ(plan["path"].back(), nlohmann::json::array({30.0, 32.0, 90.0}));
  EXPECT_EQ(plan["path_exact"].back(), nlohmann::json::array({"30", "32", "1", "0"}));  // 90° exactly: sin 1, cos 0
  EXPECT_NEAR(plan["rotation"].get<double>(), 90, 1e-6);
  EXPECT_EQ(plan["layers"]["count"], 36);
  EXPECT_GT(plan["turn_layers"]["used"].get<int>(), 0);
  EXPECT_LE(plan["layers"]["max_error_radians"].get<double>(), 1e-10);
  const std::string picture = slurp(svg);
  for (const char* text : {"turns on the spot", "orientation along the path", "robot at goal"})
    EXPECT_NE(picture.find(text), std::string::npos) << text;
  fs::remove(svg);
}

TEST(Plan, ATurningWorldNeedsTheRotationPlannerAndBadAnglesAreNamed) {
  const CliRun translating = run_polyplan("plan " + world("rotation_piano.json") + " --planner visibility");
  EXPECT_EQ(translating.exit_code, 2);
  EXPECT_NE(translating.err.find("use --planner rotation"), std::string::npos) << translating.err;
  const CliRun step = run_polyplan("plan " + world("rotation_piano.json") + " --planner rotation --rotation-step 7");
  EXPECT_EQ(step.exit_code, 2);
  EXPECT_NE(step.err.find("rotation-step 7° does not divide the range [0°, 360°]"), std::string::npos) << step.err;
  const fs::path bad = fs::temp_directory_path() / "polyplan_bad_theta.json";
  std::ofstream(bad) << R"({"obstacles": [], "start": [0, 0, "sixty"], "goal": [1, 1, 0]})";
  const CliRun angle = run_polyplan("plan " + bad.string() + " --planner rotation");
  EXPECT_EQ(angle.exit_code, 2);
  EXPECT_NE(angle.err.find("start[2] (theta, degrees)"), std::string::npos) << angle.err;
  std::ofstream(bad) << R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 4], [4, 4]]],
                           "robot": {"parts": [[[-3, -0.5], [3, -0.5], [3, 0.5], [-3, 0.5]]]},
                           "start": [5, 7, 0], "goal": [5, 6.5, 90]})";
  const CliRun upright = run_polyplan("plan " + bad.string() + " --planner rotation");
  EXPECT_EQ(upright.exit_code, 2);
  EXPECT_NE(upright.err.find("goal [5, 13/2, 90°]: not free: the robot overlaps obstacles[0]"), std::string::npos)
      << upright.err;
  fs::remove(bad);
}

TEST(Plan, TheRasterPictureShowsItsCellsAndTheTextSaysWhatWasSearched) {
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_raster.svg";
  const CliRun run =
      run_polyplan("plan " + world("seed004.json") + " --planner raster --resolution 50 --svg '" + svg.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("start/goal: length "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("astar expanded "), std::string::npos) << run.out;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("blocked cells"), std::string::npos);
  EXPECT_NE(picture.find("grid graph vertices"), std::string::npos);
  EXPECT_NE(picture.find("expanded by the search"), std::string::npos);
  fs::remove(svg);
}

TEST(Plan, ACarWorldIsRefusedByEveryPlannerThatDoesNotSteer) {
  // The translating and rotating planners would ignore the turning radius: a car is refused,
  // not planned as if it could turn on the spot.
  const fs::path world = fs::temp_directory_path() / "polyplan_cli_test_car.json";
  std::ofstream(world) << R"({"bounds": [0, 0, 20, 10], "obstacles": [],
    "robot": {"parts": [[[-1, -1], [3, -1], [3, 1], [-1, 1]]], "car": {"turning_radius": 2, "reverse": true}},
    "start": [5, 5, 0], "goal": [15, 5, 180]})";
  for (const char* planner : {"visibility", "rotation", "trapezoid"}) {
    const CliRun run = run_polyplan("plan '" + world.string() + "' --planner " + planner);
    EXPECT_EQ(run.exit_code, 2) << planner;
    EXPECT_NE(run.err.find("robot.car: the robot steers like a car, and the planner " + std::string(planner) +
                           " neither steers nor keeps to a turning radius"),
              std::string::npos)
        << run.err;
  }
  // The C-space of the car's body, as it is drawn, is still the translating robot's.
  EXPECT_EQ(run_polyplan("cspace '" + world.string() + "'").exit_code, 0);
  fs::remove(world);
}

TEST(Plan, ACarWorldIsPlannedByHybridAStarByDefaultAndByRrtWhenAsked) {
  // The U-turn in a corridor narrower than two turning radii: the car must reverse.
  for (const std::string planner : {"", " --planner rrt", " --planner rrtconnect --iterations 3000"}) {
    SCOPED_TRACE(planner);
    const CliRun run = run_polyplan("plan " + world("car_u_turn.json") + planner + " --json -");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto plan = nlohmann::json::parse(run.out);
    if (planner.empty()) EXPECT_EQ(plan["search"]["algorithm"], "hybrid A*");
    else EXPECT_EQ(plan["roadmap"]["kind"], planner.substr(11, planner.find(' ', 11) - 11));
    ASSERT_TRUE(plan["found"].get<bool>());
    EXPECT_EQ(plan["certified_by"].get<std::string>().rfind("swept-body enclosures", 0), 0u);
    ASSERT_EQ(plan["segments"].size() + 1, plan["path"].size());
    double length = 0;
    int reversing = 0;
    for (const auto& s : plan["segments"]) {
      length += s["length"].get<double>();
      reversing += s["gear"] == -1;
    }
    EXPECT_NEAR(length, plan["length"].get<double>(), 1e-9);
    EXPECT_GT(reversing, 0) << "a U-turn narrower than 2R needs reverse";
    EXPECT_GE(plan["gear_changes"].get<int>(), 1);
    EXPECT_EQ(plan["path"][0], nlohmann::json::array({6, 2.5, 0}));
  }
  const fs::path svg = fs::temp_directory_path() / "polyplan_cli_test_car.svg";
  const CliRun drawn = run_polyplan("plan " + world("car_u_turn.json") + " --planner rrt --svg '" + svg.string() + "'");
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_NE(drawn.out.find("gear change"), std::string::npos) << drawn.out;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("tree ("), std::string::npos) << "the tree is drawn with its curves";
  fs::remove(svg);
}
