// RasterPlanner: the course's graph-search homework's search_start_goal on the rasterised sphere world (routes at three
// resolutions, lengths against the exact visibility-graph optimum, every path re-checked
// independently), and on hand-made worlds where the answer is known exactly.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/rasterize.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/raster_grid.hpp>
#include <polyplan/grids/raster_planner.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
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

const std::string kSphereWorld = POLYPLAN_SOURCE_DIR "/data/worlds/sphere_world_polygons.json";

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
    for (const Query& q : world->queries) optimum.push_back(graph.plan(q).length);
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

using Report = PlanReport<ExactPoint>;

Report plan_once(const CSpace& cspace, std::size_t n, const Query& query,
                 Connectivity connectivity = Connectivity::full) {
  return RasterPlanner(cspace, RasterOptions{n, connectivity, {}}).plan(query);
}

}  // namespace

TEST_F(SphereWorld, JustRightResolutionFindsCheckedPathsWithinTwentyPercentOfTheOptimum) {
  ASSERT_EQ(world->queries.size(), 10u);  // 5 starts x 2 goals, as the course's graph-search homework runs them
  RasterPlanner planner(*cspace, RasterOptions{40});
  for (std::size_t i = 0; i < world->queries.size(); ++i) {
    const Query& q = world->queries[i];
    SCOPED_TRACE(q.name);
    const Report plan = planner.plan(q);
    ASSERT_TRUE(plan.found) << plan.why_not;
    ASSERT_GE(plan.path.size(), 2u);
    EXPECT_EQ(plan.path.front(), q.start);
    EXPECT_EQ(plan.path.back(), q.goal);
    // The optimum is a lower bound for every path; an 8-connected grid path is at most
    // 1.0824 times a straight line, plus the detours of cell centres around the discs.
    EXPECT_GE(plan.length, optimum[i] - 1e-9);
    EXPECT_LE(plan.length, 1.2 * optimum[i]);
    EXPECT_TRUE(plan.certificate.certified);
    const PathCheck independent = check_path(*cspace, plan.path);
    EXPECT_TRUE(independent.valid) << independent.reason;
    // The reported length is the polyline's, recomputed here from its points.
    double length = 0;
    for (std::size_t k = 1; k < plan.path.size(); ++k)
      length += std::hypot(to_double(plan.path[k].x) - to_double(plan.path[k - 1].x),
                           to_double(plan.path[k].y) - to_double(plan.path[k - 1].y));
    EXPECT_NEAR(plan.length, length, 1e-9);
    // The snapped cells are the free cells nearest to start and goal.
    const auto start_cell = planner.nearest_free_cell(q.start), goal_cell = planner.nearest_free_cell(q.goal);
    ASSERT_TRUE(start_cell && goal_cell);
    EXPECT_FALSE(planner.raster().is_blocked(start_cell->first, start_cell->second));
    EXPECT_EQ(plan.facts.at(RasterFacts::start_cell), cell_fact(start_cell->first, start_cell->second));
    EXPECT_EQ(plan.facts.at(RasterFacts::goal_cell), cell_fact(goal_cell->first, goal_cell->second));
  }
}

TEST_F(SphereWorld, CoarseGridClosesTheGapsThatTheJustRightGridKeeps) {
  // Discs A (centre (-4.4, 2), r 3.4) and B ((1.6, 2), r 1.4) leave a gap x in (-1, 0.2) on
  // y = 2; disc C ((4, -6.3), r 2.5) leaves 1.2 under it above the bottom wall. Cells 2 wide
  // (n = 10) close both; cells 0.5 (n = 40) and 0.1 (n = 200) keep both.
  const Query& below_gap_to_top = world->queries[1];             // (-0.4, -1.5) -> (-0.4, 8.5)
  const Query& bottom_left_to_bottom_right = world->queries[5];  // (-9, -9) -> (8.5, -9)
  for (const std::size_t n : {10, 40, 200}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    RasterPlanner planner(*cspace, RasterOptions{n});
    const Report up = planner.plan(below_gap_to_top), along = planner.plan(bottom_left_to_bottom_right);
    ASSERT_TRUE(up.found && along.found);
    const double x_at_gap = *first_crossing_of_y(up.path, 2);
    const double y_under_c = *first_crossing_of_x(along.path, 4);
    if (n == 10) {
      EXPECT_GT(x_at_gap, 3.0);    // round the right of B
      EXPECT_GT(y_under_c, -3.8);  // over C
      EXPECT_GT(up.length, 1.8 * optimum[1]);
      EXPECT_GT(along.length, 1.8 * optimum[5]);
    } else {
      EXPECT_GT(x_at_gap, -1.0);  // through the gap
      EXPECT_LT(x_at_gap, 0.2);
      EXPECT_LT(y_under_c, -8.8);  // under C
      EXPECT_LT(up.length, 1.1 * optimum[1]);
      EXPECT_LT(along.length, 1.1 * optimum[5]);
    }
  }
}

