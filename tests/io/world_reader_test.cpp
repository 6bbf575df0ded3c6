#include <polyplan/geometry/input_error.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
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

TEST(WorldReader, NormalisesOrientationSilently) {
  // Clockwise outer boundary and counter-clockwise hole: both get turned around.
  const World w = world_from(R"({"obstacles": [{"outer": [[0, 0], [0, 6], [6, 6], [6, 0]],
                                               "holes": [[[2, 2], [4, 2], [4, 4], [2, 4]]]}]})");
  const Ring& outer = w.obstacles[0].outer;
  EXPECT_EQ(outer[1], pt("6", "6"));  // reversed: (6,0) (6,6) (0,6) (0,0)
  const Ring& hole = w.obstacles[0].holes[0];
  EXPECT_EQ(hole[1], pt("4", "4"));  // reversed: (2,4) (4,4) (4,2) (2,2)
}

TEST(WorldReader, DropsRepeatedVertices) {
  const World w = world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 0], [1, 1], [0, 0]]]})");
  EXPECT_EQ(w.obstacles[0].outer.size(), 3u);
}

TEST(WorldReader, NamesTheCrossingEdges) {
  try {
    world_from(R"({"obstacles": [[[0, 0], [1, 0]], [[0, 0], [2, 2], [2, 0], [0, 2]]]})");
    FAIL() << "accepted a two-vertex polygon";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("obstacles[0]: fewer than 3 distinct vertices"), std::string::npos) << e.what();
  }
  try {
    world_from(R"({"obstacles": [[[0, 0], [2, 2], [2, 0], [0, 2]]]})");
    FAIL() << "accepted a bow-tie";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: obstacles[0]: self-intersecting: edge 0 [0, 0]-[2, 2] crosses edge 2 [2, 0]-[0, 2]"),
              std::string::npos)
        << e.what();
  }
}

TEST(WorldReader, SpikeIsNotSimple) {
  // Edges 1 and 2 fold back over each other along y = 0.
  EXPECT_THROW(world_from(R"({"obstacles": [[[0, 0], [2, 0], [1, 0], [1, 1]]]})"), InputError);
}
