// The course's sphere world (data/worlds/sphere_world.json: discs A (-4.4, 2) r 3.4, B (1.6, 2)
// r 1.4, C (4, -6.3) r 2.5, D (-5, -5.5) r 2 in the box [-10, 10]², a point robot, ten queries)
// planned by `raster` through the front door at three resolutions, against answers found another
// way: the gaps' widths from the discs themselves, rrtconnect's path for every query, and the
// exact shortest paths of the polygon version (sphere_world_polygons.json, the discs as polygons
// whose vertices lie on the circles to 4 decimals) for the gaps each shortest route takes.
//
// A route takes the A–B gap when it meets the segment between A's and B's centres (it cannot
// cross the discs, so it passes between them), the gap under C when it meets the segment from C's
// centre straight down to the bottom wall.
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/problem.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace polyplan {
namespace {

Problem read_shipped_world(const std::string& file) {
  return Problem::read(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + file + ".json");
}

const std::vector<ExactPoint>& points_of(const Report& report) {
  return std::get<PlanReport<ExactPoint>>(report.typed()).path;
}

int turn_sign(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return sgn((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Whether segment pq meets segment ab: crossing, or an end of one on the other.
bool segments_touch(const ExactPoint& p, const ExactPoint& q, const ExactPoint& a, const ExactPoint& b) {
  const auto on = [](const ExactPoint& s, const ExactPoint& t, const ExactPoint& r) {
    return turn_sign(s, t, r) == 0 && std::min(s.x, t.x) <= r.x && r.x <= std::max(s.x, t.x) &&
           std::min(s.y, t.y) <= r.y && r.y <= std::max(s.y, t.y);
  };
  if (turn_sign(p, q, a) * turn_sign(p, q, b) < 0 && turn_sign(a, b, p) * turn_sign(a, b, q) < 0) return true;
  return on(p, q, a) || on(p, q, b) || on(a, b, p) || on(a, b, q);
}

struct Gap {
  ExactPoint from, to;  // a segment across the gap, from obstacle to obstacle
};

const Gap kBetweenAAndB{{Rational(-22) / 5, 2}, {Rational(8) / 5, 2}};
const Gap kUnderC{{4, Rational(-63) / 10}, {4, -10}};

// The queries (by number) whose paths take the gap.
std::set<std::size_t> queries_through(const std::vector<std::vector<ExactPoint>>& paths, const Gap& gap) {
  std::set<std::size_t> out;
  for (std::size_t q = 0; q < paths.size(); ++q)
    for (std::size_t i = 1; i < paths[q].size(); ++i)
      if (segments_touch(paths[q][i - 1], paths[q][i], gap.from, gap.to)) out.insert(q);
  return out;
}

// Every query's path by `planner` (each must be found), each checked again among the discs.
std::vector<std::vector<ExactPoint>> found_paths(const Problem& problem, const std::string& planner,
                                                 const OptionValues& options) {
  const auto built = make_planner(planner, problem, options);
  std::vector<std::vector<ExactPoint>> paths;
  for (std::size_t q = 0; q < problem.world()->queries.size(); ++q) {
    const Report report = built->plan(q);
    EXPECT_TRUE(report.found()) << planner << " " << report.query() << ": " << report.why_not();
    paths.push_back(report.found() ? points_of(report) : std::vector<ExactPoint>{});
  }
  return paths;
}

// The table of data/worlds/README.md and docs/planners.md: at 10 cells per axis (cells 2 wide)
// both 1.2-wide gaps are closed and every route goes round; at 25 (0.8) the gap under C opens
// (cells x 3.2..4 and 4..4.8 from y -10 to -9.2 touch neither C nor the wall's inside), A–B not
// yet (its cells x -1.2..-0.4 and -0.4..0.4 reach into A and B); at 100 (0.2) both.
struct RasterRow {
  std::size_t cells_per_axis;
  std::set<std::size_t> between_a_and_b, under_c;
};

const RasterRow kRasterRows[] = {{10, {}, {}}, {25, {}, {5, 9}}, {100, {0, 1, 4, 8}, {5, 9}}};

TEST(SphereWorldRaster, TheGapsAreAsWideAsTheDiscsLeave) {
  const Problem problem = read_shipped_world("sphere_world");
  const World& world = *problem.world();
  ASSERT_EQ(world.discs.size(), 4u);
  const Disc &a = world.discs[0], &b = world.discs[1], &c = world.discs[2];
  EXPECT_EQ(a.center.y, b.center.y);  // on one line: the gap is the centres' distance less the radii
  EXPECT_EQ(b.center.x - a.center.x - a.radius - b.radius, Rational(6) / 5);
  EXPECT_EQ(c.center.y - c.radius - world.bounds->ymin, Rational(6) / 5);
  EXPECT_EQ(kBetweenAAndB.from, a.center);
  EXPECT_EQ(kBetweenAAndB.to, b.center);
  EXPECT_EQ(kUnderC.from, c.center);
}

TEST(SphereWorldRaster, ThreeResolutionsCloseAndOpenItsGaps) {
  const Problem problem = read_shipped_world("sphere_world");
  for (const RasterRow& r : kRasterRows) {
    SCOPED_TRACE("resolution " + std::to_string(r.cells_per_axis));
    // The world's free space stays one piece at every resolution: every query is found, round the
    // discs where a gap is closed, and every path passes the exact check among the discs.
    const auto paths = found_paths(problem, "raster", {{"resolution", std::to_string(r.cells_per_axis)}});
    for (const auto& path : paths) {
      const PathCheck check = problem.round_world().check_path(path);
      EXPECT_TRUE(check.valid) << check.reason;
    }
    EXPECT_EQ(queries_through(paths, kBetweenAAndB), r.between_a_and_b);
    EXPECT_EQ(queries_through(paths, kUnderC), r.under_c);
  }
}

TEST(SphereWorldRaster, TheFinestResolutionAgreesWithTheTrueAnswers) {
  const Problem discs = read_shipped_world("sphere_world");
  // Every query has a path: rrtconnect finds each, checked exactly.
  for (const auto& path : found_paths(discs, "rrtconnect", {{"seed", "1"}})) {
    EXPECT_TRUE(discs.round_world().check_path(path).valid);
  }
  // The shortest routes: exact on the polygon version, whose gaps are the discs' to 4 decimals.
  const Problem polygons = read_shipped_world("sphere_world_polygons");
  const auto shortest = found_paths(polygons, "visibility", {});
  const auto fine = found_paths(discs, "raster", {{"resolution", "100"}});
  EXPECT_EQ(queries_through(fine, kBetweenAAndB), queries_through(shortest, kBetweenAAndB));
  EXPECT_EQ(queries_through(fine, kUnderC), queries_through(shortest, kUnderC));
  EXPECT_EQ(queries_through(fine, kBetweenAAndB), kRasterRows[2].between_a_and_b);
  // And as long as an 8-connected grid's paths can be: no shorter than the shortest (less the
  // polygons' rounding), no longer than its octile stretch (8-connected moves are at most
  // √(4 - 2√2) ≈ 1.0824 times the straight line) and four cells (0.2 each) for the snapped ends and
  // the cells that round each disc outwards.
  for (std::size_t q = 0; q < fine.size(); ++q) {
    const double grid = euclidean_length(fine[q]), best = euclidean_length(shortest[q]);
    EXPECT_GE(grid, 0.999 * best) << "queries[" << q << "]";
    EXPECT_LE(grid, 1.0824 * best + 4 * 0.2) << "queries[" << q << "]";
  }
}

}  // namespace
}  // namespace polyplan