TEST_F(SphereWorld, CoarsePathsAreCheckedLikeEveryOther) {
  RasterPlanner planner(*cspace, RasterOptions{10});
  for (const Query& q : world->queries) {
    const Report plan = planner.plan(q);
    if (plan.found) EXPECT_TRUE(check_path(*cspace, plan.path).valid) << q.name;
    else EXPECT_NE(plan.why_not.find("is not a valid motion"), std::string::npos) << q.name << ": " << plan.why_not;
  }
}

TEST(RasterPlanner, JoinFromTheStartThroughAnObstacleIsRefusedWithTheReason) {
  // Cells 2 x 2; the square (0.5, 1.5)² blocks cell (0, 0). The start (0.2, 0.2) is equally near
  // the centres (3, 1) and (1, 3) (squared distance 8.48): the lower index, cell (1, 0), wins.
  // The join (0.2, 0.2) -> (3, 1) passes through the square (at x = 1.4 it is at y = 0.543).
  const World world =
      world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]]})");
  const CSpace cspace(world);
  const Query query{pt("0.2", "0.2"), pt("3.5", "3.5"), "q"};
  const Report plan = plan_once(cspace, 2, query);
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_EQ(plan.facts.at(RasterFacts::start_cell), (FactCell{1, 0}));
  // The refused polyline, checked here independently, is what the reason quotes.
  const PathCheck check = check_path(cspace, {pt("0.2", "0.2"), pt("3", "1"), pt("3", "3"), pt("3.5", "3.5")});
  ASSERT_FALSE(check.valid);
  EXPECT_EQ(plan.why_not, "the grid path joined to start and goal is not a valid motion: " + check.reason);
  EXPECT_NE(plan.why_not.find("obstacles[0]"), std::string::npos) << plan.why_not;
  // Four times finer, the start's own cell (0, 0) = (0, 0.5)² is free: the join is short and free.
  const Report fine = plan_once(cspace, 8, query);
  EXPECT_TRUE(fine.found) << fine.why_not;
  EXPECT_EQ(fine.facts.at(RasterFacts::start_cell), (FactCell{0, 0}));
}

TEST(RasterPlanner, StraightRunsKeepOnlyTheirEndsAndLengthsAreExactMultiples) {
  const World world = world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": []})");
  const CSpace cspace(world);
  RasterPlanner planner(cspace, RasterOptions{10});
  const Report along = planner.plan({pt("0.5", "0.5"), pt("9.5", "0.5"), "q"});
  EXPECT_EQ(along.path, (std::vector<ExactPoint>{pt("0.5", "0.5"), pt("9.5", "0.5")}));  // start and goal are centres
  EXPECT_EQ(along.facts.at(SearchFacts::path_edges), 9);
  EXPECT_DOUBLE_EQ(along.length, 9.0);
  EXPECT_DOUBLE_EQ(along.facts.at(RasterFacts::grid_cost), 9.0);
  const Report diagonal = planner.plan({pt("0.5", "0.5"), pt("9.5", "9.5"), "q"});
  EXPECT_EQ(diagonal.path, (std::vector<ExactPoint>{pt("0.5", "0.5"), pt("9.5", "9.5")}));
  EXPECT_NEAR(diagonal.length, 9 * std::sqrt(2.0), 1e-12);
  // 4-connected from cell (0, 0) to cell (3, 1): 4 unit moves in some order, each kept corner
  // joined to the next along an axis; the start joins its centre (0.5, 0.5), the goal is a centre.
  const Report four = plan_once(cspace, 10, {pt("0.2", "0.7"), pt("3.5", "1.5"), "q"}, Connectivity::axis_aligned);
  EXPECT_EQ(four.facts.at(SearchFacts::path_edges), 4);
  EXPECT_DOUBLE_EQ(four.facts.at(RasterFacts::grid_cost), 4.0);
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
  const Report plan = plan_once(cspace, 4, {pt("1.5", "1.5"), pt("2.5", "2.5"), "q"});
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_EQ(plan.why_not, "no path on the 4 x 4 grid from cell (1, 1) to cell (2, 2)");
}

