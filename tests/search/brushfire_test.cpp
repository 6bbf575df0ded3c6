// search/brushfire: distances, obstacle ids and the GVD of small grids written out by hand, the
// outside of the grid as one obstacle, and the GVD's connectivity by the moves the gvd-grid
// planner searches it with: one piece per free component where every passage lies between two
// obstacles (hand-made grids), thinning that never cuts what the meeting cells join (random
// grids), and the stated limit (a door between two parts of one obstacle).
#include <polyplan/search/brushfire.hpp>
#include <polyplan/search/grid_graph.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {
namespace {

// Blocked flags from rows of text, '@' blocked and '.' free, the first row being row 0 (y = 0).
std::vector<std::uint8_t> blocked_of(const std::vector<std::string>& rows) {
  std::vector<std::uint8_t> blocked;
  for (const auto& row : rows)
    for (const char c : row) blocked.push_back(c == '@' ? 1 : 0);
  return blocked;
}

std::vector<GridAxis> plane(std::size_t columns, std::size_t rows) {
  return {{static_cast<std::int64_t>(columns), AxisKind::bounded, 1.0}, {static_cast<std::int64_t>(rows), AxisKind::bounded, 1.0}};
}

// The cells reached from `from` by the grid graph's moves (BFS).
std::vector<std::uint8_t> reached_from(const GridGraph& g, GridCell from) {
  std::vector<std::uint8_t> reached(g.cell_count(), 0);
  std::deque<GridCell> queue{from};
  reached[from] = 1;
  while (!queue.empty()) {
    const GridCell c = queue.front();
    queue.pop_front();
    for (auto [e, end] = out_edges(c, g); e != end; ++e)
      if (const GridCell next = (*e).target; !reached[next]) {
        reached[next] = 1;
        queue.push_back(next);
      }
  }
  return reached;
}

// The free cells as the grid graph's bitmap.
std::vector<std::uint8_t> free_of(const std::vector<std::uint8_t>& blocked) {
  std::vector<std::uint8_t> free(blocked.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = blocked[i] ? 0 : 1;
  return free;
}

// The moves GvdGridPlanner searches the GVD with: 8-connected between free cells without cutting
// a corner, both ends in `on`.
GridGraph moves_within(std::size_t columns, std::size_t rows, const std::vector<std::uint8_t>& blocked,
                       const std::vector<std::uint8_t>& on) {
  GridGraph g(plane(columns, rows), Connectivity::full, StepCost::euclidean, free_of(blocked));
  g.set_move_test([&on](GridCell a, GridCell c) { return on[a] && on[c]; });
  return g;
}

// Whether any two GVD cells that `reference` joins, the GVD's own moves join too; `what` names the
// reference in the failure.
::testing::AssertionResult gvd_joins_what(const GridGraph& reference, const char* what, const Brushfire& b,
                                          const std::vector<std::uint8_t>& blocked) {
  const GridGraph along_gvd = moves_within(b.columns, b.rows, blocked, b.gvd);
  std::vector<std::uint8_t> seen(blocked.size(), 0);
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (!b.gvd[c] || seen[c]) continue;
    const auto joined = reached_from(reference, c), on_gvd = reached_from(along_gvd, c);
    for (std::size_t other = 0; other < blocked.size(); ++other) {
      if (!b.gvd[other] || !joined[other]) continue;
      seen[other] = 1;
      if (!on_gvd[other])
        return ::testing::AssertionFailure() << "GVD cells (" << c % b.columns << ", " << c / b.columns << ") and ("
                                             << other % b.columns << ", " << other / b.columns << ") share " << what
                                             << " but not a GVD piece";
    }
  }
  return ::testing::AssertionSuccess();
}

// For every component of free cells (8-connected, no corner cutting), whether its GVD cells are
// one piece under the same moves restricted to GVD cells (GvdGridPlanner's search graph).
::testing::AssertionResult gvd_connected_in_each_component(std::size_t columns, std::size_t rows,
                                                            const std::vector<std::uint8_t>& blocked) {
  const GridGraph free_graph(plane(columns, rows), Connectivity::full, StepCost::euclidean, free_of(blocked));
  return gvd_joins_what(free_graph, "a free component", brushfire(columns, rows, blocked), blocked);
}

// Whether thinning keeps connectivity: any two GVD cells that the thick meeting set joins — every
// free cell with a neighbour of another id, on both sides of each front — the GVD joins too.
::testing::AssertionResult thin_gvd_joins_what_the_thick_one_joins(std::size_t columns, std::size_t rows,
                                                                   const std::vector<std::uint8_t>& blocked) {
  const Brushfire b = brushfire(columns, rows, blocked);
  std::vector<std::uint8_t> thick(blocked.size(), 0);
  for (long y = 0; y < static_cast<long>(rows); ++y)
    for (long x = 0; x < static_cast<long>(columns); ++x) {
      const std::size_t c = x + y * columns;
      if (blocked[c]) continue;
      for (long dy = -1; dy <= 1; ++dy)
        for (long dx = -1; dx <= 1; ++dx) {
          const long nx = x + dx, ny = y + dy;
          const bool inside = nx >= 0 && ny >= 0 && nx < static_cast<long>(columns) && ny < static_cast<long>(rows);
          const std::uint32_t id = inside ? b.obstacle[nx + ny * columns] : 0;
          if (id != b.obstacle[c]) thick[c] = 1;
        }
    }
  return gvd_joins_what(moves_within(columns, rows, blocked, thick), "a piece of the two-sided meeting set", b, blocked);
}

TEST(Brushfire, HandLabelledGridWithOneObstacle) {
  // 7 x 5, one obstacle of two cells; the outside is obstacle 0, the block obstacle 1. Distances
  // are chessboard steps; column 5 is 2 from both, and the tie goes to the lower id (0).
  const std::vector<std::string> rows = {
      ".......",
      ".......",
      "..@@...",
      ".......",
      ".......",
  };
  const Brushfire b = brushfire(7, 5, blocked_of(rows));
  const std::vector<std::uint32_t> distance = {
      1, 1, 1, 1, 1, 1, 1,  // row 0 (y = 0)
      1, 1, 1, 1, 1, 2, 1,  //
      1, 1, 0, 0, 1, 2, 1,  //
      1, 1, 1, 1, 1, 2, 1,  //
      1, 1, 1, 1, 1, 1, 1,  // row 4
  };
  const std::vector<std::uint32_t> obstacle = {
      0, 0, 0, 0, 0, 0, 0,  //
      0, 1, 1, 1, 1, 0, 0,  //
      0, 1, 1, 1, 1, 0, 0,  //
      0, 1, 1, 1, 1, 0, 0,  //
      0, 0, 0, 0, 0, 0, 0,  //
  };
  // Of two neighbouring cells of different ids, the lower id's: a ring of outside-labelled cells
  // round the obstacle's region (column 6 sees only id 0).
  const std::vector<std::uint8_t> gvd = {
      1, 1, 1, 1, 1, 1, 0,  //
      1, 0, 0, 0, 0, 1, 0,  //
      1, 0, 0, 0, 0, 1, 0,  //
      1, 0, 0, 0, 0, 1, 0,  //
      1, 1, 1, 1, 1, 1, 0,  //
  };
  EXPECT_EQ(b.distance, distance);
  EXPECT_EQ(b.obstacle, obstacle);
  EXPECT_EQ(b.gvd, gvd);
  EXPECT_EQ(b.obstacle_count, 2u);
  EXPECT_EQ(b.max_distance, 2u);
  EXPECT_EQ(b.gvd_cells, 18u);
  EXPECT_TRUE(gvd_connected_in_each_component(7, 5, blocked_of(rows)));
  EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(7, 5, blocked_of(rows)));
}

