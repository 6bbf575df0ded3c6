// plan_on_raster: seed 000's search_start_goal on the rasterised sphere world (routes at three
// resolutions, lengths against the exact visibility-graph optimum, every path re-checked
// independently), and on hand-made worlds where the answer is known exactly.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/roadmaps/raster_planner.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <stdexcept>

using namespace polyplan;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

const std::string kSphereWorld = POLYPLAN_SOURCE_DIR "/data/worlds/sphere_world.json";

// Where the polyline first crosses the horizontal line y = at (x), if it does.
std::optional<double> first_crossing_of_y(const std::vector<ExactPoint>& path, const Rational& at) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const ExactPoint &a = path[i - 1], &b = path[i];
    if ((a.y - at) * (b.y - at) > 0 || a.y == b.y) continue;
    return to_double(a.x + (at - a.y) / (b.y - a.y) * (b.x - a.x));
  }
  return std::nullopt;
}

// Where the polyline first crosses the vertical line x = at (y), if it does.
std::optional<double> first_crossing_of_x(const std::vector<ExactPoint>& path, const Rational& at) {
  std::vector<ExactPoint> swapped;
  for (const ExactPoint& p : path) swapped.push_back({p.y, p.x});
  return first_crossing_of_y(swapped, at);
}

class SphereWorld : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    world = new World(read_world(kSphereWorld));
    cspace = new CSpace(*world);
    VisibilityGraph graph(*cspace);
    for (const Query& q : world->queries) optimum.push_back(graph.plan(q.start, q.goal).length);
  }
  static void TearDownTestSuite() {
    delete cspace;
    delete world;
  }
  static World* world;
  static CSpace* cspace;
  static std::vector<double> optimum;
};
World* SphereWorld::world = nullptr;
CSpace* SphereWorld::cspace = nullptr;
std::vector<double> SphereWorld::optimum;

}  // namespace

TEST_F(SphereWorld, JustRightResolutionFindsCheckedPathsWithinTwentyPercentOfTheOptimum) {
  ASSERT_EQ(world->queries.size(), 10u);  // 5 starts x 2 goals, as seed 000 runs them
  const Raster raster = rasterize(*cspace, 40);
  const RasterPlanner planner(raster, *cspace);
  for (std::size_t i = 0; i < world->queries.size(); ++i) {
    const Query& q = world->queries[i];
    SCOPED_TRACE(q.name);
    const RasterPlan plan = planner.plan(q);
    ASSERT_TRUE(plan.found) << plan.why_not_found;
    ASSERT_GE(plan.path.size(), 2u);
    EXPECT_EQ(plan.path.front(), q.start);
    EXPECT_EQ(plan.path.back(), q.goal);
    // The optimum is a lower bound for every path; an 8-connected grid path is at most
    // 1.0824 times a straight line, plus the detours of cell centres around the discs.
    EXPECT_GE(plan.length, optimum[i] - 1e-9);
    EXPECT_LE(plan.length, 1.2 * optimum[i]);
    const PathCheck independent = check_path(*cspace, plan.path);
    EXPECT_EQ(plan.checked_free, independent.valid);
    EXPECT_EQ(plan.why_not_free, independent.reason);
    EXPECT_TRUE(plan.checked_free) << plan.why_not_free;
    // The reported length is the polyline's, recomputed here from its points.
    double length = 0;
    for (std::size_t k = 1; k < plan.path.size(); ++k)
      length += std::hypot(to_double(plan.path[k].x) - to_double(plan.path[k - 1].x),
                           to_double(plan.path[k].y) - to_double(plan.path[k - 1].y));
    EXPECT_NEAR(plan.length, length, 1e-9);
    // The snapped cells are free and are the grid path's ends.
    EXPECT_FALSE(raster.is_blocked(plan.start_cell_x, plan.start_cell_y));
    EXPECT_FALSE(raster.is_blocked(plan.goal_cell_x, plan.goal_cell_y));
    EXPECT_EQ(plan.search.path.front(), plan.start_cell_x + plan.start_cell_y * 40);
    EXPECT_EQ(plan.search.path.back(), plan.goal_cell_x + plan.goal_cell_y * 40);
  }
}