TEST(RasterPlanner, StartInsideAnObstacleIsNotFoundWithTheReason) {
  const World world = world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})");
  const CSpace cspace(world);
  RasterPlanner planner(cspace, RasterOptions{8});
  const Report inside = planner.plan({pt("1.5", "1.5"), pt("3", "3"), "q"});
  EXPECT_FALSE(inside.found);
  EXPECT_TRUE(inside.path.empty());
  EXPECT_EQ(inside.why_not, "the start [3/2, 3/2] is not free: it is inside obstacles[0]");
  const Report outside = planner.plan({pt("0", "0"), pt("5", "3"), "q"});
  EXPECT_FALSE(outside.found);
  EXPECT_EQ(outside.why_not, "the goal [5, 3] is not free: it is outside the bounds");
  // Contact is free: a start on the obstacle's edge plans (its cell centre is beside it).
  const Report touching = planner.plan({pt("1", "1.5"), pt("3", "3"), "q"});
  EXPECT_TRUE(touching.found) << touching.why_not;
}

TEST(RasterPlanner, NearestFreeCellIsExact) {
  // Cells 0.1 wide from 0: centres at 0.05, 0.15, ... A point at x = 0.1 is exactly halfway
  // between two centres (a double computation would see 0.1 - 0.05 != 0.15 - 0.1); the lower index wins.
  const World world = world_from(R"({"bounds": [0, 0, 0.3, 0.3], "obstacles": []})");
  const CSpace cspace(world);
  const RasterPlanner planner(cspace, RasterOptions{3});
  EXPECT_EQ(planner.nearest_free_cell(pt("0.1", "0.1")), (std::pair<std::size_t, std::size_t>{0, 0}));
  EXPECT_EQ(planner.nearest_free_cell(pt("0.1000000000000000001", "0.1")), (std::pair<std::size_t, std::size_t>{1, 0}));
  EXPECT_EQ(planner.nearest_free_cell(pt("0.25", "0.3")), (std::pair<std::size_t, std::size_t>{2, 2}));
  // Outside the bounds, halfway between rows 1 and 2: clamped to column 0, the lower row wins.
  EXPECT_EQ(planner.nearest_free_cell(pt("-5", "0.2")), (std::pair<std::size_t, std::size_t>{0, 1}));
}

TEST(RasterPlanner, NearestFreeCellSearchesPastBlockedRings) {
  // Everything blocked but the top-right cell: the search walks out to the last ring.
  const World world =
      world_from(R"({"bounds": [0, 0, 5, 5], "obstacles": [[[0, 0], [5, 0], [5, 4], [4, 4], [4, 5], [0, 5]]]})");
  const CSpace cspace(world);
  const RasterPlanner planner(cspace, RasterOptions{5});
  ASSERT_EQ(planner.raster().blocked_count(), 24u);
  EXPECT_EQ(planner.nearest_free_cell(pt("0", "0")), (std::pair<std::size_t, std::size_t>{4, 4}));
  const World full = world_from(R"({"bounds": [0, 0, 5, 5], "obstacles": [[[0, 0], [5, 0], [5, 5], [0, 5]]]})");
  const CSpace full_cspace(full);
  EXPECT_EQ(RasterPlanner(full_cspace, RasterOptions{5}).nearest_free_cell(pt("1", "1")), std::nullopt);
}

TEST(RasterPlanner, AWorldWithoutBoundsOrAZeroResolutionIsRefused) {
  const CSpace unbounded(world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1]]]})"));
  EXPECT_THROW(RasterPlanner(unbounded, RasterOptions{10}), InputError);
  const CSpace bounded(world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": []})"));
  EXPECT_THROW(RasterPlanner(bounded, RasterOptions{0}), InputError);
}

TEST(RasterPlanner, RecordsTheCellsAndTheExpandedCentresForPictures) {
  const CSpace cspace(world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})"));
  RasterPlanner planner(cspace, RasterOptions{4});
  const Report plain = planner.plan({pt("0.5", "0.5"), pt("3.5", "3.5"), "q"});
  EXPECT_FALSE(plain.recording.cells);
  EXPECT_TRUE(plain.recording.expanded.empty());
  const Report recorded = planner.plan({pt("0.5", "0.5"), pt("3.5", "3.5"), "q"}, QueryOptions{true});
  ASSERT_TRUE(recorded.recording.cells);
  EXPECT_EQ(recorded.recording.cells->columns, 4u);
  EXPECT_EQ(recorded.recording.cells->state(1, 1), CellGrid::blocked);
  EXPECT_EQ(recorded.recording.cells->state(0, 0), CellGrid::free);
  EXPECT_EQ(static_cast<std::int64_t>(recorded.recording.expanded.size()), recorded.facts.at(SearchFacts::expanded));
  EXPECT_EQ(recorded.path, plain.path);
}

