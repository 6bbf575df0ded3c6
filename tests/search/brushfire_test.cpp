// search/brushfire: distances, obstacle ids, origins and the GVD of small grids written out by
// hand, the outside of the grid as one obstacle, and the GVD's connectivity by the moves the
// gvd-grid planner climbs and searches with, checked by flood fills of its own: one piece per free
// component that every climb reaches — through a door or a pocket of one obstacle and between
// posts where only the outside's fronts meet (hand-made grids), on random grids of rectangles and
// of noise — and taking one side of each front never cuts what the meeting cells join.
#include <polyplan/search/brushfire.hpp>

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

// The moves GvdGridPlanner climbs and searches with, written out here so that the checks do not
// lean on the planner or on GridGraph: 8-connected between free cells, a diagonal move only when
// both cells beside it are free (no corner cutting).
class Moves {
 public:
  Moves(std::size_t columns, std::size_t rows, const std::vector<std::uint8_t>& blocked)
      : columns_(static_cast<long>(columns)), rows_(static_cast<long>(rows)), blocked_(&blocked) {}
  // Calls f(n) for every cell n one move from free cell c.
  template <class F>
  void from(std::size_t c, F&& f) const {
    const long x = static_cast<long>(c) % columns_, y = static_cast<long>(c) / columns_;
    for (long dy = -1; dy <= 1; ++dy)
      for (long dx = -1; dx <= 1; ++dx)
        if ((dx != 0 || dy != 0) && free(x + dx, y + dy) && free(x + dx, y) && free(x, y + dy))
          f(static_cast<std::size_t>(x + dx + (y + dy) * columns_));
  }
  std::size_t cells() const { return blocked_->size(); }
  // The cells reached from `start` by moves between cells of `on` (flood fill).
  std::vector<std::uint8_t> reached_within(const std::vector<std::uint8_t>& on, std::size_t start) const {
    std::vector<std::uint8_t> reached(cells(), 0);
    std::deque<std::size_t> queue{start};
    reached[start] = 1;
    while (!queue.empty()) {
      const std::size_t c = queue.front();
      queue.pop_front();
      from(c, [&](std::size_t n) {
        if (on[n] && !reached[n]) {
          reached[n] = 1;
          queue.push_back(n);
        }
      });
    }
    return reached;
  }

 private:
  bool free(long x, long y) const {
    return x >= 0 && y >= 0 && x < columns_ && y < rows_ && !(*blocked_)[x + y * columns_];
  }
  long columns_, rows_;
  const std::vector<std::uint8_t>* blocked_;
};

std::string cell_text(const Brushfire& b, std::size_t c) {
  return "(" + std::to_string(c % b.columns) + ", " + std::to_string(c / b.columns) + ")";
}

// Whether any two GVD cells that moves between cells of `reference` join, moves between GVD cells
// join too; `what` names the reference in the failure.
::testing::AssertionResult gvd_joins_what(const std::vector<std::uint8_t>& reference, const char* what,
                                          const Brushfire& b, const std::vector<std::uint8_t>& blocked) {
  const Moves moves(b.columns, b.rows, blocked);
  std::vector<std::uint8_t> seen(blocked.size(), 0);
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (!b.gvd[c] || seen[c]) continue;
    const auto joined = moves.reached_within(reference, c), on_gvd = moves.reached_within(b.gvd, c);
    for (std::size_t other = 0; other < blocked.size(); ++other) {
      if (!b.gvd[other] || !joined[other]) continue;
      seen[other] = 1;
      if (!on_gvd[other])
        return ::testing::AssertionFailure() << "GVD cells " << cell_text(b, c) << " and " << cell_text(b, other)
                                             << " share " << what << " but not a GVD piece";
    }
  }
  return ::testing::AssertionSuccess();
}