TEST_F(SphereWorld, CoarseGridClosesTheGapsThatTheJustRightGridKeeps) {
  // Discs A (centre (-4.4, 2), r 3.4) and B ((1.6, 2), r 1.4) leave a gap x in (-1, 0.2) on
  // y = 2; disc C ((4, -6.3), r 2.5) leaves 1.2 under it above the bottom wall. Cells 2 wide
  // (n = 10) close both; cells 0.5 (n = 40) and 0.1 (n = 200) keep both.
  const Query& below_gap_to_top = world->queries[1];       // (-0.4, -1.5) -> (-0.4, 8.5)
  const Query& bottom_left_to_bottom_right = world->queries[5];  // (-9, -9) -> (8.5, -9)
  for (const std::size_t n : {10, 40, 200}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const Raster raster = rasterize(*cspace, n);
    const RasterPlanner planner(raster, *cspace);
    const RasterPlan up = planner.plan(below_gap_to_top), along = planner.plan(bottom_left_to_bottom_right);
    ASSERT_TRUE(up.found && along.found);
    const double x_at_gap = *first_crossing_of_y(up.path, 2);
    const double y_under_c = *first_crossing_of_x(along.path, 4);
    if (n == 10) {
      EXPECT_GT(x_at_gap, 3.0);     // round the right of B
      EXPECT_GT(y_under_c, -3.8);   // over C
      EXPECT_GT(up.length, 1.8 * optimum[1]);
      EXPECT_GT(along.length, 1.8 * optimum[5]);
    } else {
      EXPECT_GT(x_at_gap, -1.0);    // through the gap
      EXPECT_LT(x_at_gap, 0.2);
      EXPECT_LT(y_under_c, -8.8);   // under C
      EXPECT_LT(up.length, 1.1 * optimum[1]);
      EXPECT_LT(along.length, 1.1 * optimum[5]);
    }
  }
}

TEST_F(SphereWorld, CoarsePathsAreCheckedLikeEveryOther) {
  const Raster raster = rasterize(*cspace, 10);
  const RasterPlanner planner(raster, *cspace);
  for (const Query& q : world->queries) {
    const RasterPlan plan = planner.plan(q);
    ASSERT_TRUE(plan.found) << q.name;
    EXPECT_EQ(plan.checked_free, check_path(*cspace, plan.path).valid) << q.name;
  }
}

TEST(RasterPlanner, JoinFromTheStartThroughAnObstacleIsReportedNotHidden) {
  // Cells 2 x 2; the square (0.5, 1.5)² blocks cell (0, 0). The start (0.2, 0.2) is equally near
  // the centres (3, 1) and (1, 3) (squared distance 8.48): the lower index, cell (1, 0), wins.
  // The join (0.2, 0.2) -> (3, 1) passes through the square (at x = 1.4 it is at y = 0.543).
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]]})");
  const CSpace cspace(world);
  const Raster raster = rasterize(cspace, 2);
  const RasterPlan plan = plan_on_raster(raster, cspace, Query{pt("0.2", "0.2"), pt("3.5", "3.5"), "q"});
  ASSERT_TRUE(plan.found);
  EXPECT_EQ(plan.start_cell_x, 1u);
  EXPECT_EQ(plan.start_cell_y, 0u);
  EXPECT_EQ(plan.path, (std::vector<ExactPoint>{pt("0.2", "0.2"), pt("3", "1"), pt("3", "3"), pt("3.5", "3.5")}));
  EXPECT_FALSE(plan.checked_free);
  EXPECT_EQ(check_path(cspace, plan.path).reason, plan.why_not_free);
  EXPECT_NE(plan.why_not_free.find("obstacles[0]"), std::string::npos) << plan.why_not_free;
  EXPECT_NEAR(plan.length, std::sqrt(2.8 * 2.8 + 0.8 * 0.8) + 2 + std::sqrt(0.5), 1e-12);
  // Four times finer, the start's own cell (0, 0) = (0, 0.5)² is free: the join is short and free.
  const RasterPlan fine = plan_on_raster(rasterize(cspace, 8), cspace, Query{pt("0.2", "0.2"), pt("3.5", "3.5"), "q"});
  EXPECT_TRUE(fine.checked_free) << fine.why_not_free;
  EXPECT_EQ(fine.start_cell_x, 0u);
  EXPECT_EQ(fine.start_cell_y, 0u);
}

