// rasterize(RoundWorld): hand-counted cells where a disc, a wall or the bounds touch a cell's side
// or corner exactly; the polygon rasteriser's cells on every shipped polygon world of a point robot
// (an independent construction: edges clipped to open squares here, C-obstacle arrangements
// there); and on the shipped round worlds, no free cell holds a configuration that is not free.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/geometry/round_rasterize.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include "raster_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

using namespace polyplan;
using polyplan::test::blocked_cells;
using polyplan::test::Cells;
using polyplan::test::world_from;

namespace {

Raster round_raster(const std::string& json, std::size_t n) { return rasterize(RoundWorld(world_from(json)), n); }

TEST(RoundRasterize, ADiscBlocksTheCellsItEntersNotThoseItTouches) {
  // Unit cells; the disc of radius 1 round (2, 2) reaches the sides of the ring of cells round the
  // four it enters, and their corners beyond: touching is free.
  EXPECT_EQ(blocked_cells(round_raster(R"({"bounds": [0, 0, 4, 4], "discs": [{"center": [2, 2], "radius": 1}]})", 4)),
            (Cells{{1, 1}, {2, 1}, {1, 2}, {2, 2}}));
  // A hair larger, it enters the eight cells beside them, not yet the corners (√2 away).
  const Raster larger =
      round_raster(R"({"bounds": [0, 0, 4, 4], "discs": [{"center": [2, 2], "radius": "1.000000001"}]})", 4);
  EXPECT_EQ(larger.blocked_count(), 12u);
  EXPECT_FALSE(larger.is_blocked(0, 0));
  // The robot's radius adds to the disc's: radii 1/2 and 1/2 block what 1/4 and 3/4 do (the outer
  // ring of cells leaves the box bounds shrunk by either robot; the inner ones as above).
  const Raster halves = round_raster(
      R"({"bounds": [-1, -1, 5, 5], "robot": {"disc": 0.5}, "discs": [{"center": [2, 2], "radius": 0.5}]})", 6);
  EXPECT_EQ(
      blocked_cells(halves),
      blocked_cells(round_raster(
          R"({"bounds": [-1, -1, 5, 5], "robot": {"disc": 0.25}, "discs": [{"center": [2, 2], "radius": 0.75}]})", 6)));
  EXPECT_EQ(halves.blocked_count(), 20u + 4u);
}

TEST(RoundRasterize, AWallOfZeroThicknessBlocksEveryCellItTouches) {
  // Along the grid line x = 2, y 0.5..1.5: both columns beside it, both rows it spans; crossing it
  // is never allowed, so no free cell may straddle it.
  EXPECT_EQ(blocked_cells(round_raster(R"({"bounds": [0, 0, 4, 4], "walls": [[[2, 0.5], [2, 1.5]]]})", 4)),
            (Cells{{1, 0}, {2, 0}, {1, 1}, {2, 1}}));
  // For a disc robot of radius 1/4 it blocks the cells within 1/4 of it: (1, 2) and (2, 2) are 1/2
  // above its end; the box bounds shrunk by 1/4 leave no cell of the outer ring free.
  const Raster disc =
      round_raster(R"({"bounds": [0, 0, 4, 4], "robot": {"disc": 0.25}, "walls": [[[2, 0.5], [2, 1.5]]]})", 4);
  EXPECT_FALSE(disc.is_blocked(1, 2));
  EXPECT_TRUE(disc.is_blocked(1, 1));
  EXPECT_TRUE(disc.walls[0]);
}

TEST(RoundRasterize, DiscBoundsBlockTheCellsThatReachOutsideThem) {
  // The square round the disc bounds, unit cells: the four inner cells' farthest corners lie
  // √2 from the centre, inside radius 2; every other cell reaches beyond it.
  const Raster r = round_raster(R"({"bounds": {"center": [0, 0], "radius": 2}, "obstacles": []})", 4);
  EXPECT_EQ(r.bounds.xmin, -2);
  EXPECT_EQ(r.bounds.ymax, 2);
  EXPECT_EQ(blocked_cells(r).size(), 12u);
  EXPECT_FALSE(r.is_blocked(1, 1));
  EXPECT_TRUE(r.walls[0]);
  // A robot of radius 1/2 keeps them (√2 < 3/2), one of 0.6 does not (√2 > 1.4).
  EXPECT_EQ(round_raster(R"({"bounds": {"center": [0, 0], "radius": 2}, "robot": {"disc": 0.5}, "obstacles": []})", 4)
                .blocked_count(),
            12u);
  EXPECT_EQ(round_raster(R"({"bounds": {"center": [0, 0], "radius": 2}, "robot": {"disc": 0.6}, "obstacles": []})", 4)
                .blocked_count(),
            16u);
}

TEST(RoundRasterize, AWorldWithoutBoundsOrAZeroResolutionIsRefused) {
  EXPECT_THROW(round_raster(R"({"discs": [{"center": [0, 0], "radius": 1}]})", 4), InputError);
  EXPECT_THROW(round_raster(R"({"bounds": [0, 0, 4, 4], "discs": [{"center": [0, 0], "radius": 1}]})", 0), InputError);
}

// A point robot among polygons: the same cells as the polygon C-space's raster, which decides them
// by another construction.
class RoundRasterOfPolygons : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundRasterOfPolygons, AgreesWithThePolygonRaster) {
  const World world = test::shipped(GetParam());
  ASSERT_TRUE(world.robot.is_point());
  const RoundWorld round(world);
  for (const std::size_t n : {7u, 20u, 64u})
    EXPECT_EQ(blocked_cells(rasterize(round, n)), blocked_cells(rasterize(world, n))) << "n = " << n;
}

INSTANTIATE_TEST_SUITE_P(Shipped, RoundRasterOfPolygons,
                         ::testing::Values("maze", "sphere_world_polygons", "touching_corners", "decimal", "u_trap",
                                           "spiral", "disc_gap", "ring_goal"));

// Conservative: on the shipped round worlds, every point of a 5 × 5 lattice over each free cell's
// closed square (corners and sides included) is a free configuration.
class RoundRasterOfRoundWorlds : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundRasterOfRoundWorlds, NoFreeCellHoldsABlockedConfiguration) {
  const RoundWorld round(test::shipped(GetParam()));
  const Raster r = rasterize(round, 23);
  const Rational w = r.cell_width(), h = r.cell_height();
  std::size_t free = 0;
  for (std::size_t y = 0; y < r.cells_per_axis; ++y)
    for (std::size_t x = 0; x < r.cells_per_axis; ++x) {
      if (r.is_blocked(x, y)) continue;
      ++free;
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; b <= 4; ++b) {
          const ExactPoint p{r.bounds.xmin + w * (Rational(mpz_class(x)) + Rational(a, 4)),
                             r.bounds.ymin + h * (Rational(mpz_class(y)) + Rational(b, 4))};
          EXPECT_FALSE(round.config_not_free(p).has_value()) << "cell (" << x << ", " << y << ")";
        }
    }
  EXPECT_GT(free, 100u);
}

INSTANTIATE_TEST_SUITE_P(Shipped, RoundRasterOfRoundWorlds,
                         ::testing::Values("sphere_world", "sphere_world_disc_bounds", "disc_robot_floor_plan"));

}  // namespace