TEST(Brushfire, TheOutsideIsOneObstacleOneCellFromTheBorder) {
  // No blocked cell: every cell's nearest obstacle is the outside (id 0), at its chessboard
  // distance from the border plus one; one obstacle meets no other, so there is no GVD.
  const Brushfire empty = brushfire(5, 4, std::vector<std::uint8_t>(20, 0));
  const std::vector<std::uint32_t> distance = {
      1, 1, 1, 1, 1,  //
      1, 2, 2, 2, 1,  //
      1, 2, 2, 2, 1,  //
      1, 1, 1, 1, 1,  //
  };
  EXPECT_EQ(empty.distance, distance);
  EXPECT_EQ(empty.obstacle, std::vector<std::uint32_t>(20, 0));
  EXPECT_EQ(empty.obstacle_count, 1u);
  EXPECT_EQ(empty.gvd_cells, 0u);
  // All four sides are the same obstacle: a grid cut by a wall from border to border has two
  // free components, each between the outside and the wall, each with its GVD in one piece.
  const std::vector<std::string> rows = {
      "...@....",
      "...@....",
      "...@....",
      "...@....",
      "...@....",
  };
  const Brushfire cut = brushfire(8, 5, blocked_of(rows));
  EXPECT_EQ(cut.obstacle_count, 2u);
  EXPECT_EQ(cut.obstacle[3], 1u);  // the wall touches the border and keeps its own id
  EXPECT_EQ(cut.distance[2 * 8 + 2], 1u);  // next to the wall
  EXPECT_EQ(cut.distance[2 * 8 + 1], 2u);  // two from the wall, two from the left side
  EXPECT_EQ(cut.obstacle[2 * 8 + 1], 0u);  // a tie: the outside's
  EXPECT_GT(cut.gvd_cells, 0u);
  EXPECT_TRUE(gvd_connected_in_each_component(8, 5, blocked_of(rows)));
}

