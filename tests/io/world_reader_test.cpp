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
  })",
                              "w.json", &warnings);
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

namespace {

std::string repeated(const std::string& s, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += s;
  return out;
}

}  // namespace

// The limits of geometry/input_limits.hpp, each with a message naming the object.
TEST(WorldReader, NumbersOutsideTheSupportedRangeNameTheirObject) {
  const std::string range = "the supported range (0 or a magnitude from 1e-100 to 1e100)";
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [], "start": [0, 1e400], "goal": [1, 1]})"); }),
            "test.json: start[1]: number at byte 36 overflows " + range);
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [], "start": [5e307, 0], "goal": [1, 1]})"); }),
            "test.json: start[0]: overflows " + range + ": \"5e307\"");
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [], "start": [1e-200, 0], "goal": [1, 1]})"); }),
            "test.json: start[0]: underflows " + range + ": \"1e-200\"");
  const std::string digits(100000, '9');
  EXPECT_EQ(
      input_error_of([&] { world_from(R"({"obstacles": [], "start": [)" + digits + R"(, 0], "goal": [1, 1]})"); }),
      "test.json: start[0]: number at byte 100028 overflows " + range);
  EXPECT_EQ(
      input_error_of([&] { world_from(R"({"obstacles": [], "start": ["1.)" + digits + R"(", 0], "goal": [1, 1]})"); }),
      "test.json: start[0]: longer than the supported 100 characters: \"1.9999999999999999999999999999999999...");
  EXPECT_EQ(world_from(R"({"obstacles": [], "start": [1e100, 1e-100], "goal": [1, 1]})").queries[0].start.y,
            Rational(mpz_class(1), mpz_class("1" + std::string(100, '0'))));
}

TEST(WorldReader, DeepNestingIsRefusedBeforeAnythingRecurses) {
  // 55,000 levels crashed the program (the error message printed the value recursively).
  const std::string deep = std::string(55000, '[') + std::string(55000, ']');
  const std::string message = input_error_of([&] { world_from(deep); });
  EXPECT_EQ(message.rfind("test.json: [0][0][0]", 0), 0u) << message.substr(0, 200);
  EXPECT_NE(message.find("]: nested deeper than the supported 32 levels"), std::string::npos) << message.substr(0, 200);
  EXPECT_EQ(input_error_of([&] {
              world_from(R"({"obstacles": [], "robot": {"parts": [[[0, 0, )" + std::string(40, '[') + "]]]}}");
            }),
            "test.json: robot.parts[0][0][2]" + repeated("[0]", 27) + ": nested deeper than the supported 32 levels");
}

TEST(WorldReader, DuplicateKeysAreRefused) {
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [], "obstacles": [[[0, 0], [1, 0], [0, 1]]]})"); }),
            "test.json: top level: duplicate key \"obstacles\"");
  EXPECT_EQ(input_error_of([] { world_from(R"({"obstacles": [{"outer": [[0, 0], [1, 0], [0, 1]], "outer": []}]})"); }),
            "test.json: obstacles[0]: duplicate key \"outer\"");
}

TEST(WorldReader, AHugeUnknownKeyIsWarnedAboutShortly) {
  std::vector<std::string> warnings;
  parse_world(R"({"obstacles": [], ")" + std::string(20 << 20, 'k') + R"(": 1})", "test.json", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "test.json: world: unknown field \"kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk...\" ignored");
}

TEST(WorldReader, FilesThatAreNotInputsEndAtOnce) {
  EXPECT_EQ(input_error_of([] { read_world("/dev/zero"); }), "/dev/zero: larger than the supported 64 MiB");
  EXPECT_EQ(input_error_of([] { read_world(POLYPLAN_SOURCE_DIR); }),
            std::string(POLYPLAN_SOURCE_DIR) + ": is a directory, not a file");
}

TEST(WorldReader, ReadsACar) {
  const World w = world_from(R"({"obstacles": [], "robot": {"parts": [[[-1, -1], [3, -1], [3, 1], [-1, 1]]],
    "car": {"turning_radius": "5/2", "reverse": true}}, "start": [0, 0, 90], "goal": [10, 0, -90]})");
  ASSERT_TRUE(w.robot.car);
  EXPECT_EQ(w.robot.car->turning_radius, 2.5);
  EXPECT_TRUE(w.robot.car->reverse);
  EXPECT_EQ(*w.queries[0].goal_theta, -90);
  EXPECT_FALSE(
      world_from(R"({"obstacles": [], "robot": {"parts": [[[0, 0], [1, 0], [0, 1]]], "car": {"turning_radius": 1}},
    "start": [0, 0, 0], "goal": [1, 1, 0]})")
          .robot.car->reverse);
  EXPECT_FALSE(world_from(R"({"obstacles": [], "robot": {"parts": [[[0, 0], [1, 0], [0, 1]]]}})").robot.car);
}

