// The integer walks against the exact kernel's (free_space_triangulation.hpp) on random grids with
// pinch points, for both ways of making the integer triangulation: converted from the exact one,
// and read straight from the map's cells.
#include <polyplan/free_space/detail/free_space_triangulation.hpp>
#include <polyplan/free_space/detail/integer_triangulation.hpp>
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include "movingai_fixtures.hpp"

#include <gtest/gtest.h>

#include <set>

namespace polyplan::test {
namespace {

using detail::IntegerTriangulation;

std::set<std::pair<std::int64_t, std::int64_t>> as_points(const std::vector<int>& ids, const IntegerTriangulation& t) {
  std::set<std::pair<std::int64_t, std::int64_t>> points;
  for (int id : ids) points.insert({t.point(static_cast<std::size_t>(id)).x, t.point(static_cast<std::size_t>(id)).y});
  return points;
}

TEST(IntegerTriangulation, WalksGiveTheExactKernelsVerdicts) {
  std::mt19937 random(3);
  std::size_t blocked_segments = 0, free_segments = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const GridMap map = random_grid(random, 8 + trial % 5, 6 + trial % 4, 0.3);
    const CSpace cspace(world_from_grid(map));
    const detail::FreeSpaceTriangulation exact(detail::CSpaceAccess::impl(cspace), query_points(cspace.world()));
    const auto converted = IntegerTriangulation::from(exact);
    ASSERT_TRUE(converted);
    const IntegerTriangulation from_cells = IntegerTriangulation::from_grid(map);
    ASSERT_EQ(converted->vertex_count(), exact.vertex_count());
    ASSERT_EQ(from_cells.vertex_count(), exact.vertex_count());
    std::uniform_int_distribution<int> x(0, map.width), y(0, map.height);
    IntegerTriangulation::Scratch scratch;
    for (int k = 0; k < 300; ++k) {
      const IntegerPoint a{x(random), y(random)}, b{x(random), y(random)};
      const detail::Point pa(static_cast<double>(a.x), static_cast<double>(a.y)),
          pb(static_cast<double>(b.x), static_cast<double>(b.y));
      const bool blocked = exact.why_blocked(pa, pb).has_value();
      (blocked ? blocked_segments : free_segments) += 1;
      for (const IntegerTriangulation* t : {&*converted, &from_cells}) {
        EXPECT_EQ(!t->segment_free(a, t->locate(a), b), blocked)
            << "trial " << trial << " [" << a.x << ", " << a.y << "]-[" << b.x << ", " << b.y << "]";
        EXPECT_EQ(t->why_blocked(a, t->locate(a), b).has_value(), blocked);
      }
      std::vector<std::size_t> seen;
      const bool free = exact.visible_from_point(pa, seen);
      std::set<std::pair<std::int64_t, std::int64_t>> expected;
      for (std::size_t v : seen)
        expected.insert({static_cast<std::int64_t>(CGAL::to_double(exact.point(v).x())),
                         static_cast<std::int64_t>(CGAL::to_double(exact.point(v).y()))});
      for (const IntegerTriangulation* t : {&*converted, &from_cells}) {
        std::vector<int> visible;
        EXPECT_EQ(t->visible_from_point(a, t->locate(a), visible, scratch), free);
        EXPECT_EQ(as_points(visible, *t), expected) << "trial " << trial << " from [" << a.x << ", " << a.y << "]";
        std::vector<int> components;
        t->components_at(t->locate(a), components);
        EXPECT_EQ(components.size(), exact.components_at(pa).size());
      }
    }
  }
  EXPECT_GT(blocked_segments, 500u);
  EXPECT_GT(free_segments, 300u);
}

}  // namespace
}  // namespace polyplan::test
