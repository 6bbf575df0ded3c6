// search/movingai_grid: the MovingAI octile benchmark on the implicit grid graph. Every arena and
// den312d query must give the scenario file's optimal length within its printed precision, and
// every path is re-checked here against the map itself (king moves between free cells, no corner
// cut, the sum of 1s and sqrt(2)s equal to the reported cost).
#include <polyplan/grids/movingai_grid.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

const std::string kBenchmarks = POLYPLAN_SOURCE_DIR "/data/movingai";

GridMap load_map(const std::string& name) { return read_movingai_map(kBenchmarks + "/maps/" + name + ".map"); }
std::vector<ScenarioQuery> load_scenarios(const std::string& name) {
  return read_scenarios(kBenchmarks + "/scenarios/" + name + ".map.scen");
}

// The test's own reading of the file's precision: digits after the point (the files print no exponents).
double printed_tolerance(const std::string& text) {
  const auto point = text.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(text.size() - point - 1);
  return 0.5 * std::pow(10.0, -decimals);
}

// The path re-walked on the map: each step a king move between free cells that cuts no corner.
// Returns the length summed here, or NaN (with a failure) for an invalid path.
double checked_length(const GridMap& map, const GridGraph& graph, const std::vector<GridCell>& path,
                      const ScenarioQuery& q) {
  EXPECT_FALSE(path.empty());
  if (path.empty()) return NAN;
  const auto at = [&](GridCell c) { return graph.coordinates(c); };
  EXPECT_EQ(at(path.front()), (std::vector<GridCoordinate>{q.start_x, q.start_y}));
  EXPECT_EQ(at(path.back()), (std::vector<GridCoordinate>{q.goal_x, q.goal_y}));
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const auto a = at(path[i]), b = at(path[i + 1]);
    const int dx = b[0] - a[0], dy = b[1] - a[1];
    const bool king = std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dx || dy);
    const bool free = !map.is_blocked(a[0], a[1]) && !map.is_blocked(b[0], b[1]);
    const bool no_corner_cut = !(dx && dy) || (!map.is_blocked(a[0] + dx, a[1]) && !map.is_blocked(a[0], a[1] + dy));
    if (!(king && free && no_corner_cut)) {
      ADD_FAILURE() << "invalid step " << i << " (" << a[0] << ", " << a[1] << ") -> (" << b[0] << ", " << b[1] << ")";
      return NAN;
    }
    length += dx && dy ? std::sqrt(2.0) : 1.0;
  }
  return length;
}

struct Outcome {
  std::size_t queries = 0, mismatches = 0;
};

// Every query of the map's scenario file with A*, judged by the test's own tolerance.
Outcome run_map(const std::string& name) {
  const GridMap map = load_map(name);
  const auto scenarios = load_scenarios(name);
  check_scenarios_fit(map, scenarios, name);
  MovingAiGridSearch grid(map);
  Outcome outcome;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const ScenarioQuery& q = scenarios[i];
    const auto r = grid.search(q);
    ++outcome.queries;
    // These files have a path for every query.
    if (!r.found) {
      ++outcome.mismatches;
      ADD_FAILURE() << name << " query " << i << ": no path, the file says " << q.octile_text;
      continue;
    }
    EXPECT_NEAR(checked_length(map, grid.graph(), r.path, q), r.cost, 1e-9) << name << " query " << i;
    if (std::abs(r.cost - q.octile_length) > printed_tolerance(q.octile_text) + 1e-12 * q.octile_length) {
      ++outcome.mismatches;
      ADD_FAILURE() << name << " query " << i << ": length " << r.cost << ", the file says " << q.octile_text;
    }
    EXPECT_TRUE(matches(octile_expectation(q), r.found, r.cost)) << name << " query " << i;
  }
  return outcome;
}