TEST(WorldReader, BadCarsNameTheirField) {
  const std::string body = R"("parts": [[[-1, -1], [3, -1], [3, 1], [-1, 1]]])";
  const auto car_world = [&](const std::string& car, const std::string& queries) {
    return input_error_of(
        [&] { world_from(R"({"obstacles": [], "robot": {)" + body + R"(, "car": )" + car + "}, " + queries + "}"); });
  };
  const std::string poses = R"("start": [0, 0, 0], "goal": [5, 5, 90])";
  EXPECT_EQ(car_world(R"({"turning_radius": 0})", poses),
            "test.json: robot.car.turning_radius: 0: expected a positive number");
  EXPECT_EQ(car_world(R"({"turning_radius": -2})", poses),
            "test.json: robot.car.turning_radius: -2: expected a positive number");
  EXPECT_EQ(car_world(R"({"turning_radius": "fast"})", poses).rfind("test.json: robot.car.turning_radius: ", 0), 0u);
  EXPECT_EQ(car_world(R"({"turning_radius": true})", poses), "test.json: robot.car.turning_radius: not a number: true");
  EXPECT_EQ(car_world(R"({"reverse": true})", poses), "test.json: robot.car: missing field \"turning_radius\"");
  EXPECT_EQ(car_world(R"({"turning_radius": 1, "reverse": "yes"})", poses),
            "test.json: robot.car.reverse: expected true or false, got \"yes\"");
  EXPECT_EQ(car_world("[1]", poses).rfind("test.json: robot.car: expected {", 0), 0u);
  EXPECT_EQ(car_world(R"({"turning_radius": 1})", R"("start": [0, 0], "goal": [5, 5, 90])"),
            "test.json: start: a car's pose is [x, y, theta] (theta in degrees), got [0,0]");
  EXPECT_EQ(car_world(R"({"turning_radius": 1})", R"("queries": [{"start": [0, 0, 0], "goal": [5, 5]}])"),
            "test.json: queries[0].goal: a car's pose is [x, y, theta] (theta in degrees), got [5,5]");
  // An empty or self-intersecting body is refused as every robot's is.
  EXPECT_NE(input_error_of([] {
              world_from(R"({"obstacles": [], "robot": {"parts": [], "car": {"turning_radius": 1}}})");
            }).find("robot.parts: empty"),
            std::string::npos);
  EXPECT_NE(input_error_of([] {
              world_from(R"({"obstacles": [], "robot": {"parts": [[[0, 0], [2, 2], [2, 0], [0, 2]]], )"
                         R"("car": {"turning_radius": 1}}})");
            }).find("robot.parts[0]: self-intersecting"),
            std::string::npos);
}

TEST(WorldReader, ReadsChanges) {
  const World w = world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]]], "changes": [
    {"after_moves": 3, "add_obstacle": [[5, 5], [5, 6], [6, 6], [6, 5]]},
    {"after_moves": 3, "remove_obstacle": 0},
    {"after_moves": 9, "remove_obstacle": 1}]})");
  ASSERT_EQ(w.changes.size(), 3u);
  EXPECT_EQ(w.changes[0].after_moves, 3u);
  ASSERT_TRUE(w.changes[0].added);
  // Written clockwise, oriented counter-clockwise as the world's obstacles are.
  EXPECT_EQ(w.changes[0].added->outer, (Ring{{6, 5}, {6, 6}, {5, 6}, {5, 5}}));
  EXPECT_EQ(*w.changes[1].removed, 0u);
  EXPECT_EQ(*w.changes[2].removed, 1u);  // the one changes[0] added
  EXPECT_EQ(w.changes[2].name, "changes[2]");
  EXPECT_TRUE(world_from(R"({"obstacles": []})").changes.empty());
}

