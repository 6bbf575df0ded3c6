// The contour lines of a grid of values (marching squares): on a plane rising along x the line of
// a level is the vertical line where x takes it; cells not free are left out.
#include <polyplan/draw/potential_svg.hpp>

#include <gtest/gtest.h>

namespace polyplan {
namespace {

CellGrid rising_along_x(std::size_t n) {
  CellGrid grid;
  grid.columns = grid.rows = n;
  for (std::size_t row = 0; row < n; ++row)
    for (std::size_t column = 0; column < n; ++column) {
      grid.states.push_back(CellGrid::free);
      grid.values.push_back(static_cast<float>(column) + 0.5f);  // the centre's x: cells are 1 wide from 0
    }
  return grid;
}

TEST(PotentialSvg, AContourOfAPlaneIsAStraightLine) {
  CellGrid grid = rising_along_x(10);
  const auto segments = contour_segments(grid, 3.25);
  ASSERT_EQ(segments.size(), 9u);  // one per square of centres the line crosses, row after row
  for (const auto& [a, b] : segments) {
    EXPECT_DOUBLE_EQ(a.x, 3.25);
    EXPECT_DOUBLE_EQ(b.x, 3.25);
  }
  grid.states[3 + 4 * 10] = CellGrid::blocked;  // a cell beside the line: the two squares touching it go
  EXPECT_EQ(contour_segments(grid, 3.25).size(), 7u);
  EXPECT_TRUE(contour_segments(grid, 100).empty());
}

}  // namespace
}  // namespace polyplan
