// The vertical decomposition on worlds whose cells are counted by hand: which trapezoids, which
// walls, the sweep's events, and the degenerate inputs (vertical edges, vertices on one vertical
// line, pinch points, seams, holes, no bounds).
#include <polyplan/free_space/trapezoidal_decomposition.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace polyplan;
using polyplan::test::canonical;
using polyplan::test::pt;
using polyplan::test::signed_area;
using polyplan::test::world_from;

namespace {

// The cell holding p (p strictly inside one), by its corners.
Ring cell_at(const TrapezoidalDecomposition& d, const ExactPoint& p) {
  const auto cells = d.cells_at(p);
  EXPECT_EQ(cells.size(), 1u) << to_string(p);
  return cells.empty() ? Ring{} : canonical(d.cells()[cells[0]]);
}

Ring box(int x0, int y0, int x1, int y1) {
  return {pt(std::to_string(x0), std::to_string(y0)), pt(std::to_string(x1), std::to_string(y0)),
          pt(std::to_string(x1), std::to_string(y1)), pt(std::to_string(x0), std::to_string(y1))};
}

// Walls as "x: lower..upper" texts, sorted, for whole-set comparisons.
std::vector<std::string> wall_texts(const TrapezoidalDecomposition& d) {
  std::vector<std::string> texts;
  for (const TrapezoidWall& w : d.walls())
    texts.push_back(to_string(w.lower.x) + ": " + to_string(w.lower.y) + ".." + to_string(w.upper.y));
  std::sort(texts.begin(), texts.end());
  return texts;
}

Rational total_area(const TrapezoidalDecomposition& d) {
  Rational sum = 0;
  for (const Ring& c : d.cells()) sum += signed_area(c);
  return sum;
}

TEST(TrapezoidalDecomposition, OneSquareInABoxMakesFourCellsAndFourWalls) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})"));
  const TrapezoidalDecomposition d(c);
  ASSERT_EQ(d.cells().size(), 4u);
  EXPECT_EQ(cell_at(d, pt("1", "5")), box(0, 0, 4, 10));  // the square's side is not a corner
  EXPECT_EQ(cell_at(d, pt("5", "1")), box(4, 0, 6, 4));
  EXPECT_EQ(cell_at(d, pt("5", "9")), box(4, 6, 6, 10));
  EXPECT_EQ(cell_at(d, pt("9", "5")), box(6, 0, 10, 10));
  EXPECT_EQ(wall_texts(d), (std::vector<std::string>{"4: 0..4", "4: 6..10", "6: 0..4", "6: 6..10"}));
  for (const TrapezoidWall& w : d.walls()) {  // left and right cells on their sides of the wall
    EXPECT_LT(to_double(d.centroids()[w.left].x), to_double(w.lower.x));
    EXPECT_GT(to_double(d.centroids()[w.right].x), to_double(w.lower.x));
  }
  EXPECT_EQ(d.centroids()[d.cells_at(pt("1", "5"))[0]], pt("2", "5"));
  EXPECT_EQ(total_area(d), 96);
  // Four non-vertical edges (the box's and the square's bottoms and tops): 4 insertions, 4
  // deletions; between x = 4 and 6 a vertical line crosses all four.
  EXPECT_EQ(d.sweep().insertions, 4u);
  EXPECT_EQ(d.sweep().deletions, 4u);
  EXPECT_EQ(d.sweep().events(), 8u);
  EXPECT_EQ(d.sweep().most_crossed, 4u);
}

TEST(TrapezoidalDecomposition, WhereAPointLiesCountsTheCellsAroundIt) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(d.cells_at(pt("4", "2")).size(), 2u);  // on a wall
  EXPECT_EQ(d.cells_at(pt("4", "4")).size(), 2u);  // the square's corner: left and bottom cells
  EXPECT_EQ(d.cells_at(pt("5", "4")).size(), 1u);  // on the square's bottom: the cell below
  EXPECT_EQ(d.cells_at(pt("4", "0")).size(), 2u);  // a wall's foot on the bounds
  EXPECT_TRUE(d.cells_at(pt("5", "5")).empty());   // inside the obstacle
  EXPECT_TRUE(d.in_frame(pt("100", "100")));       // bounded: no frame
}

