// rasterize: hand-counted cells on small worlds (boundary contact, corners, exact decimals, robots
// with extent), and every cell against an independent exact reference: the area of the C-obstacles
// clipped to the cell's square (positive iff the open square meets their interior).
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include "raster_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <sstream>
#include <utility>

using namespace polyplan;
using polyplan::test::blocked_cells;
using polyplan::test::Cells;
using polyplan::test::signed_area;
using polyplan::test::world_from;

namespace {

// ---- the reference: Sutherland–Hodgman clipping of each ring to the closed square, exact ----

Ring clip(const Ring& ring, const Rational& at, bool vertical, bool keep_above) {
  auto value = [&](const ExactPoint& p) { return vertical ? p.x : p.y; };
  auto inside = [&](const ExactPoint& p) { return keep_above ? value(p) >= at : value(p) <= at; };
  Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % ring.size()];
    if (inside(a)) out.push_back(a);
    if (inside(a) != inside(b)) {
      const Rational t = (at - value(a)) / (value(b) - value(a));
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return out;
}

// Area of the C-obstacles inside the closed square [x0, x1] × [y0, y1]: outer rings count positive
// (counter-clockwise), holes negative (clockwise), so the sum is the area of the intersection.
Rational covered_area(const CSpace& c, const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) {
  Rational area = 0;
  auto add = [&](const Ring& ring) {
    Ring r = clip(clip(clip(clip(ring, x0, true, true), x1, true, false), y0, false, true), y1, false, false);
    if (r.size() >= 3) area += signed_area(r);
  };
  for (const PolygonWithHoles& p : c.cobstacles()) {
    add(p.outer);
    for (const Ring& h : p.holes) add(h);
  }
  return area;
}

Cells reference_blocked_cells(const CSpace& c, std::size_t n) {
  const Bounds& b = *c.world().bounds;
  const Bounds& box = *c.reference_box();
  const Rational w = (b.xmax - b.xmin) / Rational(mpz_class(n)), h = (b.ymax - b.ymin) / Rational(mpz_class(n));
  Cells out;
  for (std::size_t y = 0; y < n; ++y)
    for (std::size_t x = 0; x < n; ++x) {
      const Rational x0 = b.xmin + Rational(mpz_class(x)) * w, y0 = b.ymin + Rational(mpz_class(y)) * h;
      const Rational x1 = x0 + w, y1 = y0 + h;
      const bool leaves_box = x0 < box.xmin || x1 > box.xmax || y0 < box.ymin || y1 > box.ymax;
      if (leaves_box || covered_area(c, x0, y0, x1, y1) > 0) out.insert({x, y});
    }
  return out;
}

void expect_matches_reference(const World& world, std::size_t n) {
  const CSpace c(world);
  EXPECT_EQ(blocked_cells(rasterize(c, n)), reference_blocked_cells(c, n)) << "n = " << n;
}

const char* kUnitSquare = R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})";

}  // namespace

TEST(Rasterize, UnitSquareBlocksOneCellAtN4AndFourAtN8) {
  const World world = world_from(kUnitSquare);
  const Raster coarse = rasterize(world, 4);
  EXPECT_EQ(coarse.cells_per_axis, 4u);
  ASSERT_EQ(coarse.blocked.size(), 16u);
  EXPECT_EQ(blocked_cells(coarse), (Cells{{1, 1}}));
  // Its eight neighbours touch it along a side or at a corner only: free.
  EXPECT_EQ(coarse.blocked_count(), 1u);
  EXPECT_EQ(blocked_cells(rasterize(world, 8)), (Cells{{2, 2}, {3, 2}, {2, 3}, {3, 3}}));
  // n = 2: the square sits inside cell (0, 0) = [0, 2]², touching two of its sides.
  EXPECT_EQ(blocked_cells(rasterize(world, 2)), (Cells{{0, 0}}));
}

TEST(Rasterize, CellCentresAreExact) {
  const Raster r = rasterize(world_from(R"({"bounds": [-1, 0, 2, 0.3], "obstacles": []})"), 3);
  EXPECT_EQ(r.cell_center(0, 0), (ExactPoint{Rational(-1, 2), Rational(1, 20)}));
  EXPECT_EQ(r.cell_center(2, 1), (ExactPoint{Rational(3, 2), Rational(3, 20)}));  // cells 1 × 0.1
  EXPECT_EQ(r.blocked_count(), 0u);
}

TEST(Rasterize, ObstacleOnGridLinesTouchesItsNeighboursOnlyAlongBoundaries) {
  // A 2×1 block exactly on grid lines at n = 4, and one whose corner sits on a grid corner.
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [
      [[0, 0], [2, 0], [2, 1], [0, 1]], [[3, 3], [4, 3], [4, 4], [3, 4]]]})");
  EXPECT_EQ(blocked_cells(rasterize(world, 4)), (Cells{{0, 0}, {1, 0}, {3, 3}}));
}

