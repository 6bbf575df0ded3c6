// GvdGridPlanner: a corridor whose GVD and clearance are known exactly, the climbs to the GVD and
// the path along it, paths where only one obstacle's fronts meet (a room without obstacles, a
// door in one wall), every office query within one free component found, the answers that are
// not paths (a start in an obstacle, two free components), the picture, and every path
// re-checked independently.
#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/grids/grid_facts.hpp>
#include <polyplan/grids/gvd_grid_planner.hpp>
#include <polyplan/grids/raster_planner.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace polyplan;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

using Report = PlanReport<ExactPoint>;

// Bounds 20 x 20 in 1 x 1 cells (resolution 20); walls below y = 8 and above y = 13 leave a
// corridor of rows 8 to 12. Row 10 is 3 cells from both walls, so it is the GVD away from the
// ends, and its centres are exactly 2.5 from the walls: the clearance bound (3 - 1/2) x 1.
const char* kCorridor = R"({"bounds": [0, 0, 20, 20], "obstacles": [
    [[0, 0], [20, 0], [20, 8], [0, 8]], [[0, 13], [20, 13], [20, 20], [0, 20]]]})";

GridCell cell(std::size_t x, std::size_t y) { return x + y * 20; }

// (column, row) of a cell of the 20 x 20 grid, as the facts give it.
FactCell cell_of(GridCell c) { return {std::int64_t(c % 20), std::int64_t(c / 20)}; }

}  // namespace

TEST(GvdGridPlanner, AlongTheMiddleOfACorridorWithItsExactClearance) {
  const World world = world_from(kCorridor);
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{20});
  for (std::size_t x = 4; x < 16; ++x) {
    EXPECT_TRUE(planner.brushfire().gvd[cell(x, 10)]) << x;
    EXPECT_FALSE(planner.brushfire().gvd[cell(x, 9)]) << x;
    EXPECT_FALSE(planner.brushfire().gvd[cell(x, 11)]) << x;
  }
  const Report along = planner.plan({pt("5.5", "10.5"), pt("14.5", "10.5"), "q"});
  ASSERT_TRUE(along.found) << along.why_not;
  EXPECT_EQ(along.path, (std::vector<ExactPoint>{pt("5.5", "10.5"), pt("14.5", "10.5")}));  // straight: no turn kept
  EXPECT_DOUBLE_EQ(along.length, 9.0);
  EXPECT_DOUBLE_EQ(along.facts.at(GvdFacts::clearance_bound), 2.5);
  EXPECT_DOUBLE_EQ(along.bottleneck.value().clearance, 2.5);  // measured: 2.5 from both walls
  EXPECT_EQ(along.facts.at(RoadmapFacts::kind), "gvd-grid");
  EXPECT_EQ(along.facts.at(RasterFacts::cells_per_axis), 20);
  EXPECT_EQ(along.facts.at(GvdFacts::max_distance), 3);
  EXPECT_EQ(along.facts.at(GvdFacts::cells), along.facts.at(RoadmapFacts::vertices));
  EXPECT_GT(along.facts.at(RoadmapFacts::edges), 0);
  EXPECT_EQ(along.facts.at(GvdFacts::start_cell), (FactCell{5, 10}));
  EXPECT_EQ(along.facts.at(SearchFacts::path_edges), 9);
  EXPECT_TRUE(check_path(cspace, along.path).valid);
}