// The GVD as the gvd-grid planner needs it, in every component of free cells: its GVD cells are
// one piece under the moves (the search's graph), and the climb reaches them from every cell — a
// cell off the GVD has a GVD neighbour or a neighbour of larger distance, one move away, so every
// steepest ascent ends on the GVD of the cell's own component whatever its tie-breaking.
::testing::AssertionResult gvd_connected_and_climbed_to(std::size_t columns, std::size_t rows,
                                                        const std::vector<std::uint8_t>& blocked) {
  const Brushfire b = brushfire(columns, rows, blocked);
  const Moves moves(columns, rows, blocked);
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (blocked[c] || b.gvd[c]) continue;
    bool up = false;
    moves.from(c, [&](std::size_t n) { up = up || b.gvd[n] || b.distance[n] > b.distance[c]; });
    if (!up) return ::testing::AssertionFailure() << "the climb stops at " << cell_text(b, c) << ", off the GVD";
  }
  std::vector<std::uint8_t> free(blocked.size()), done(blocked.size(), 0);
  for (std::size_t c = 0; c < free.size(); ++c) free[c] = blocked[c] ? 0 : 1;
  for (std::size_t c = 0; c < blocked.size(); ++c) {
    if (!b.gvd[c] || done[c]) continue;
    const auto component = moves.reached_within(free, c), piece = moves.reached_within(b.gvd, c);
    for (std::size_t other = 0; other < blocked.size(); ++other) {
      if (!component[other] || !b.gvd[other]) continue;
      done[other] = 1;
      if (!piece[other])
        return ::testing::AssertionFailure() << "GVD cells " << cell_text(b, c) << " and " << cell_text(b, other)
                                             << " share a free component but not a GVD piece";
    }
  }
  return ::testing::AssertionSuccess();
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
  return gvd_joins_what(thick, "a piece of the two-sided meeting set", b, blocked);
}

TEST(Brushfire, HandLabelledGridWithOneObstacle) {
  // 7 x 5, one obstacle of two cells; the outside is obstacle 0, the block obstacle 1. Distances
  // are chessboard steps; column 5 is 2 from both, and the tie goes to the lower id (0).
  const std::vector<std::string> rows = {
      ".......", ".......", "..@@...", ".......", ".......",
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
  // round the obstacle's region. Column 6 sees only id 0: the outside's fronts from two sides
  // meet in the corner cells (6, 0) and (6, 4) — origins (6, -1) and (7, 1) are not 8-adjacent —
  // but those meetings of one obstacle join nothing and end no climb, so they are thinned away.
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
  EXPECT_EQ(b.origin[b.index(4, 2)].column, 3);  // beside the block: the block's cell (3, 2)
  EXPECT_EQ(b.origin[b.index(4, 2)].row, 2);
  EXPECT_EQ(b.origin[b.index(6, 2)].column, 7);  // the border's: the cell beyond it
  EXPECT_EQ(b.origin[b.index(6, 2)].row, 2);
  EXPECT_TRUE(gvd_connected_and_climbed_to(7, 5, blocked_of(rows)));
  EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(7, 5, blocked_of(rows)));
}

TEST(Brushfire, TheOutsideIsOneObstacleOneCellFromTheBorder) {
  // No blocked cell: every cell's nearest obstacle is the outside (id 0), at its chessboard
  // distance from the border plus one. Its fronts from the four sides meet from the corners to
  // the middle; thinned, the GVD keeps a cell of the plateau of distance 2 for the climbs to end.
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
  EXPECT_EQ(empty.gvd_cells, 1u);
  EXPECT_TRUE(empty.gvd[empty.index(2, 1)]);
  EXPECT_TRUE(gvd_connected_and_climbed_to(5, 4, std::vector<std::uint8_t>(20, 0)));
  // All four sides are the same obstacle: a grid cut by a wall from border to border has two
  // free components, each between the outside and the wall, each with its GVD in one piece.
  const std::vector<std::string> rows = {
      "...@....", "...@....", "...@....", "...@....", "...@....",
  };
  const Brushfire cut = brushfire(8, 5, blocked_of(rows));
  EXPECT_EQ(cut.obstacle_count, 2u);
  EXPECT_EQ(cut.obstacle[3], 1u);          // the wall touches the border and keeps its own id
  EXPECT_EQ(cut.distance[2 * 8 + 2], 1u);  // next to the wall
  EXPECT_EQ(cut.distance[2 * 8 + 1], 2u);  // two from the wall, two from the left side
  EXPECT_EQ(cut.obstacle[2 * 8 + 1], 0u);  // a tie: the outside's
  EXPECT_GT(cut.gvd_cells, 0u);
  EXPECT_TRUE(gvd_connected_and_climbed_to(8, 5, blocked_of(rows)));
}