// office.json's raster at 400 cells, the issue's case: the textbook's weighted A* (w = 20, no
// reopening) expands fewer cells than A*, each at most once (expanded <= generated); reopening
// expands more than A* there. The counts are deterministic; the times are bench/weighted_astar_bench's.
TEST(RasterPlanner, TextbookWeightedAStarExpandsFewerCellsThanAStarOnTheOffice) {
  const World world = read_world(POLYPLAN_SOURCE_DIR "/data/worlds/office.json");
  const CSpace cspace(world);
  struct Counts {
    std::int64_t expanded, generated;
    double length;
  };
  const auto counts = [&](Search algorithm, bool reopen) {
    RasterOptions options{400};
    options.search = {algorithm, 20.0};
    options.search.reopen = reopen;
    const Report r = RasterPlanner(cspace, options).plan(world.queries.front());
    EXPECT_TRUE(r.found) << to_string(algorithm);
    return Counts{r.facts.at(SearchFacts::expanded), r.facts.at(SearchFacts::generated), r.length};
  };
  const Counts astar = counts(Search::astar, false), textbook = counts(Search::wastar, false),
               reopening = counts(Search::wastar, true);
  EXPECT_LT(textbook.expanded, astar.expanded);
  EXPECT_LE(textbook.expanded, textbook.generated);
  EXPECT_GT(reopening.expanded, astar.expanded);
  EXPECT_LE(textbook.length, 20 * astar.length);
  EXPECT_LE(reopening.length, 20 * astar.length);
}

// The grid conventions reach the raster: on an empty 10 x 10 raster from cell (0, 0) to (9, 9)
// the grid path is 9 diagonals, costing 9 √2 by default, 9 at diagonal cost 1, 13.5 at 1.5, and
// 18 straight moves at cost 3 (two straight moves beat a diagonal dearer than 2) or 4-connected.
TEST(RasterPlanner, GridConventionsSetTheMovesAndTheirCosts) {
  const World world = world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": []})");
  const CSpace cspace(world);
  const auto cost = [&](OptionValues values) {  // through the registry's entry, as the CLI and Python
    values.emplace_back("resolution", "10");
    const auto planner = raster_planner_entry<TranslatingRobot>().make(cspace, values);
    return planner->plan({pt("0.5", "0.5"), pt("9.5", "9.5"), "q"}).facts.at(RasterFacts::grid_cost);
  };
  EXPECT_NEAR(cost({}), 9 * std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(cost({{"diagonal-cost", "1"}}), 9.0);
  EXPECT_DOUBLE_EQ(cost({{"diagonal-cost", "1.5"}}), 13.5);
  EXPECT_DOUBLE_EQ(cost({{"diagonal-cost", "3"}}), 18.0);
  EXPECT_DOUBLE_EQ(cost({{"connectivity", "4"}}), 18.0);
  EXPECT_NEAR(cost({{"diagonal-cost", "sqrt2"}, {"corner-cutting", "true"}}), 9 * std::sqrt(2.0), 1e-12);
  // The report says which grid it searched.
  const auto planner = raster_planner_entry<TranslatingRobot>().make(
      cspace, {{"connectivity", "4"}, {"corner-cutting", "true"}, {"diagonal-cost", "1.5"}});
  const Report report = planner->plan({pt("0.5", "0.5"), pt("9.5", "9.5"), "q"});
  EXPECT_EQ(report.facts.at(RasterFacts::connectivity), 4);
  EXPECT_TRUE(report.facts.at(RasterFacts::corner_cutting));
  EXPECT_EQ(report.facts.at(RasterFacts::diagonal_cost), "1.5");
  // A number needs square cells: 10 x 5 bounds cut 10 x 10 give cells 1 x 0.5.
  const World flat = world_from(R"({"bounds": [0, 0, 10, 5], "obstacles": []})");
  const CSpace flat_cspace(flat);
  RasterOptions o;
  o.diagonal_cost = DiagonalCost{3, 2};
  EXPECT_THROW(RasterPlanner(flat_cspace, o), InputError);
}