TEST(Rasterize, ThinTriangleThroughACellCornerBlocksIt) {
  // The sliver between x + y = 2.15 and the line from (2.05, 0.1) to (0.1, 1.9) clips cell (1, 1)
  // = (1, 2)² only near its corner (1, 1): at x = 1.06 it spans y in (1.014, 1.09). The centre
  // (1.5, 1.5) is far outside; no vertex is in the cell.
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[0.1, 2.05], [2.05, 0.1], [0.1, 1.9]]]})");
  EXPECT_EQ(blocked_cells(rasterize(world, 4)), (Cells{{0, 1}, {0, 2}, {1, 0}, {1, 1}, {2, 0}}));
  expect_matches_reference(world, 4);
  expect_matches_reference(world, 13);
}

TEST(Rasterize, DecimalGridLinesAreExact) {
  // Cells 0.1 wide: in doubles 0.3 / 3 = 0.09999999999999999 and 2 * that = 0.19999999999999998,
  // so the obstacle's sides x = 0.1 and x = 0.2 would fall strictly inside neighbouring cells.
  const World on_lines =
      world_from(R"({"bounds": [0, 0, 0.3, 0.3], "obstacles": [[[0.1, 0.1], [0.2, 0.1], [0.2, 0.2], [0.1, 0.2]]]})");
  EXPECT_EQ(blocked_cells(rasterize(on_lines, 3)), (Cells{{1, 1}}));
  // 1e-17 beyond the grid line (the same double as 0.2): the next column and row are entered.
  const World beyond = world_from(R"({"bounds": [0, 0, 0.3, 0.3], "obstacles": [
      [[0.1, 0.1], [0.20000000000000001, 0.1], [0.20000000000000001, 0.20000000000000001], [0.1, )"
                                  R"(0.20000000000000001]]]})");
  EXPECT_EQ(blocked_cells(rasterize(beyond, 3)), (Cells{{1, 1}, {2, 1}, {1, 2}, {2, 2}}));
}

TEST(Rasterize, TouchingObstaclesPinchAtACornerWithoutBlockingTheCornerCells) {
  // touching_corners.json: two squares meeting at (2, 2); cells (1, 1) and (2, 2) touch both at
  // that point only.
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [
      [[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]]})");
  const Raster r = rasterize(world, 4);
  EXPECT_EQ(r.blocked_count(), 8u);
  EXPECT_FALSE(r.is_blocked(1, 1));
  EXPECT_FALSE(r.is_blocked(2, 2));
  EXPECT_TRUE(r.is_blocked(1, 2));
  EXPECT_TRUE(r.is_blocked(2, 1));
}

TEST(Rasterize, CellsInsideAHoleAreFree) {
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [
      {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[1, 1], [3, 1], [3, 3], [1, 3]]]}]})");
  const Raster r = rasterize(world, 4);
  EXPECT_EQ(r.blocked_count(), 12u);
  for (std::size_t y = 1; y <= 2; ++y)
    for (std::size_t x = 1; x <= 2; ++x) EXPECT_FALSE(r.is_blocked(x, y)) << x << ", " << y;
  // At n = 3 (cells 4/3) the middle cell (4/3, 8/3)² lies inside the hole (1, 3)²; the other
  // eight meet the ring.
  const Raster thirds = rasterize(world, 3);
  EXPECT_EQ(thirds.blocked_count(), 8u);
  EXPECT_FALSE(thirds.is_blocked(1, 1));
  expect_matches_reference(world, 7);
}

TEST(Rasterize, ObstacleLargerThanACellBlocksTheCellsInside) {
  // Cells entirely inside the obstacle meet no edge: decided by their centre.
  const World world =
      world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[1.5, 1.5], [8.5, 1.5], [8.5, 8.5], [1.5, 8.5]]]})");
  EXPECT_EQ(rasterize(world, 10).blocked_count(), 64u);  // cells 1..8 in each axis
  EXPECT_EQ(rasterize(world, 5).blocked_count(), 25u);   // every cell meets (1.5, 8.5)²
}

TEST(Rasterize, RobotWithExtentBlocksItsCObstaclesAndTheWalls) {
  const std::string obstacle = R"("bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]])";
  const World point = world_from("{" + obstacle + "}");
  const World square = world_from(
      "{" + obstacle + R"(, "robot": {"parts": [[[-0.25, -0.25], [0.25, -0.25], [0.25, 0.25], [-0.25, 0.25]]]}})");
  const Raster p = rasterize(point, 8), s = rasterize(square, 8);
  // C-obstacle (0.75, 2.25)²: cells 1..4 in each axis (16); the reference point stays in
  // [0.25, 3.75]², which the border cells (0, 0.5) and (3.5, 4) leave (28 of them).
  EXPECT_EQ(p.blocked_count(), 4u);
  EXPECT_EQ(s.blocked_count(), 16u + 28u);
  for (const auto& [x, y] : blocked_cells(p)) EXPECT_TRUE(s.is_blocked(x, y));
  expect_matches_reference(square, 8);
  expect_matches_reference(square, 11);
}

TEST(Rasterize, RobotThatDoesNotFitBlocksEverything) {
  const World world = world_from(R"({"bounds": [0, 0, 1, 1], "obstacles": [],
      "robot": {"parts": [[[0, 0], [2, 0], [2, 1], [0, 1]]]}})");
  EXPECT_EQ(rasterize(world, 3).blocked_count(), 9u);
}