TEST(Brushfire, WallCellsMarkedOutsideAreTheOutside) {
  // A robot with extent cannot reach the border ring: those blocked cells are the outside (id 0),
  // and the wall touching them from the bottom keeps its own id, as it would touching the border.
  const std::vector<std::string> rows = {
      "@@@@@@@",
      "@..@..@",
      "@..@..@",
      "@.....@",
      "@.....@",
      "@@@@@@@",
  };
  std::vector<std::uint8_t> ring(42, 0);
  for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = i % 7 == 0 || i % 7 == 6 || i < 7 || i >= 35;
  const Brushfire b = brushfire(7, 6, blocked_of(rows), ring);
  EXPECT_EQ(b.obstacle_count, 2u);
  EXPECT_EQ(b.obstacle[0], 0u);
  EXPECT_EQ(b.obstacle[3 + 7], 1u);  // the wall
  EXPECT_EQ(b.distance[1 + 7], 1u);
  EXPECT_TRUE(b.gvd[2 + 7]);  // touches the wall and the ring
  // Unmarked, the ring and the wall are one obstacle: no two ids meet.
  EXPECT_EQ(brushfire(7, 6, blocked_of(rows)).gvd_cells, 0u);
  EXPECT_THROW(brushfire(7, 6, blocked_of(rows), std::vector<std::uint8_t>(41, 0)), std::invalid_argument);
}

TEST(Brushfire, PassageOneCellWideBetweenTwoObstaclesIsOnTheGvd) {
  // Obstacles 1 (left) and 2 (right) leave column 3 free: each of its cells touches both, so
  // each is on the GVD whichever id it took, and the GVD runs through the passage.
  const std::vector<std::string> rows = {
      "..........",
      ".@@.@@@...",
      ".@@.@@@...",
      ".@@.@@@...",
      "..........",
  };
  const Brushfire b = brushfire(10, 5, blocked_of(rows));
  EXPECT_EQ(b.obstacle_count, 3u);
  for (std::size_t row = 1; row <= 3; ++row) EXPECT_TRUE(b.gvd[b.index(3, row)]) << row;
  EXPECT_TRUE(gvd_connected_in_each_component(10, 5, blocked_of(rows)));
}

