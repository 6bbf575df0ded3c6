// io/arm_reader: arm files, every field and every bad input with its one-line message.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/arm_reader.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace polyplan;

namespace {

// Writes `text` to a fresh file in a temporary folder and returns its path.
class ArmFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("polyplan_arm_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // The InputError message for a bad file, or "" when it was accepted.
  std::string error_for(const std::string& name, const std::string& text) const {
    const std::string path = write(name, text);
    try {
      std::vector<std::string> warnings;
      read_arm_problem(path, &warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
};

}  // namespace

TEST_F(ArmFiles, ReadsEveryField) {
  std::vector<std::string> warnings;
  const ArmProblem p = read_arm_problem(write("arm.json", R"({
    "links": [1.5, "1/2"], "link_width": 0.1, "self_collision": true,
    "obstacles": [[[0, 3], [0.1, 3], [0, 3.1]], {"outer": [[5, 5], [6, 5], [6, 6], [5, 6]]}],
    "points": [[1, 2], [-0.5, 1e-1]],
    "start": [0, 7], "goal": [1, -1],
    "queries": [{"name": "easy", "start": [0, 0], "goal": [1, 1]}, {"start": [2, 2], "goal": [3, 3], "speed": 2}],
    "colour": "red"
  })"),
                                        &warnings);
  EXPECT_EQ(p.source, (dir_ / "arm.json").string());
  EXPECT_EQ(p.arm.links, (std::vector<double>{1.5, 0.5}));
  EXPECT_EQ(p.arm.link_width, 0.1);
  EXPECT_TRUE(p.arm.self_collision);
  ASSERT_EQ(p.obstacles.size(), 2u);
  EXPECT_EQ(p.obstacles[0].outer[1].x, Rational(1, 10));  // exact, counter-clockwise as given
  EXPECT_EQ(p.obstacle_names[1], "obstacles[1]");
  ASSERT_EQ(p.points.size(), 2u);
  EXPECT_EQ(p.points[1], Eigen::Vector2d(-0.5, 0.1));
  ASSERT_EQ(p.queries.size(), 3u);
  EXPECT_EQ(p.queries[0].name, "start/goal");
  EXPECT_EQ(p.queries[0].start, (JointAngles{0, 7}));  // not normalised: planners do that
  EXPECT_EQ(p.queries[1].name, "easy");
  EXPECT_EQ(p.queries[2].name, "queries[1]");
  EXPECT_EQ(p.queries[2].goal, (JointAngles{3, 3}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("arm: unknown field \"colour\" ignored"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("queries[1]: unknown field \"speed\" ignored"), std::string::npos) << warnings[1];
}

TEST_F(ArmFiles, ReadsGoalPointsAndJointLimits) {
  std::vector<std::string> warnings;
  const ArmProblem p = read_arm_problem(write("reach.json", R"({
    "links": [1, 1, 1], "limits": [[-1.5, 1.5], ["-1/2", 3], [0, 0]],
    "start": [0, 0, 0], "goal_point": [1.5, "1/3"], "goal_orientation": 0.1,
    "queries": [{"name": "point", "start": [1, 1, 1], "goal_point": [-2, 0.5]},
                {"name": "angles", "start": [1, 1, 1], "goal": [0, 0, 0]}]
  })"),
                                        &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.arm.limits, (std::vector<std::pair<double, double>>{{-1.5, 1.5}, {-0.5, 3}, {0, 0}}));
  ASSERT_EQ(p.queries.size(), 3u);
  ASSERT_TRUE(p.queries[0].goal_point.has_value());
  EXPECT_TRUE(p.queries[0].goal.empty());
  EXPECT_EQ(p.queries[0].goal_point->point, Eigen::Vector2d(1.5, 1.0 / 3));  // the double nearest 1/3
  EXPECT_EQ(p.queries[0].goal_point->orientation, 0.1);
  EXPECT_EQ(p.queries[0].goal_point->exact_point, (ExactPoint{Rational(3, 2), Rational(1, 3)}));  // as written
  EXPECT_EQ(p.queries[1].goal_point,
            (WorkspaceGoal{{-2, 0.5}, std::nullopt, ExactPoint{Rational(-2), Rational(1, 2)}}));
  EXPECT_FALSE(p.queries[2].goal_point.has_value());
  EXPECT_EQ(p.queries[2].goal, (JointAngles{0, 0, 0}));
}

TEST_F(ArmFiles, WarningsGoToStderrWhenNotCollected) {
  const std::string path = write("arm.json", R"({"links": [1], "colour": "red"})");
  ::testing::internal::CaptureStderr();
  read_arm_problem(path);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err, "warning: " + path + ": arm: unknown field \"colour\" ignored\n");
}

TEST_F(ArmFiles, EachBadFileNamesTheFileTheObjectAndTheProblem) {
  struct Case {
    const char* name;
    const char* text;
    const char* message;  // after "<path>: "
  };
  const std::vector<Case> cases = {
      {"no_links", R"({"points": []})", "arm: missing field \"links\" (the link lengths, e.g. [1, 1])"},
      {"empty_links", R"({"links": []})", "links: expected at least one link length, got []"},
      {"links_not_a_list", R"({"links": 5})", "links: expected a list of link lengths, got 5"},
      {"negative_link", R"({"links": [1, -2.5]})", "links[1]: a link length must be positive, got -2.5"},
      {"zero_link", R"({"links": [0, 1]})", "links[0]: a link length must be positive, got 0"},
      {"infinite_link", R"({"links": ["1e999"]})",
       "links[0]: overflows the supported range (0 or a magnitude from 1e-100 to 1e100): \"1e999\""},
      {"underflowing_link", R"({"links": [1e-400]})",
       "links[0]: underflows the supported range (0 or a magnitude from 1e-100 to 1e100): \"1e-400\""},
      {"link_not_a_number", R"({"links": [true]})", "links[0]: not a number: true"},
      {"negative_width", R"({"links": [1], "link_width": -0.5})",
       "link_width: must be 0 (segments) or positive, got -0.5"},
      {"self_collision_string", R"({"links": [1], "self_collision": "yes"})",
       "self_collision: expected true or false, got \"yes\""},
      {"start_too_short", R"({"links": [1, 1], "start": [0], "goal": [0, 0]})",
       "start: expected 2 joint angles (one per link, radians), got 1"},
      {"query_goal_too_long", R"({"links": [1], "queries": [{"start": [0], "goal": [0, 1]}]})",
       "queries[0].goal: expected 1 joint angles (one per link, radians), got 2"},
      {"angle_not_finite", R"({"links": [1, 1], "start": [0, "-1e999"], "goal": [0, 0]})",
       "start[1]: overflows the supported range (0 or a magnitude from 1e-100 to 1e100): \"-1e999\""},
      {"angle_not_a_number", R"({"links": [1], "start": ["abc"], "goal": [0]})", "start[0]: not a number: \"abc\""},
      {"goal_missing", R"({"links": [1], "start": [0]})",
       "arm: missing field \"goal\" or \"goal_point\" (start is given)"},
      {"start_missing", R"({"links": [1], "goal_point": [0, 1]})",
       "arm: missing field \"start\" (goal_point is given)"},
      {"goal_and_goal_point", R"({"links": [1, 1], "start": [0, 0], "goal": [1, 1], "goal_point": [1, 1]})",
       "arm: both \"goal\" and \"goal_point\" given: a query's goal is joint angles or the hand at a point, not both"},
      {"query_goal_and_goal_point", R"({"links": [1], "queries": [{"start": [0], "goal": [1], "goal_point": [0, 1]}]})",
       "queries[0]: both \"goal\" and \"goal_point\" given: a query's goal is joint angles or the hand at a point, not "
       "both"},
      {"query_goal_missing", R"({"links": [1], "queries": [{"name": "q", "start": [0]}]})",
       "queries[0]: missing field \"goal\" (or \"goal_point\")"},
      {"orientation_alone", R"({"links": [1, 1], "start": [0, 0], "goal": [1, 1], "goal_orientation": 1})",
       "goal_orientation: given without \"goal_point\" (it is the hand's orientation at that point)"},
      {"orientation_without_query", R"({"links": [1], "goal_orientation": 1})",
       "goal_orientation: given without \"goal_point\" (it is the hand's orientation at that point)"},
      {"query_orientation_alone", R"({"links": [1], "queries": [{"start": [0], "goal": [0], "goal_orientation": 1}]})",
       "queries[0].goal_orientation: given without \"goal_point\" (it is the hand's orientation at that point)"},
      {"goal_point_three_numbers", R"({"links": [1], "start": [0], "goal_point": [1, 2, 3]})",
       "goal_point: expected a point [x, y], got [1,2,3]"},
      {"goal_point_text", R"({"links": [1], "queries": [{"start": [0], "goal_point": [1, "far"]}]})",
       "queries[0].goal_point[1]: not a number: \"far\""},
      {"goal_point_overflows", R"({"links": [1], "start": [0], "goal_point": [1, "1e999"]})",
       "goal_point[1]: overflows the supported range (0 or a magnitude from 1e-100 to 1e100): \"1e999\""},
      {"goal_orientation_text", R"({"links": [1], "start": [0], "goal_point": [1, 0], "goal_orientation": "up"})",
       "goal_orientation: not a number: \"up\""},
      {"limits_too_few", R"({"links": [1, 1], "limits": [[0, 1]]})",
       "limits: expected 2 joint limits [lo, hi] (one per link, radians), got 1"},
      {"limits_not_a_list", R"({"links": [1], "limits": 3})",
       "limits: expected a list of 1 joint limits [lo, hi] (one per link, radians), got 3"},
      {"limit_three_numbers", R"({"links": [1], "limits": [[0, 1, 2]]})",
       "limits[0]: expected [lo, hi] (radians), got [0,1,2]"},
      {"limit_not_a_pair", R"({"links": [1], "limits": [1]})", "limits[0]: expected [lo, hi] (radians), got 1"},
      {"limit_inverted", R"({"links": [1, 1], "limits": [[0, 1], [2, 1.5]]})",
       "limits[1]: lo 2 is above hi 1.5 (radians, [lo, hi])"},
      {"limit_infinite", R"({"links": [1], "limits": [["-1e999", 0]]})",
       "limits[0][0]: overflows the supported range (0 or a magnitude from 1e-100 to 1e100): \"-1e999\""},
      {"query_start_missing", R"({"links": [1], "queries": [{"goal": [0]}]})", "queries[0]: missing field \"start\""},
      {"query_name_twice",
       R"({"links": [1], "queries": [{"name": "a", "start": [0], "goal": [0]}, {"name": "a", "start": [0], )"
       R"("goal": [0]}]})",
       "queries[1].name: the query name \"a\" is used twice"},
      {"point_three_numbers", R"({"links": [1], "points": [[0, 0], [1, 2, 3]]})",
       "points[1]: expected a point [x, y], got [1,2,3]"},
      {"point_coordinate_text", R"({"links": [1], "points": [[0, "x"]]})", "points[0][1]: not a number: \"x\""},
      {"points_not_a_list", R"({"links": [1], "points": {"x": 1}})",
       "points: expected a list of points [[x, y], ...], got {\"x\":1}"},
      {"obstacle_bowtie", R"({"links": [1], "obstacles": [[[0, 0], [2, 2], [2, 0], [0, 2]]]})",
       "obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 2] crosses edge 2 [2, 0]-[0, 2]"},
      {"top_level_array", R"([1, 2])", "arm: expected a JSON object at the top level"},
  };
  for (const Case& c : cases) {
    const std::string path = (dir_ / (std::string(c.name) + ".json")).string();
    const std::string message = error_for(std::string(c.name) + ".json", c.text);
    EXPECT_EQ(message, path + ": " + c.message) << c.name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
  }
  EXPECT_EQ(error_for("syntax.json", R"({"links": [1,]})")
                .rfind((dir_ / "syntax.json").string() + ": invalid JSON at byte", 0),
            0u);
  EXPECT_EQ(error_for("huge.json", R"({"links": [1, 1e999]})"),
            (dir_ / "huge.json").string() +
                ": links[1]: number at byte 19 overflows the supported range (0 or a magnitude from 1e-100 to 1e100)");
  try {
    read_arm_problem((dir_ / "missing.json").string());
    FAIL() << "read a file that does not exist";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "missing.json").string() + ": cannot open file");
  }
}
