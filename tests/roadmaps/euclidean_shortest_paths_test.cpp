// EuclideanShortestPaths (the integer engine behind polyplan scen) against independent answers:
// the reference lengths of the shipped MovingAI maps (Polyanya's), and on random grids with pinch
// points the exact-kernel visibility graph, with every path re-checked by check_path.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/roadmaps/euclidean_shortest_paths.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include "movingai_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace polyplan::test {
namespace {

std::vector<ExactPoint> exact(const std::vector<IntegerPoint>& path) {
  std::vector<ExactPoint> points;
  for (const IntegerPoint& p : path)
    points.push_back({Rational(static_cast<long>(p.x)), Rational(static_cast<long>(p.y))});
  return points;
}

TEST(EuclideanShortestPaths, ShippedMapsMatchTheReferenceOnEveryQuery) {
  for (const std::string name : {"arena", "den312d", "lak303d"}) {
    const std::string dir = data_file("movingai");
    const GridMap map = read_movingai_map(dir + "/maps/" + name + ".map");
    const auto scenarios = read_scenarios(dir + "/scenarios/" + name + ".map.scen");
    const auto reference = read_reference_lengths(dir + "/reference/" + name + ".csv", scenarios.size());
    const EuclideanShortestPaths paths(map), through_labels(map, {.table_bytes = 0});
    EXPECT_TRUE(paths.has_table());
    EXPECT_TRUE(through_labels.has_labels());
    EuclideanShortestPaths::Scratch scratch;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < scenarios.size(); ++i) {
      if (i >= reference.size() || !reference[i]) continue;
      const ScenarioQuery& q = scenarios[i];
      const EuclideanPathAnswer answer = paths.query({q.start_x, q.start_y}, {q.goal_x, q.goal_y}, scratch);
      ASSERT_EQ(answer.found, *reference[i] >= 0) << name << " query " << i << ": " << answer.why_not;
      if (answer.found) {
        EXPECT_NEAR(answer.length, *reference[i], 1e-9 * std::max(1.0, *reference[i])) << name << " query " << i;
        const EuclideanPathAnswer labelled =
            through_labels.query({q.start_x, q.start_y}, {q.goal_x, q.goal_y}, scratch);
        EXPECT_NEAR(labelled.length, *reference[i], 1e-9 * std::max(1.0, *reference[i]))
            << name << " query " << i << " (labels)";
      }
      ++compared;
    }
    EXPECT_GE(compared, 150u) << name;
  }
}

// The grid construction (straight from the cells) and the exact one (the C-space's arrangement,
// converted) make the same graph; every answer equals the exact-kernel visibility graph's, through
// the distance table, the hub labels or the A*, and every path passes the exact check.
TEST(EuclideanShortestPaths, RandomGridsAgreeWithTheExactVisibilityGraph) {
  std::mt19937 random(7);
  std::size_t found = 0, not_found = 0, pinch_points = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const GridMap map = random_grid(random, 9 + trial % 4, 7 + trial % 3, 0.3);
    const CSpace cspace(world_from_grid(map));
    const EuclideanShortestPaths from_cells(map), from_arrangement(cspace), labelled(map, {.table_bytes = 0}),
        searching(map, {.table_bytes = 0, .label_bytes = 0});
    ASSERT_EQ(from_cells.corner_count(), from_arrangement.corner_count()) << "trial " << trial;
    ASSERT_EQ(from_cells.edge_count(), from_arrangement.edge_count()) << "trial " << trial;
    EXPECT_TRUE(from_cells.has_table());
    EXPECT_TRUE(labelled.has_labels());
    EXPECT_FALSE(searching.has_table() || searching.has_labels());
    VisibilityGraph graph(cspace);
    EuclideanShortestPaths::Scratch a, b, c, d;
    std::uniform_int_distribution<int> x(0, map.width), y(0, map.height);
    for (int k = 0; k < 60; ++k) {
      const IntegerPoint start{x(random), y(random)}, goal{x(random), y(random)};
      const auto expected = graph.plan(Query{exact({start})[0], exact({goal})[0], "q"});
      for (const EuclideanPathAnswer& answer :
           {from_cells.query(start, goal, a), from_arrangement.query(start, goal, b), labelled.query(start, goal, c),
            searching.query(start, goal, d)}) {
        ASSERT_EQ(answer.found, expected.found)
            << "trial " << trial << " query " << k << ": " << answer.why_not << " / " << expected.why_not;
        if (!answer.found) {
          EXPECT_FALSE(answer.why_not.empty());
          continue;
        }
        EXPECT_NEAR(answer.length, expected.length, 1e-9) << "trial " << trial << " query " << k;
        const PathCheck check = check_path(cspace, exact(answer.path));
        EXPECT_TRUE(check.valid) << check.reason;
        EXPECT_EQ(answer.path.front(), start);
        EXPECT_EQ(answer.path.back(), goal);
      }
      (expected.found ? found : not_found) += 1;
    }
    for (int py = 1; py < map.height; ++py)  // interior grid points whose diagonal cells alone are blocked
      for (int px = 1; px < map.width; ++px) {
        const bool nw = map.is_blocked(px - 1, py - 1), ne = map.is_blocked(px, py - 1),
                   sw = map.is_blocked(px - 1, py), se = map.is_blocked(px, py);
        pinch_points += nw == se && ne == sw && nw != ne;
      }
  }
  // The random grids ask both kinds of question, among pinch points.
  EXPECT_GT(found, 200u);
  EXPECT_GT(not_found, 50u);
  EXPECT_GT(pinch_points, 20u);
}