TEST(GvdGridPlanner, ClimbsToTheGvdFollowsItAndDescends) {
  const World world = world_from(kCorridor);
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{20});
  // From row 8 (next to the bottom wall) and row 12 (next to the top one).
  const Query query{pt("5.5", "8.5"), pt("14.5", "12.5"), "q"};
  const std::vector<GridCell> up = planner.climb(cell(5, 8)), down = planner.climb(cell(14, 12));
  ASSERT_GE(up.size(), 2u);
  ASSERT_GE(down.size(), 2u);
  const Brushfire& field = planner.brushfire();
  for (std::size_t k = 1; k < up.size(); ++k)
    EXPECT_TRUE(field.gvd[up[k]] || field.distance[up[k]] > field.distance[up[k - 1]]) << "a climb only goes up";
  EXPECT_TRUE(field.gvd[up.back()]);
  EXPECT_TRUE(field.gvd[down.back()]);

  const Report plan = planner.plan(query);
  ASSERT_TRUE(plan.found) << plan.why_not;
  EXPECT_EQ(plan.path.front(), query.start);
  EXPECT_EQ(plan.path.back(), query.goal);
  EXPECT_TRUE(check_path(cspace, plan.path).valid);
  EXPECT_EQ(plan.facts.at(GvdFacts::start_cell), cell_of(up.back()));
  EXPECT_EQ(plan.facts.at(GvdFacts::goal_cell), cell_of(down.back()));
  // Every corner between start and goal is a cell centre of the start's climb, of the GVD, or of
  // the goal's climb, in that order: once on the GVD, the path leaves it only for the descent.
  const Raster& raster = planner.raster();
  std::set<GridCell> climb_up(up.begin(), up.end()), climb_down(down.begin(), down.end());
  int stage = 0;  // 0 climbing, 1 on the GVD, 2 descending
  for (std::size_t k = 1; k + 1 < plan.path.size(); ++k) {
    const auto [x, y] = std::pair{static_cast<std::size_t>(to_double(plan.path[k].x)),
                                  static_cast<std::size_t>(to_double(plan.path[k].y))};
    ASSERT_EQ(raster.cell_center(x, y), plan.path[k]) << k;
    const GridCell c = cell(x, y);
    if (stage == 0 && !climb_up.count(c)) stage = 1;
    if (stage == 1 && !field.gvd[c]) stage = 2;
    if (stage == 2) {
      EXPECT_TRUE(climb_down.count(c)) << "corner " << k << " is off the GVD and off the descent";
    }
  }
  EXPECT_GE(stage, 1) << "no corner on the GVD";
  // The path's cells are at least 1 from the walls (rows 8 and 12): clearance (1 - 1/2) x 1.
  EXPECT_DOUBLE_EQ(plan.facts.at(GvdFacts::clearance_bound), 0.5);
}

TEST(GvdGridPlanner, StartInAnObstacleIsAnAnswerWithItsReason) {
  const World world = world_from(kCorridor);
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{20});
  const Report plan = planner.plan({pt("5", "4"), pt("14.5", "10.5"), "q"});
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_EQ(plan.why_not, *cspace.query_not_free({pt("5", "4"), pt("14.5", "10.5"), "q"}));
  EXPECT_NE(plan.why_not.find("not free"), std::string::npos) << plan.why_not;
}

TEST(GvdGridPlanner, WithoutObstaclesTheBoundsFrontsMeetOnTheGvd) {
  // No obstacle but the bounds: the outside's fronts from the four sides meet on the GVD (the
  // medial axis of the square), so there is a path between any two cells.
  const World world = world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": []})");
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{10});
  EXPECT_GT(planner.brushfire().gvd_cells, 0u);
  const Report plan = planner.plan({pt("1.5", "1.5"), pt("8.5", "2.5"), "q"});
  ASSERT_TRUE(plan.found) << plan.why_not;
  EXPECT_TRUE(check_path(cspace, plan.path).valid);
}

// A room in one wall (cells 1 to 13) with a door, cell (7, 1), and a post inside, cell (7, 7).
const char* kRoomWithADoor = R"({"bounds": [0, 0, 15, 15], "obstacles": [
    [[1, 1], [7, 1], [7, 2], [2, 2], [2, 13], [13, 13], [13, 2], [8, 2], [8, 1], [14, 1], [14, 14], [1, 14]],
    [[7, 7], [8, 7], [8, 8], [7, 8]]]})";

TEST(GvdGridPlanner, ThroughADoorBetweenTwoPartsOfOneWall) {
  // The door lies between two parts of the same obstacle; the fronts from its two jambs meet in
  // it, so the GVD round the post meets the GVD outside there.
  const World world = world_from(kRoomWithADoor);
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{15});
  EXPECT_TRUE(planner.brushfire().gvd[planner.brushfire().index(7, 1)]);
  const Report plan = planner.plan({pt("0.5", "7.5"), pt("4.5", "7.5"), "q"});
  ASSERT_TRUE(plan.found) << plan.why_not;
  EXPECT_TRUE(check_path(cspace, plan.path).valid);
}

TEST(GvdGridPlanner, StartAndGoalInTwoFreeComponentsAreAnAnswerNotAPath) {
  // A wall from the bottom to the top of the bounds: each side has its GVD, and they never meet.
  const World world = world_from(R"({"bounds": [0, 0, 15, 15], "obstacles": [[[7, 0], [8, 0], [8, 15], [7, 15]]]})");
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{15});
  const Report plan = planner.plan({pt("2.5", "7.5"), pt("12.5", "7.5"), "q"});
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_NE(plan.why_not.find("the GVD does not connect cell"), std::string::npos) << plan.why_not;
}