TEST(MovingAiGrid, EveryArenaQueryHasTheFilesOptimalLength) {
  const Outcome o = run_map("arena");
  EXPECT_EQ(o.queries, 160u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(MovingAiGrid, EveryDen312dQueryHasTheFilesOptimalLength) {
  const Outcome o = run_map("den312d");
  EXPECT_EQ(o.queries, 320u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(MovingAiGrid, DijkstraFindsTheSameLengthsWithMoreExpansions) {
  const GridMap map = load_map("den312d");
  const auto scenarios = load_scenarios("den312d");
  MovingAiGridSearch grid(map);
  // The last queries of the file: its longest bucket, where the heuristic matters most.
  for (std::size_t i = scenarios.size() - 5; i < scenarios.size(); ++i) {
    const auto astar = grid.search(scenarios[i], {Search::astar});
    const auto dijkstra = grid.search(scenarios[i], {Search::dijkstra});
    ASSERT_TRUE(astar.found && dijkstra.found) << "query " << i;
    EXPECT_NEAR(dijkstra.cost, astar.cost, 1e-9) << "query " << i;
    EXPECT_NEAR(dijkstra.cost, scenarios[i].octile_length, printed_tolerance(scenarios[i].octile_text))
        << "query " << i;
    EXPECT_GT(dijkstra.expanded, astar.expanded) << "query " << i;
  }
}

TEST(MovingAiGrid, WeightedAStarStaysWithinTwiceTheOptimum) {
  for (const std::string name : {"arena", "den312d"}) {
    const GridMap map = load_map(name);
    const auto scenarios = load_scenarios(name);
    MovingAiGridSearch grid(map);
    std::size_t longer = 0;
    for (std::size_t i = 0; i < scenarios.size(); ++i) {
      const ScenarioQuery& q = scenarios[i];
      const auto r = grid.search(q, {Search::wastar, 2.0});
      ASSERT_TRUE(r.found) << name << " query " << i;
      const double tolerance = printed_tolerance(q.octile_text);
      EXPECT_NEAR(checked_length(map, grid.graph(), r.path, q), r.cost, 1e-9) << name << " query " << i;
      EXPECT_LE(r.cost, 2 * (q.octile_length + tolerance)) << name << " query " << i;
      EXPECT_GE(r.cost, q.octile_length - tolerance) << name << " query " << i;  // never below the optimum
      longer += r.cost > q.octile_length + tolerance;
    }
    // Not a requirement, a sign that the weight is applied at all: some paths are suboptimal.
    EXPECT_GT(longer, 0u) << name;
  }
}

// row 0: . @ .     (1, 0) blocked
// row 1: . . .
GridMap tiny_map() { return {"tiny.map", 3, 2, {false, true, false, false, false, false}}; }

TEST(MovingAiGrid, CellsAreRowMajorAndDiagonalsNeverCutCorners) {
  const GridMap map = tiny_map();
  const GridGraph g = movingai_grid(map);
  EXPECT_EQ(g.cell({2, 1}), 5u);
  EXPECT_FALSE(g.is_free(1));
  // From (0, 0): (1, 0) is blocked and the diagonal to (1, 1) would cut its corner; only (0, 1).
  std::vector<GridCell> from_origin;
  for (auto [e, end] = out_edges(g.cell({0, 0}), g); e != end; ++e) from_origin.push_back(target(*e, g));
  EXPECT_EQ(from_origin, (std::vector<GridCell>{g.cell({0, 1})}));
  // Around the blocked cell: (0, 0) -> (0, 1) -> (1, 1) -> (2, 1) -> (2, 0) = 4, no diagonal allowed.
  ScenarioQuery q;
  q.map_width = 3;
  q.map_height = 2;
  q.start_x = 0, q.start_y = 0, q.goal_x = 2, q.goal_y = 0;
  MovingAiGridSearch grid(map);
  const auto r = grid.search(q);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.cost, 4.0);
}

TEST(MovingAiGrid, PrintedPrecisionIsHalfAUnitInTheLastDecimal) {
  EXPECT_DOUBLE_EQ(half_unit_in_last_place("3.41421"), 5e-6);
  EXPECT_DOUBLE_EQ(half_unit_in_last_place("132.40"), 0.005);
  EXPECT_DOUBLE_EQ(half_unit_in_last_place("4"), 0.5);
  EXPECT_DOUBLE_EQ(half_unit_in_last_place("1.5e2"), 5.0);
  EXPECT_DOUBLE_EQ(half_unit_in_last_place("2.50e-3"), 5e-6);

  ScenarioQuery q;
  q.start_x = 1, q.goal_x = 2;
  q.octile_length = 3.41421, q.octile_text = "3.41421";
  const OctileExpectation e = octile_expectation(q);
  EXPECT_TRUE(e.found);
  EXPECT_TRUE(matches(e, true, 2 + std::sqrt(2.0)));  // 3.4142136 rounds to 3.41421
  EXPECT_FALSE(matches(e, true, 3.414216));           // 6e-6 away
  EXPECT_FALSE(matches(e, false, 0));
  // The files' lengths carry single-precision error: 235.76450199 printed "235.764" (lak303d query
  // 587) matches, 0.0005 + 2^-24 * 235.764 = 0.000514 being the limit.
  q.octile_length = 235.764, q.octile_text = "235.764";
  EXPECT_NEAR(octile_expectation(q).tolerance, 0.0005 + 235.764 / 16777216, 1e-15);
  EXPECT_TRUE(matches(octile_expectation(q), true, 235.76450198781743));
  EXPECT_FALSE(matches(octile_expectation(q), true, 235.76452));
  EXPECT_FALSE(matches(octile_expectation(q), true, 235.76348));
  q.octile_length = 0, q.octile_text = "0";  // 0 between different cells: the old files' "no path"
  EXPECT_FALSE(octile_expectation(q).found);
  EXPECT_TRUE(matches(octile_expectation(q), false, 0));
  EXPECT_FALSE(matches(octile_expectation(q), true, 0.4));
  q.goal_x = 1;  // 0 from a cell to itself is a path
  EXPECT_TRUE(octile_expectation(q).found);
  EXPECT_TRUE(matches(octile_expectation(q), true, 0));
}

// The message of the InputError check_scenarios_fit throws for one query, or "" if none.
std::string fit_error(const GridMap& map, const ScenarioQuery& q) {
  try {
    check_scenarios_fit(map, {q}, "x.scen");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MovingAiGrid, QueriesThatDoNotFitTheMapAreBadInput) {
  const GridMap map = load_map("arena");  // 49 x 49, row 0 all blocked, (1, 11) free
  ScenarioQuery q;
  q.line = 7;
  q.map_width = 49, q.map_height = 49;
  q.start_x = 1, q.start_y = 11, q.goal_x = 1, q.goal_y = 12;
  q.octile_length = 1, q.octile_text = "1";
  EXPECT_EQ(fit_error(map, q), "");
  ScenarioQuery other_map = q;
  other_map.map_width = 65;
  EXPECT_EQ(fit_error(map, other_map), "x.scen: line 7: the query is for a 65x49 map, " + map.source + " is 49x49");
  ScenarioQuery outside = q;
  outside.goal_x = 49;
  EXPECT_EQ(fit_error(map, outside), "x.scen: line 7: goal (49, 12) is outside the 49x49 map");
  ScenarioQuery blocked = q;
  blocked.start_y = 0;
  EXPECT_EQ(fit_error(map, blocked), "x.scen: line 7: start (1, 0) is a blocked cell of " + map.source);
  // The search itself refuses what the check would have reported.
  MovingAiGridSearch grid(map);
  EXPECT_THROW(grid.search(blocked), std::invalid_argument);
  EXPECT_THROW(grid.search(outside), std::invalid_argument);
  EXPECT_THROW(grid.search(q, {Search::wastar, 0.5}), std::invalid_argument);
}

// The grid conventions on a MovingAI map, lengths counted by hand. Row 0 ". @ .", row 1 ". . .":
// from (0, 0) to (2, 0) the benchmark's grid goes round (4); cutting the blocked cell's corners,
// two diagonals (2 √2, or 2 at diagonal cost 1); 4-connected, round again (4).
TEST(MovingAiGrid, GridConventionsCutCornersAndPriceDiagonals) {
  GridMap map = tiny_map();
  ScenarioQuery q;
  q.map_width = 3;
  q.map_height = 2;
  q.start_x = 0, q.start_y = 0, q.goal_x = 2, q.goal_y = 0;
  const auto length = [&](GridConventions conventions) {
    MovingAiGridSearch grid(map, conventions);
    const auto r = grid.search(q);
    EXPECT_TRUE(r.found);
    return r.cost;
  };
  EXPECT_DOUBLE_EQ(length({}), 4.0);
  EXPECT_DOUBLE_EQ(length({Connectivity::full, true, {}}), 2 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(length({Connectivity::full, true, DiagonalCost{1, 1}}), 2.0);
  EXPECT_DOUBLE_EQ(length({Connectivity::axis_aligned, true, {}}), 4.0);
  // On an open 3 x 3 map from (0, 0) to (2, 2): two diagonals at 1.5 (3), four straight moves at 3 (4).
  map.width = map.height = 3;
  map.blocked.assign(9, false);
  q.map_width = q.map_height = 3;
  q.goal_x = q.goal_y = 2;
  EXPECT_DOUBLE_EQ(length({Connectivity::full, false, DiagonalCost{3, 2}}), 3.0);
  EXPECT_DOUBLE_EQ(length({Connectivity::full, false, DiagonalCost{3, 1}}), 4.0);
}

}  // namespace
}  // namespace polyplan