TEST(WorldReader, BadChangesNameTheirField) {
  const auto changes = [](const std::string& list) {
    return input_error_of(
        [&] { world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1], [0, 1]]], "changes": )" + list + "}"); });
  };
  EXPECT_EQ(changes("{}").rfind("test.json: changes: expected a list", 0), 0u);
  EXPECT_EQ(changes(R"([{"add_obstacle": [[0, 0], [1, 0], [0, 1]]}])"),
            "test.json: changes[0]: missing field \"after_moves\"");
  EXPECT_EQ(changes(R"([{"after_moves": -1, "remove_obstacle": 0}])"),
            "test.json: changes[0].after_moves: expected a whole number of at least 0, got -1");
  EXPECT_EQ(changes(R"([{"after_moves": 1.5, "remove_obstacle": 0}])"),
            "test.json: changes[0].after_moves: expected a whole number of at least 0, got \"1.5\"");
  EXPECT_EQ(changes(R"([{"after_moves": 1}])")
                .rfind("test.json: changes[0]: give one of \"add_obstacle\" and \"remove_obstacle\"", 0),
            0u);
  EXPECT_EQ(changes(R"([{"after_moves": 1, "remove_obstacle": 0, "add_obstacle": [[0, 0], [1, 0], [0, 1]]}])")
                .rfind("test.json: changes[0]: give one of", 0),
            0u);
  EXPECT_EQ(changes(R"([{"after_moves": 1, "add_obstacle": [[0, 0], [2, 2], [2, 0], [0, 2]]}])")
                .rfind("test.json: changes[0].add_obstacle: self-intersecting", 0),
            0u);
  EXPECT_EQ(changes(R"([{"after_moves": 1, "remove_obstacle": 1}])"),
            "test.json: changes[0].remove_obstacle: 1: there are 1 obstacles at that moment (numbered from 0: the "
            "world's, then those "
            "the changes before added)");
  EXPECT_EQ(changes(R"([{"after_moves": 1, "remove_obstacle": 0}, {"after_moves": 2, "remove_obstacle": 0}])"),
            "test.json: changes[1].remove_obstacle: obstacle 0 was removed by an earlier change");
  EXPECT_EQ(changes(R"([{"after_moves": 5, "remove_obstacle": 0}, {"after_moves": 2, "add_obstacle": [[0, 0], [1, 0], )"
                    R"([0, 1]]}])"),
            "test.json: changes[1].after_moves: 2 after changes[0]'s 5: list the changes in the order they happen");
}

TEST(WorldReader, ReadsRoundThingsAndThinWallsExactly) {
  const World w = world_from(R"({"bounds": {"center": [0, 0.5], "radius": "21/2"},
      "discs": [{"center": [1, 2], "radius": 0.1}], "walls": [[[0, 0], [0, 0], [0, 3], [2, 3]]],
      "robot": {"disc": 0.25}, "start": [1, 1], "goal": [-1, -1]})");
  ASSERT_EQ(w.discs.size(), 1u);
  EXPECT_EQ(w.discs[0].radius, Rational(1, 10));
  EXPECT_EQ(w.discs[0].center.y, Rational(2));
  ASSERT_EQ(w.walls.size(), 1u);
  EXPECT_EQ(w.walls[0].size(), 3u);  // the repeated point dropped
  ASSERT_TRUE(w.disc_bounds.has_value());
  EXPECT_EQ(w.disc_bounds->radius, Rational(21, 2));
  EXPECT_FALSE(w.bounds.has_value());
  ASSERT_TRUE(w.robot.disc.has_value());
  EXPECT_EQ(*w.robot.disc, Rational(1, 4));
  EXPECT_FALSE(w.robot.is_point());
  EXPECT_EQ(round_features(w), (std::vector<std::string>{"discs", "walls", "disc bounds", "a disc robot"}));
  EXPECT_TRUE(round_features(world_from(R"({"obstacles": []})")).empty());
}

TEST(WorldReader, RefusesRoundThingsItCannotReadNamingThem) {
  const auto refused = [](const std::string& text) {
    try {
      parse_world(text, "test.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused(R"({"discs": [{"center": [0, 0], "radius": 0}]})"),
            "test.json: discs[0].radius: 0: expected a radius > 0");
  EXPECT_EQ(refused(R"({"discs": [{"center": [0, 0]}]})"), "test.json: discs[0]: missing field \"radius\"");
  EXPECT_EQ(refused(R"({"walls": [[[1, 1], [1, 1]]]})"),
            "test.json: walls[0]: a wall needs at least two distinct points [[x, y], [x, y], ...]");
  EXPECT_EQ(refused(R"({"obstacles": [], "bounds": {"center": [0, 0], "radius": -1}})"),
            "test.json: bounds.radius: -1: expected a radius > 0");
  EXPECT_EQ(refused(R"({"obstacles": [], "robot": {"disc": 1, "parts": [[[0, 0], [1, 0], [0, 1]]]}})"),
            "test.json: robot: a robot is {\"parts\": [...]} or {\"disc\": r}, not both");
  EXPECT_EQ(refused(R"({"obstacles": [], "robot": {"disc": 1, "car": {"turning_radius": 1}}})"),
            "test.json: robot: a disc robot is {\"disc\": r} alone: a car's body is its parts");
  // An unknown field that may hold obstacles is an error: planning straight through them is not an answer.
  EXPECT_NE(refused(R"({"obstacles": [], "circles": [{"center": [0, 0], "radius": 1}]})")
                .find("test.json: world: unknown field \"circles\": it may describe what is not free"),
            std::string::npos);
}