TEST(EuclideanShortestPaths, APinchPointIsNoPassageAndBlockedEndsSaySo) {
  // Two blocked cells touching at the corner (2, 2) close the diagonal between the free halves.
  GridMap map;
  map.source = "pinch";
  map.width = 4;
  map.height = 4;
  map.blocked.assign(16, false);
  for (int i = 0; i < 4; ++i) map.blocked[static_cast<std::size_t>(i * 4 + i)] = true;  // the diagonal
  const EuclideanShortestPaths paths(map);
  EuclideanShortestPaths::Scratch scratch;
  const auto across = paths.query({3, 1}, {1, 3}, scratch);
  EXPECT_FALSE(across.found);
  EXPECT_EQ(across.why_not, "start and goal lie in different components of the free space");
  const auto along = paths.query({4, 0}, {2, 1}, scratch);
  EXPECT_TRUE(along.found);
  const auto inside = paths.query({3, 1}, {5, 1}, scratch);
  EXPECT_FALSE(inside.found);
  EXPECT_EQ(inside.why_not, "the goal [5, 1] is not in the free space");
}

TEST(EuclideanShortestPaths, ThreadsShareOnePreprocessingAndGetTheSameAnswers) {
  std::mt19937 random(11);
  const GridMap map = random_grid(random, 40, 30, 0.2);
  const EuclideanShortestPaths one(map, {.threads = 1}), two(map, {.threads = 2});
  EXPECT_EQ(one.edge_count(), two.edge_count());
  std::vector<std::pair<IntegerPoint, IntegerPoint>> queries;
  std::uniform_int_distribution<int> x(0, map.width), y(0, map.height);
  for (int k = 0; k < 400; ++k) queries.push_back({{x(random), y(random)}, {x(random), y(random)}});
  std::vector<EuclideanPathAnswer> alone(queries.size());
  EuclideanShortestPaths::Scratch scratch;
  for (std::size_t i = 0; i < queries.size(); ++i) alone[i] = one.query(queries[i].first, queries[i].second, scratch);
  const std::vector<TimedPathAnswer> shared = answer_all(two, queries, 2);
  ASSERT_EQ(shared.size(), queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(alone[i].found, shared[i].answer.found);
    EXPECT_EQ(alone[i].length, shared[i].answer.length);
    EXPECT_EQ(alone[i].path, shared[i].answer.path);
  }
}

// A world of large integer coordinates has too many integer points to table each one's corners:
// its queries walk instead, in little memory.
TEST(EuclideanShortestPaths, LargeIntegerCoordinatesWalkInsteadOfTablingEveryPoint) {
  const CSpace cspace(
      world_from(R"({"obstacles": [[[1000000, 1000000], [3000000, 1000000], [3000000, 3000000], [1000000, 3000000]]],
                                    "bounds": [0, 0, 4000000, 4000000]})"));
  const EuclideanShortestPaths paths(cspace);
  EXPECT_LT(paths.memory_bytes(), std::size_t{1} << 20);
  EuclideanShortestPaths::Scratch scratch;
  const EuclideanPathAnswer around = paths.query({0, 2000000}, {4000000, 2000000}, scratch);
  ASSERT_TRUE(around.found) << around.why_not;
  EXPECT_NEAR(around.length, 2e6 * (1 + std::sqrt(2.0)), 1e-6);
  EXPECT_EQ(around.path.size(), 4u);
}

TEST(EuclideanShortestPaths, AWorldWithFractionalCornersIsRefusedByName) {
  const CSpace cspace(
      world_from(R"({"name": "thirds", "obstacles": [[[1, 1], [2, 1], [2, "4/3"]]], "bounds": [0, 0, 3, 3]})"));
  try {
    EuclideanShortestPaths paths(cspace);
    FAIL() << "a corner at 4/3 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not an integer point"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace polyplan::test