TEST(TrapezoidalDecomposition, VerticesOnOneVerticalLineShareTheirWalls) {
  // Two squares stacked at the same x: the wall between them is made once.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10],
      "obstacles": [[[4, 1], [6, 1], [6, 3], [4, 3]], [[4, 6], [6, 6], [6, 8], [4, 8]]]})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(d.cells().size(), 5u);
  EXPECT_EQ(wall_texts(d),
            (std::vector<std::string>{"4: 0..1", "4: 3..6", "4: 8..10", "6: 0..1", "6: 3..6", "6: 8..10"}));
  EXPECT_EQ(cell_at(d, pt("5", "4")), box(4, 3, 6, 6));
  EXPECT_EQ(total_area(d), 92);
}

TEST(TrapezoidalDecomposition, AStraightVertexBelowACornerStillEndsItsWall) {
  // A post standing on a band across the box leaves the band's top straight through the post's
  // corners (a vertex of no corner); the walls down from the square above end there. (The maze's
  // failure: the walls were left out and a cell wrapped around an obstacle.)
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[0, 2], [10, 2], [10, 3], [0, 3]],
      [[4, 0], [5, 0], [5, 3], [4, 3]], [[4, 6], [5, 6], [5, 8], [4, 8]]]})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(wall_texts(d), (std::vector<std::string>{"4: 3..6", "4: 8..10", "5: 3..6", "5: 8..10"}));
  EXPECT_EQ(d.cells().size(), 6u);
  EXPECT_EQ(cell_at(d, pt("4.5", "4")), box(4, 3, 5, 6));
}

TEST(TrapezoidalDecomposition, WallsEndOnSlantedEdgesAtRationalPoints) {
  // A triangle with decimal coordinates under a slanted bar along the top of the box. The apex
  // (0.4, 0.9) sends no wall down (that would run inside the triangle): five walls, and the region
  // under the triangle is one trapezoid from x = 0.1 to 0.7 — five cells.
  const CSpace c(world_from(R"({"bounds": [0, 0, 1, 1], "obstacles": [[[0.1, 0.2], [0.7, 0.3], [0.4, 0.9]],
      [[0, 0.95], [1, 0.99], [1, 1], [0, 1]]]})"));
  const TrapezoidalDecomposition d(c);
  // The bar's underside at x = 0.1, 0.4, 0.7 is 0.95 + 0.04 x: 477/500, 483/500, 489/500.
  EXPECT_EQ(wall_texts(d), (std::vector<std::string>{"1/10: 0..1/5", "1/10: 1/5..477/500", "2/5: 9/10..483/500",
                                                     "7/10: 0..3/10", "7/10: 3/10..489/500"}));
  EXPECT_EQ(d.cells().size(), 5u);
  EXPECT_EQ(cell_at(d, pt("0.4", "0.1")), (Ring{pt("0.1", "0"), pt("0.7", "0"), pt("0.7", "0.3"), pt("0.1", "0.2")}));
  // The triangle's area is 0.195 and the bar's 0.03: the cells cover the rest exactly.
  EXPECT_EQ(total_area(d), Rational(31, 40));
}