TEST(RasterPlanner, StraightRunsKeepOnlyTheirEndsAndLengthsAreExactMultiples) {
  const World world = world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": []})");
  const CSpace cspace(world);
  const Raster raster = rasterize(cspace, 10);
  const RasterPlanner planner(raster, cspace);
  const RasterPlan along = planner.plan({pt("0.5", "0.5"), pt("9.5", "0.5"), "q"});
  EXPECT_EQ(along.path, (std::vector<ExactPoint>{pt("0.5", "0.5"), pt("9.5", "0.5")}));  // start and goal are centres
  EXPECT_EQ(along.search.path.size(), 10u);
  EXPECT_DOUBLE_EQ(along.length, 9.0);
  EXPECT_DOUBLE_EQ(along.search.cost, 9.0);
  const RasterPlan diagonal = planner.plan({pt("0.5", "0.5"), pt("9.5", "9.5"), "q"});
  EXPECT_EQ(diagonal.path, (std::vector<ExactPoint>{pt("0.5", "0.5"), pt("9.5", "9.5")}));
  EXPECT_NEAR(diagonal.length, 9 * std::sqrt(2.0), 1e-12);
  // 4-connected from cell (0, 0) to cell (3, 1): 4 unit moves in some order, each kept corner
  // joined to the next along an axis; the start joins its centre (0.5, 0.5), the goal is a centre.
  const RasterPlan four = plan_on_raster(raster, cspace, {pt("0.2", "0.7"), pt("3.5", "1.5"), "q"}, {},
                                         Connectivity::axis_aligned);
  EXPECT_EQ(four.search.path.size(), 5u);
  EXPECT_DOUBLE_EQ(four.search.cost, 4.0);
  ASSERT_GE(four.path.size(), 4u);  // start, (0.5, 0.5), at least one corner, goal
  EXPECT_EQ(four.path.front(), pt("0.2", "0.7"));
  EXPECT_EQ(four.path[1], pt("0.5", "0.5"));
  EXPECT_EQ(four.path.back(), pt("3.5", "1.5"));
  for (std::size_t k = 2; k < four.path.size(); ++k)
    EXPECT_TRUE(four.path[k].x == four.path[k - 1].x || four.path[k].y == four.path[k - 1].y) << k;
  EXPECT_NEAR(four.length, std::sqrt(0.13) + 4, 1e-12);
}

TEST(RasterPlanner, PinchBetweenTouchingObstaclesIsNotAPassage) {
  // touching_corners.json: the free cells (1, 1) and (2, 2) meet only at the pinch point (2, 2);
  // the diagonal move between them would brush the blocked cells (2, 1) and (1, 2).
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [
      [[0, 2], [2, 2], [2, 4], [0, 4]], [[2, 0], [4, 0], [4, 2], [2, 2]]]})");
  const CSpace cspace(world);
  const RasterPlan plan = plan_on_raster(rasterize(cspace, 4), cspace, {pt("1.5", "1.5"), pt("2.5", "2.5"), "q"});
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_EQ(plan.why_not_found, "no path on the 4 x 4 grid from cell (1, 1) to cell (2, 2)");
}