TEST(Rasterize, ObstaclesReachingOutsideTheBounds) {
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [
      [[-100, -100], [0.5, -100], [0.5, 0.5], [-100, 0.5]], [[3.5, 3.5], [1e30, 3.5], [1e30, 1e30], [3.5, 1e30]]]})");
  EXPECT_EQ(blocked_cells(rasterize(world, 4)), (Cells{{0, 0}, {3, 3}}));
}

TEST(Rasterize, MatchesTheClippedAreaReferenceOnRandomDecimalWorlds) {
  // Triangles with vertices on a 0.05 lattice in [0, 4]²: many vertices on grid lines and edges
  // along them at n = 8 (cells 0.5), plus n = 7 whose grid lines are not on the lattice.
  std::mt19937 random(20240607);
  std::uniform_int_distribution<int> lattice(0, 80);
  for (int world_index = 0; world_index < 12; ++world_index) {
    std::ostringstream json;
    json << R"({"bounds": [0, 0, 4, 4], "obstacles": [)";
    for (int t = 0; t < 4; ++t) {
      int coords[6];
      do {
        for (int& c : coords) c = lattice(random);
      } while ((coords[2] - coords[0]) * (coords[5] - coords[1]) == (coords[4] - coords[0]) * (coords[3] - coords[1]));
      json << (t ? ", " : "") << "[";
      for (int v = 0; v < 3; ++v)
        json << (v ? ", " : "") << "[" << coords[2 * v] * 0.05 << ", " << coords[2 * v + 1] * 0.05 << "]";
      json << "]";
    }
    json << "]}";
    const World world = world_from(json.str());
    SCOPED_TRACE(json.str());
    expect_matches_reference(world, 8);
    expect_matches_reference(world, 7);
  }
}

TEST(Rasterize, RejectsWorldsWithoutBoundsAndZeroCells) {
  const World unbounded = world_from(R"({"obstacles": [[[1, 1], [2, 1], [2, 2]]]})");
  try {
    rasterize(unbounded, 4);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("test.json: bounds: ", 0), 0u) << e.what();
  }
  try {
    rasterize(world_from(kUnitSquare), 0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "test.json: raster: cells per axis must be between 1 and 2048, got 0");
  }
  EXPECT_THROW(rasterize(CSpace(world_from(kUnitSquare)), max_cells_per_axis + 1), InputError);
  EXPECT_EQ(rasterize(world_from(kUnitSquare), 1).blocked_count(), 1u);
}

// A world that changes: the raster decided again only near the obstacles a change adds or removes
// is the raster of the changed world made whole, for a robot with extent, obstacles that merge
// with and split from others, and changes beyond the bounds.
TEST(RasterizeChange, EqualsTheChangedWorldRasterisedWhole) {
  std::mt19937 random(44);
  std::uniform_int_distribution<int> lattice(-4, 84);
  const auto triangle = [&] {
    int c[6];
    do {
      for (int& v : c) v = lattice(random);
    } while ((c[2] - c[0]) * (c[5] - c[1]) == (c[4] - c[0]) * (c[3] - c[1]));
    Ring ring;
    for (int v = 0; v < 3; ++v) ring.push_back({Rational(c[2 * v], 20), Rational(c[2 * v + 1], 20)});
    if (test::signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    return PolygonWithHoles{ring, {}};
  };
  for (const char* robot : {"", R"(, "robot": {"parts": [[[-0.15, -0.1], [0.2, -0.1], [0.2, 0.25], [-0.15, 0.25]]]})"})
    for (int trial = 0; trial < 6; ++trial) {
      World world =
          world_from(std::string(R"({"bounds": [0, 0, 4, 4], "obstacles": [)") +
                     R"([[1, 1], [2, 1], [2, 2], [1, 2]], [[2.5, 0.5], [3.5, 0.5], [3, 1.5]]])" + robot + "}");
      for (std::size_t n : {7u, 16u}) {
        SCOPED_TRACE("robot " + std::string(robot) + ", trial " + std::to_string(trial) + ", n " + std::to_string(n));
        World before = world;
        Raster raster = rasterize(CSpace(before), n);
        for (int step = 0; step < 4; ++step) {
          World after = before;
          std::vector<const PolygonWithHoles*> changed;
          if (step % 2 == 1 && !after.obstacles.empty()) {
            const std::size_t k = random() % after.obstacles.size();
            changed.push_back(&before.obstacles[k]);
            after.obstacles.erase(after.obstacles.begin() + static_cast<long>(k));
            after.obstacle_names.erase(after.obstacle_names.begin() + static_cast<long>(k));
          } else {
            after.obstacles.push_back(triangle());
            after.obstacle_names.push_back("added");
            changed.push_back(&after.obstacles.back());
          }
          const CSpace cspace(after);
          raster = rasterize_change(cspace, raster, changed);
          EXPECT_EQ(blocked_cells(raster), blocked_cells(rasterize(cspace, n))) << "step " << step;
          EXPECT_EQ(raster.walls, rasterize(cspace, n).walls);
          before = after;
        }
      }
    }
}