TEST(GvdGridPlanner, WorldsWithoutBoundsAreRefusedNamingTheFile) {
  const World world = world_from(R"({"obstacles": [[[0, 0], [1, 0], [1, 1]]]})");
  const CSpace cspace(world);
  try {
    GvdGridPlanner planner(cspace);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json"), std::string::npos) << e.what();
  }
}

TEST(GvdGridPlanner, EveryOfficeQueryWithinOneFreeComponentIsFound) {
  // The shipped queries, and from the first query's start to free points all over the office
  // (every room, corridor and doorway): wherever start and goal share a free component of the
  // exact C-space, the GVD joins their climbs, so the answer is a path — or the exact check
  // refusing the joins, which why_not says.
  const World world = read_world(POLYPLAN_SOURCE_DIR "/data/worlds/office.json");
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace);
  std::vector<Query> queries = world.queries;
  for (int y = 1; y < 30; y += 4)
    for (int x = 1; x < 40; x += 4) {
      const ExactPoint goal{Rational(2 * x + 1, 2), Rational(2 * y + 1, 2)};
      if (!cspace.locate(goal).components.empty()) queries.push_back({world.queries.front().start, goal, "lattice"});
    }
  int together = 0, found = 0;
  for (const Query& q : queries) {
    const auto from = cspace.locate(q.start).components, to = cspace.locate(q.goal).components;
    if (from.size() != 1 || to.size() != 1 || from != to) continue;
    ++together;
    const Report plan = planner.plan(q);
    if (!plan.found) {
      EXPECT_NE(plan.why_not.find("is not a valid motion"), std::string::npos) << q.name << ": " << plan.why_not;
      continue;
    }
    ++found;
    const PathCheck check = check_path(cspace, plan.path);
    EXPECT_TRUE(check.valid) << q.name << ": " << check.reason;
    EXPECT_GT(plan.facts.at(GvdFacts::clearance_bound), 0) << q.name;
  }
  EXPECT_GT(together, 40);
  EXPECT_EQ(found, together);
}

TEST(GvdGridPlanner, OnASquareMovingAiMapTheResolutionOfItsSideGivesTheMapsOwnCells) {
  // README's advice: arena.map is 49 x 49, traced into a world of bounds [0, 0, 49, 49].
  const GridMap map = read_movingai_map(POLYPLAN_SOURCE_DIR "/data/movingai/maps/arena.map");
  ASSERT_EQ(map.width, map.height);
  const CSpace cspace(world_from_grid(map));
  GvdGridPlanner planner(cspace, GvdGridOptions{static_cast<std::size_t>(map.width)});
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      EXPECT_EQ(planner.raster().is_blocked(x, y), map.is_blocked(x, y)) << x << ", " << y;
}

TEST(GvdGridPlanner, PictureIsTheDistanceFieldWithTheGvdAndRasterPicturesKeepTheirLook) {
  const World world = world_from(kCorridor);
  const CSpace cspace(world);
  GvdGridPlanner planner(cspace, GvdGridOptions{20});
  const Report plan = planner.plan({pt("5.5", "10.5"), pt("14.5", "10.5"), "q"}, QueryOptions{true});
  ASSERT_TRUE(plan.recording.cells);
  EXPECT_EQ(plan.recording.cells->values.size(), 400u);
  EXPECT_EQ(plan.recording.cells->values[cell(10, 10)], 3.0f);
  EXPECT_EQ(plan.recording.cells->state(10, 10), CellGrid::ridge);
  EXPECT_EQ(plan.recording.cells->state(10, 9), CellGrid::free);
  EXPECT_EQ(plan.recording.cells->state(10, 3), CellGrid::blocked);
  const std::string picture = draw_plan(cspace, {plan}).str();
  EXPECT_NE(picture.find(theme::heat[0]), std::string::npos);
  EXPECT_NE(picture.find(theme::heat[theme::heat_steps - 1]), std::string::npos);
  EXPECT_NE(picture.find(theme::ridge_cell), std::string::npos);
  EXPECT_NE(picture.find("ridge cells"), std::string::npos);
  // A raster's cells have no values and no ridge: none of the new colours.
  const Report raster =
      RasterPlanner(cspace, RasterOptions{20}).plan({pt("5.5", "10.5"), pt("14.5", "10.5"), "q"}, QueryOptions{true});
  const std::string plain = draw_plan(cspace, {raster}).str();
  EXPECT_EQ(plain.find(theme::ridge_cell), std::string::npos);
  EXPECT_EQ(plain.find("ridge cells"), std::string::npos);
  EXPECT_NE(plain.find("free cells"), std::string::npos);
}