TEST(RasterPlanner, StartInsideAnObstacleIsNotFoundWithTheReason) {
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})");
  const CSpace cspace(world);
  const Raster raster = rasterize(cspace, 8);
  const RasterPlan inside = plan_on_raster(raster, cspace, {pt("1.5", "1.5"), pt("3", "3"), "q"});
  EXPECT_FALSE(inside.found);
  EXPECT_TRUE(inside.path.empty());
  EXPECT_EQ(inside.why_not_found, "start [3/2, 3/2] is not free: it is inside obstacles[0]");
  const RasterPlan outside = plan_on_raster(raster, cspace, {pt("0", "0"), pt("5", "3"), "q"});
  EXPECT_FALSE(outside.found);
  EXPECT_EQ(outside.why_not_found, "goal [5, 3] is not free: it is outside the bounds");
  // Contact is free: a start on the obstacle's edge plans (its cell centre is beside it).
  const RasterPlan touching = plan_on_raster(raster, cspace, {pt("1", "1.5"), pt("3", "3"), "q"});
  EXPECT_TRUE(touching.found) << touching.why_not_found;
  EXPECT_TRUE(touching.checked_free) << touching.why_not_free;
}

TEST(RasterPlanner, NearestFreeCellIsExact) {
  // Cells 0.1 wide from 0: centres at 0.05, 0.15, ... A point at x = 0.1 is exactly halfway
  // between two centres (a double computation would see 0.1 - 0.05 != 0.15 - 0.1); the lower index wins.
  const World world = world_from(R"({"bounds": [0, 0, 0.3, 0.3], "obstacles": []})");
  const CSpace cspace(world);
  const Raster raster = rasterize(cspace, 3);
  const RasterPlanner planner(raster, cspace);
  EXPECT_EQ(planner.nearest_free_cell(pt("0.1", "0.1")), (std::pair<std::size_t, std::size_t>{0, 0}));
  EXPECT_EQ(planner.nearest_free_cell(pt("0.1000000000000000001", "0.1")), (std::pair<std::size_t, std::size_t>{1, 0}));
  EXPECT_EQ(planner.nearest_free_cell(pt("0.25", "0.3")), (std::pair<std::size_t, std::size_t>{2, 2}));
  // Outside the bounds, halfway between rows 1 and 2: clamped to column 0, the lower row wins.
  EXPECT_EQ(planner.nearest_free_cell(pt("-5", "0.2")), (std::pair<std::size_t, std::size_t>{0, 1}));
}

TEST(RasterPlanner, NearestFreeCellSearchesPastBlockedRings) {
  // Everything blocked but the top-right cell: the search walks out to the last ring.
  const World world = world_from(R"({"bounds": [0, 0, 5, 5], "obstacles": [[[0, 0], [5, 0], [5, 4], [4, 4], [4, 5], [0, 5]]]})");
  const CSpace cspace(world);
  const Raster raster = rasterize(cspace, 5);
  ASSERT_EQ(raster.blocked_count(), 24u);
  const RasterPlanner planner(raster, cspace);
  EXPECT_EQ(planner.nearest_free_cell(pt("0", "0")), (std::pair<std::size_t, std::size_t>{4, 4}));
  const World full = world_from(R"({"bounds": [0, 0, 5, 5], "obstacles": [[[0, 0], [5, 0], [5, 5], [0, 5]]]})");
  const CSpace full_cspace(full);
  const Raster all_blocked = rasterize(full_cspace, 5);
  EXPECT_EQ(RasterPlanner(all_blocked, full_cspace).nearest_free_cell(pt("1", "1")), std::nullopt);
}

TEST(RasterPlanner, RasterOfAnotherWorldIsRejected) {
  const World a = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": []})");
  const World b = world_from(R"({"bounds": [0, 0, 5, 4], "obstacles": []})");
  const CSpace ca(a), cb(b);
  const Raster raster = rasterize(ca, 4);
  EXPECT_THROW(RasterPlanner(raster, cb), std::invalid_argument);
}