TEST(TrapezoidalDecomposition, APinchPointJoinsNoCells) {
  // Two obstacles touching at (5, 5) close a band across the box: above and below it are two
  // components, which the walls up and down from the pinch keep apart.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [
      [[0, 4], [4, 4], [5, 5], [4, 6], [0, 6]], [[10, 4], [10, 6], [6, 6], [5, 5], [6, 4]]]})"));
  const TrapezoidalDecomposition d(c);
  const auto below = d.cells_at(pt("5", "1")), above = d.cells_at(pt("5", "9"));
  ASSERT_EQ(below.size(), 2u);  // on the walls down and up from the pinch
  ASSERT_EQ(above.size(), 2u);
  // Flood the cells through walls from below: none of the cells above is reached.
  std::vector<bool> reached(d.cells().size(), false);
  std::vector<std::size_t> stack(below.begin(), below.end());
  while (!stack.empty()) {
    const std::size_t cell = stack.back();
    stack.pop_back();
    if (reached[cell]) continue;
    reached[cell] = true;
    for (const TrapezoidWall& w : d.walls()) {
      if (w.left == cell) stack.push_back(w.right);
      if (w.right == cell) stack.push_back(w.left);
    }
  }
  for (std::size_t cell : above) EXPECT_FALSE(reached[cell]);
  // The pinch point itself is a corner of cells on both sides.
  EXPECT_EQ(d.cells_at(pt("5", "5")).size(), 4u);
}

TEST(TrapezoidalDecomposition, ASeamBetweenTouchingObstaclesMakesNoCell) {
  // Two squares sharing a side are one solid: decomposed like one rectangle.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10],
      "obstacles": [[[2, 2], [4, 2], [4, 4], [2, 4]], [[4, 2], [6, 2], [6, 4], [4, 4]]]})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(d.cells().size(), 4u);
  EXPECT_EQ(wall_texts(d), (std::vector<std::string>{"2: 0..2", "2: 4..10", "6: 0..2", "6: 4..10"}));
  EXPECT_TRUE(d.cells_at(pt("4", "3")).empty());
}

TEST(TrapezoidalDecomposition, AHoleInAnObstacleIsACellOfItsOwn) {
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [
      {"outer": [[2, 2], [8, 2], [8, 8], [2, 8]], "holes": [[[4, 4], [4, 6], [6, 6], [6, 4]]]}]})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(d.cells().size(), 5u);
  EXPECT_EQ(cell_at(d, pt("5", "5")), box(4, 4, 6, 6));
  for (const TrapezoidWall& w : d.walls()) EXPECT_NE(w.lower.x, 4);  // no wall leaves the pocket
}

TEST(TrapezoidalDecomposition, WithoutBoundsAFrameHoldsTheObstaclesAndThePointsAskedFor) {
  const CSpace c(world_from(R"({"obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})"));
  const TrapezoidalDecomposition d(c, {pt("-100", "3")});
  EXPECT_TRUE(d.in_frame(pt("-100", "3")));
  EXPECT_FALSE(d.in_frame(pt("1000", "3")));
  EXPECT_EQ(d.cells().size(), 4u);  // like the square in a box
  EXPECT_EQ(d.cells_at(pt("-100", "3")).size(), 1u);
  EXPECT_TRUE(d.cells_at(pt("1000", "3")).empty());
}

TEST(TrapezoidalDecomposition, APolygonRobotDecomposesItsCSpace) {
  // A 2 x 2 square robot (reference point at its centre) in a 10 x 10 box around a 2 x 2 obstacle:
  // the C-obstacle is [3, 7]^2 and the reference box [1, 9]^2.
  const CSpace c(world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
      "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_EQ(d.cells().size(), 4u);
  EXPECT_EQ(wall_texts(d), (std::vector<std::string>{"3: 1..3", "3: 7..9", "7: 1..3", "7: 7..9"}));
  EXPECT_EQ(total_area(d), 64 - 16);
}

TEST(TrapezoidalDecomposition, ARobotThatDoesNotFitHasNoCells) {
  const CSpace c(world_from(
      R"({"bounds": [0, 0, 1, 1], "obstacles": [], "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}})"));
  const TrapezoidalDecomposition d(c);
  EXPECT_TRUE(d.cells().empty());
  EXPECT_TRUE(d.cells_at(pt("0.5", "0.5")).empty());
}

}  // namespace
