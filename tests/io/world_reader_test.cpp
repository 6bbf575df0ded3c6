// parse_world and read_world (io/world_reader.cpp): every field read exactly from its text.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/io/world_reader.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::input_error_of;
using polyplan::test::pt;
using polyplan::test::world_from;

TEST(WorldReader, ReadsEveryFieldExactly) {
  std::vector<std::string> warnings;
  const World w = parse_world(R"({
    "bounds": [0, 0, 10.5, "21/2"],
    "obstacles": [[[1, 1], [2, 1], [2, 2]],
                  {"outer": [[3, 3], [6, 3], [6, 6], [3, 6]], "holes": [[[4, 4], [5, 4], [5, 5], [4, 5]]]}],
    "robot": {"parts": [[[0, 0], [0.1, 0], [0, 0.1]]]},
    "start": [0.3, 0.3], "goal": [9, 9],
    "queries": [{"start": [1e-1, 5], "goal": [7, 8]}],
    "colour": "red"
  })", "w.json", &warnings);
  ASSERT_TRUE(w.bounds);
  EXPECT_EQ(w.bounds->xmax, w.bounds->ymax);
  EXPECT_EQ(w.obstacles.size(), 2u);
  EXPECT_EQ(w.obstacles[1].holes.size(), 1u);
  EXPECT_EQ(w.robot.parts[0][1].x, Rational(1, 10));
  ASSERT_EQ(w.queries.size(), 2u);
  EXPECT_EQ(w.queries[0].start.x, Rational(3, 10));
  EXPECT_EQ(w.queries[1].start.x, Rational(1, 10));
  EXPECT_EQ(w.queries[1].name, "queries[0]");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("unknown field \"colour\""), std::string::npos);
}

TEST(WorldReader, ValidatesWhatItReads) {
  // The geometry is checked by validate_world (tests/geometry/world_validation_test.cpp); the
  // reader names its file and orients what it returns.
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [[[0, 0], [2, 2], [2, 0], [0, 2]]]})"); }),
            "test.json: obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 2] crosses edge 2 [2, 0]-[0, 2]");
  const World w = world_from(R"({"obstacles": [[[0, 0], [0, 1], [1, 1], [1, 0]]]})");
  EXPECT_EQ(w.obstacles[0].outer, (Ring{pt("1", "0"), pt("1", "1"), pt("0", "1"), pt("0", "0")}));
}

TEST(WorldReader, RobotWithoutPartsIsAnError) {
  // A point robot leaves out "robot"; an empty list of parts is a mistake, not a point robot.
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [], "robot": {"parts": []}})"); }),
            "test.json: robot.parts: empty: a robot needs at least one part (leave out \"robot\" for a point robot)");
  EXPECT_TRUE(world_from(R"({"obstacles": []})").robot.is_point());
}

TEST(WorldReader, ReadsWktObstaclesBesideTheWorldFile) {
  // data/worlds/wkt_obstacles.json names "wkt_obstacles.wkt", relative to its own folder.
  const World w = read_world(polyplan::test::data_file("worlds/wkt_obstacles.json"));
  ASSERT_EQ(w.obstacles.size(), 3u);
  EXPECT_EQ(w.obstacle_names, (std::vector<std::string>{"wkt_obstacles.wkt polygon 0", "wkt_obstacles.wkt polygon 1",
                                                         "wkt_obstacles.wkt polygon 2"}));
  EXPECT_EQ(w.queries.size(), 2u);
  EXPECT_EQ(w.queries[1].start, pt("7", "3"));
}

TEST(WorldReader, ReadsAPathFile) {
  EXPECT_EQ(read_path(std::string(POLYPLAN_SOURCE_DIR) + "/tests/data/paths/touching_corners_touch_and_back.json"),
            (std::vector<ExactPoint>{pt("1", "1"), pt("2", "2"), pt("1", "1.5")}));
}