TEST(Brushfire, AxisParallelFrontIsOneCellWide) {
  // A corridor of five rows (2 to 6) between two walls: row 4 is 3 from both (the tie to the
  // lower id, the bottom wall's), row 5 is the top wall's; the GVD is row 4 alone away from the
  // ends.
  std::vector<std::string> rows(9, std::string(30, '.'));
  rows[0] = rows[1] = std::string(30, '@');
  rows[7] = rows[8] = std::string(30, '@');
  const Brushfire b = brushfire(30, 9, blocked_of(rows));
  for (std::size_t column = 6; column < 24; ++column)
    for (std::size_t row = 2; row <= 6; ++row) EXPECT_EQ(b.gvd[b.index(column, row)] != 0, row == 4) << column << ", " << row;
  EXPECT_EQ(b.distance[b.index(15, 4)], 3u);
  EXPECT_TRUE(gvd_connected_in_each_component(30, 9, blocked_of(rows)));
}

// Random grids of separate rectangles (each one convex obstacle), some against the border.
std::vector<std::uint8_t> random_rectangles(std::mt19937& random, std::size_t columns, std::size_t rows) {
  std::vector<std::uint8_t> blocked(columns * rows, 0);
  const auto clear_around = [&](long x0, long y0, long x1, long y1) {  // no blocked cell within one of the box
    for (long y = y0 - 1; y <= y1 + 1; ++y)
      for (long x = x0 - 1; x <= x1 + 1; ++x)
        if (x >= 0 && y >= 0 && x < static_cast<long>(columns) && y < static_cast<long>(rows) && blocked[x + y * columns])
          return false;
    return true;
  };
  for (int k = 0; k < 12; ++k) {
    const long w = 1 + random() % 6, h = 1 + random() % 6;
    const long x0 = static_cast<long>(random() % columns), y0 = static_cast<long>(random() % rows);
    const long x1 = std::min<long>(x0 + w - 1, columns - 1), y1 = std::min<long>(y0 + h - 1, rows - 1);
    if (!clear_around(x0, y0, x1, y1)) continue;
    for (long y = y0; y <= y1; ++y)
      for (long x = x0; x <= x1; ++x) blocked[x + y * columns] = 1;
  }
  return blocked;
}

// (Not on random noise: there fronts run one cell apart without meeting, and the two-sided set
// joins them by touching, which is no reference.)
TEST(Brushfire, ThinningKeepsEveryConnectionOfTheMeetingCellsOnRandomRectangles) {
  std::mt19937 random(2026);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t columns = 12 + random() % 30, rows = 10 + random() % 25;
    EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(columns, rows, random_rectangles(random, columns, rows))) << "trial " << trial;
  }
}

TEST(Brushfire, GvdIsConnectedInEachFreeComponentOfRoomsWithPosts) {
  // Walls from border to border cut the grid into rooms with a door each, posts inside: every
  // passage is between two obstacles (a wall and a post, or two walls), so each free component's
  // GVD is one piece.
  const std::vector<std::string> rows = {
      "....@.........@......",
      "....@....@....@......",
      "....@.........@..@@..",
      "..@.@.........@..@@..",
      ".........@@..........",
      "....@....@@...@......",
      "....@.........@...@..",
  };
  EXPECT_TRUE(gvd_connected_in_each_component(21, 7, blocked_of(rows)));
  EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(21, 7, blocked_of(rows)));
}

TEST(Brushfire, DoorInAWallIsNoMeetingOfTwoObstacles) {
  // A room whose wall (one obstacle) has a door, a post inside: the door is between two parts
  // of the same obstacle, so the GVD round the post and the GVD outside are separate pieces —
  // the limitation brushfire.hpp states.
  const std::vector<std::string> rows = {
      "...............",
      ".@@@@@@.@@@@@@.",
      ".@...........@.",
      ".@...........@.",
      ".@.....@.....@.",
      ".@...........@.",
      ".@...........@.",
      ".@@@@@@@@@@@@@.",
      "...............",
  };
  EXPECT_FALSE(gvd_connected_in_each_component(15, 9, blocked_of(rows)));
}

TEST(Brushfire, RefusesFlagsOfTheWrongSize) {
  EXPECT_THROW(brushfire(3, 3, std::vector<std::uint8_t>(8, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