TEST(Brushfire, WallCellsMarkedOutsideAreTheOutside) {
  // A robot with extent cannot reach the border ring: those blocked cells are the outside (id 0),
  // and the wall touching them from the bottom keeps its own id, as it would touching the border.
  const std::vector<std::string> rows = {
      "@@@@@@@", "@..@..@", "@..@..@", "@.....@", "@.....@", "@@@@@@@",
  };
  std::vector<std::uint8_t> ring(42, 0);
  for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = i % 7 == 0 || i % 7 == 6 || i < 7 || i >= 35;
  const Brushfire b = brushfire(7, 6, blocked_of(rows), ring);
  EXPECT_EQ(b.obstacle_count, 2u);
  EXPECT_EQ(b.obstacle[0], 0u);
  EXPECT_EQ(b.obstacle[3 + 7], 1u);  // the wall
  EXPECT_EQ(b.distance[1 + 7], 1u);
  EXPECT_TRUE(b.gvd[2 + 7]);  // touches the wall and the ring
  // Unmarked, the ring and the wall are one obstacle, whose fronts from the two sides of the wall
  // meet below its end and in the corners: a GVD all the same, connected.
  const Brushfire one = brushfire(7, 6, blocked_of(rows));
  EXPECT_EQ(one.obstacle_count, 2u);
  EXPECT_TRUE(one.gvd[one.index(3, 3)]);
  EXPECT_TRUE(gvd_connected_and_climbed_to(7, 6, blocked_of(rows)));
  EXPECT_THROW(brushfire(7, 6, blocked_of(rows), std::vector<std::uint8_t>(41, 0)), std::invalid_argument);
}

TEST(Brushfire, PassageOneCellWideBetweenTwoObstaclesIsOnTheGvd) {
  // Obstacles 1 (left) and 2 (right) leave column 3 free: each of its cells touches both, so
  // each is on the GVD whichever id it took, and the GVD runs through the passage.
  const std::vector<std::string> rows = {
      "..........", ".@@.@@@...", ".@@.@@@...", ".@@.@@@...", "..........",
  };
  const Brushfire b = brushfire(10, 5, blocked_of(rows));
  EXPECT_EQ(b.obstacle_count, 3u);
  for (std::size_t row = 1; row <= 3; ++row) EXPECT_TRUE(b.gvd[b.index(3, row)]) << row;
  EXPECT_TRUE(gvd_connected_and_climbed_to(10, 5, blocked_of(rows)));
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
    for (std::size_t row = 2; row <= 6; ++row)
      EXPECT_EQ(b.gvd[b.index(column, row)] != 0, row == 4) << column << ", " << row;
  EXPECT_EQ(b.distance[b.index(15, 4)], 3u);
  EXPECT_TRUE(gvd_connected_and_climbed_to(30, 9, blocked_of(rows)));
}

// Random grids of separate rectangles (each one convex obstacle), some against the border.
std::vector<std::uint8_t> random_rectangles(std::mt19937& random, std::size_t columns, std::size_t rows) {
  std::vector<std::uint8_t> blocked(columns * rows, 0);
  const auto clear_around = [&](long x0, long y0, long x1, long y1) {  // no blocked cell within one of the box
    for (long y = y0 - 1; y <= y1 + 1; ++y)
      for (long x = x0 - 1; x <= x1 + 1; ++x)
        if (x >= 0 && y >= 0 && x < static_cast<long>(columns) && y < static_cast<long>(rows) &&
            blocked[x + y * columns])
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
    EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(columns, rows, random_rectangles(random, columns, rows)))
        << "trial " << trial;
  }
}

// Random noise: every cell blocked with probability `density` — pockets, doors, single free
// cells and diagonal squeezes of every kind.
std::vector<std::uint8_t> random_noise(std::mt19937& random, std::size_t columns, std::size_t rows, double density) {
  std::bernoulli_distribution blocked_cell(density);
  std::vector<std::uint8_t> blocked(columns * rows);
  for (auto& b : blocked) b = blocked_cell(random) ? 1 : 0;
  return blocked;
}

TEST(Brushfire, GvdIsConnectedAndClimbedToInEachFreeComponentOfRandomGrids) {
  std::mt19937 random(4711);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t columns = 8 + random() % 40, rows = 6 + random() % 30;
    const auto rectangles = random_rectangles(random, columns, rows);
    EXPECT_TRUE(gvd_connected_and_climbed_to(columns, rows, rectangles)) << "rectangles, trial " << trial;
    const auto noise = random_noise(random, columns, rows, 0.05 + 0.1 * (trial % 6));
    EXPECT_TRUE(gvd_connected_and_climbed_to(columns, rows, noise)) << "noise, trial " << trial;
  }
}

TEST(Brushfire, GvdIsConnectedInEachFreeComponentOfRoomsWithPosts) {
  // Walls from border to border cut the grid into rooms with a door each, posts inside: every
  // passage is between two obstacles (a wall and a post, or two walls), so each free component's
  // GVD is one piece.
  const std::vector<std::string> rows = {
      "....@.........@......", "....@....@....@......", "....@.........@..@@..", "..@.@.........@..@@..",
      ".........@@..........", "....@....@@...@......", "....@.........@...@..",
  };
  EXPECT_TRUE(gvd_connected_and_climbed_to(21, 7, blocked_of(rows)));
  EXPECT_TRUE(thin_gvd_joins_what_the_thick_one_joins(21, 7, blocked_of(rows)));
}

TEST(Brushfire, DoorInAWallIsOnTheGvdThatJoinsTheRoomToTheOutside) {
  // A room whose wall (one obstacle) has a door, a post inside: the door is between two parts of
  // the same obstacle — origins (6, 1) and (8, 1), not 8-adjacent — so the door cell is on the
  // GVD and joins the GVD round the post to the GVD outside.
  const std::vector<std::string> rows = {
      "...............", ".@@@@@@.@@@@@@.", ".@...........@.", ".@...........@.", ".@.....@.....@.",
      ".@...........@.", ".@...........@.", ".@@@@@@@@@@@@@.", "...............",
  };
  const Brushfire b = brushfire(15, 9, blocked_of(rows));
  EXPECT_EQ(b.obstacle[b.index(7, 1)], b.obstacle[b.index(1, 1)]);
  EXPECT_TRUE(b.gvd[b.index(7, 1)]);
  EXPECT_TRUE(gvd_connected_and_climbed_to(15, 9, blocked_of(rows)));
}

TEST(Brushfire, PocketOfOneObstacleIsOnTheGvdFromItsMouthToItsEnd) {
  // A deep U open at the bottom, 6 cells wide inside: the fronts from its two arms meet down the
  // middle (columns 5 and 6, 3 from each arm), the outside's from above and below meet round it
  // — one piece of GVD, into the pocket and round the U.
  const std::vector<std::string> rows = {
      "............", "..@@@@@@@@..", "..@......@..", "..@......@..", "..@......@..", "..@......@..", "..@......@..",
      "..@......@..", "..@......@..", "..@......@..", "..@......@..", "............", "............",
  };
  const Brushfire b = brushfire(12, 13, blocked_of(rows));
  EXPECT_EQ(b.obstacle_count, 2u);
  for (std::size_t row = 5; row <= 9; ++row) {
    EXPECT_EQ(b.obstacle[b.index(5, row)], 1u) << row;  // inside: the U's fronts only
    EXPECT_EQ(b.distance[b.index(5, row)], 3u) << row;
    EXPECT_NE(b.gvd[b.index(5, row)], b.gvd[b.index(6, row)]) << row;  // one of the middle pair
  }
  EXPECT_TRUE(gvd_connected_and_climbed_to(12, 13, blocked_of(rows)));
}

TEST(Brushfire, TheOutsidesFrontsMeetBetweenTwoPostsFarApart) {
  // Two posts in a low room: between them only the outside's fronts, from above and from below,
  // meet — the GVD along the middle row joins the loops round the posts.
  const std::vector<std::string> rows = {
      "....................", "...@..........@.....", "....................",
      "....................", "...@..........@.....", "....................",
  };
  const Brushfire b = brushfire(20, 6, blocked_of(rows));
  for (std::size_t column = 6; column <= 11; ++column) {
    EXPECT_EQ(b.obstacle[b.index(column, 2)], 0u) << column;
    EXPECT_TRUE(b.gvd[b.index(column, 2)]) << column;
  }
  EXPECT_TRUE(gvd_connected_and_climbed_to(20, 6, blocked_of(rows)));
}

TEST(Brushfire, RefusesFlagsOfTheWrongSize) {
  EXPECT_THROW(brushfire(3, 3, std::vector<std::uint8_t>(8, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
