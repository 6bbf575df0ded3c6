// search/grid_graph: the implicit grid as a BGL graph, searched with the one shortest_path. Costs
// are checked against closed forms (octile, wrap-around distances) and against an independent
// flat-array Dijkstra/BFS written here; lazy cells are evaluated once each and only where touched.
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/grid_graph.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace polyplan {
namespace {

const double root2 = std::sqrt(2.0);

std::vector<GridAxis> plane_axes(int w, int h) { return {{w, AxisKind::bounded, 1.0}, {h, AxisKind::bounded, 1.0}}; }

// A w x h bitmap from rows of text, '.' free and '@' blocked, row 0 = y 0.
std::vector<std::uint8_t> bitmap(const std::vector<std::string>& rows) {
  std::vector<std::uint8_t> free;
  for (const auto& r : rows)
    for (char c : r) free.push_back(c == '.');
  return free;
}

std::set<GridCell> neighbours(const GridGraph& g, GridCell c) {
  std::set<GridCell> out;
  for (auto [e, end] = out_edges(c, g); e != end; ++e) {
    EXPECT_EQ(source(*e, g), c);
    out.insert(target(*e, g));
  }
  return out;
}

TEST(GridGraph, EightConnectedNeverCutsACorner) {
  // (1,1) in the middle; (2,1) blocked: moves to (2,0) and (2,2) would brush it.
  const GridGraph g(plane_axes(3, 3), Connectivity::full, StepCost::euclidean, bitmap({"...", "..@", "..."}));
  const GridCell centre = g.cell({1, 1});
  EXPECT_EQ(neighbours(g, centre),
            (std::set<GridCell>{g.cell({0, 0}), g.cell({1, 0}), g.cell({0, 1}), g.cell({0, 2}), g.cell({1, 2})}));
  EXPECT_EQ(out_degree(g.cell({0, 0}), g), 3u);  // a corner of a bounded grid
  const GridGraph four(plane_axes(3, 3), Connectivity::axis_aligned, StepCost::euclidean,
                       bitmap({"...", "..@", "..."}));
  EXPECT_EQ(neighbours(four, centre), (std::set<GridCell>{four.cell({1, 0}), four.cell({0, 1}), four.cell({1, 2})}));
}

TEST(GridGraph, DiagonalMoveCostsSqrt2AndTheOctilePathIsOptimal) {
  const GridGraph g(plane_axes(20, 10), Connectivity::full, StepCost::euclidean, std::vector<std::uint8_t>(200, 1));
  const GridCell s = g.cell({0, 0}), t = g.cell({9, 5});
  const auto astar =
      shortest_path(g, s, t, {Search::astar}, GridDistanceTo(g, t, GridMetric::octile), GridMoveCost{&g});
  ASSERT_TRUE(astar.found);
  EXPECT_DOUBLE_EQ(astar.cost, 5 * root2 + 4);
  EXPECT_DOUBLE_EQ(GridDistanceTo(g, t, GridMetric::octile)(s), 5 * root2 + 4);
  EXPECT_DOUBLE_EQ(GridDistanceTo(g, t, GridMetric::euclidean)(s), std::sqrt(81.0 + 25.0));
  EXPECT_DOUBLE_EQ(GridDistanceTo(g, t, GridMetric::sum_of_axes)(s), 14.0);
  // On an empty grid the octile heuristic is exact: A* expands only cells on optimal paths.
  EXPECT_LE(astar.expanded, 10u + 20u);
  const auto dijkstra =
      shortest_path(g, s, t, {Search::dijkstra}, GridDistanceTo(g, t, GridMetric::octile), GridMoveCost{&g});
  EXPECT_DOUBLE_EQ(dijkstra.cost, astar.cost);
  EXPECT_GT(dijkstra.expanded, astar.expanded);
  const auto bfs = shortest_path(g, s, t, {Search::bfs}, GridDistanceTo(g, t, GridMetric::octile), GridMoveCost{&g});
  EXPECT_EQ(bfs.path_edges(), 9u);  // Chebyshev distance
}

TEST(GridGraph, WrappingAxisGoesTheShortWayRound) {
  // One joint at 1 degree: cells 359 and 1 are two steps apart across the seam.
  const double step = 2 * M_PI / 360;
  const GridGraph ring({{360, AxisKind::wrapping, step}}, Connectivity::axis_aligned, StepCost::sum_of_axes,
                       std::vector<std::uint8_t>(360, 1));
  EXPECT_EQ(neighbours(ring, 0), (std::set<GridCell>{1, 359}));
  const GridDistanceTo h(ring, 1, GridMetric::sum_of_axes);
  EXPECT_DOUBLE_EQ(h(359), 2 * step);
  const auto r = shortest_path(ring, 359, 1, {Search::astar}, h, GridMoveCost{&ring});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector<GridCell>{359, 0, 1}));
  EXPECT_DOUBLE_EQ(r.cost, 2 * step);
  // The same ring, bounded: the long way, 358 steps.
  const GridGraph line({{360, AxisKind::bounded, step}}, Connectivity::axis_aligned, StepCost::sum_of_axes,
                       std::vector<std::uint8_t>(360, 1));
  const auto long_way = shortest_path(line, 359, 1, {Search::astar}, GridDistanceTo(line, 1, GridMetric::sum_of_axes),
                                      GridMoveCost{&line});
  EXPECT_EQ(long_way.path_edges(), 358u);
}

TEST(GridGraph, TorusWithAFullNeighbourhoodWrapsDiagonalMovesAndTheirGuards) {
  const GridGraph torus({{5, AxisKind::wrapping, 1.0}, {4, AxisKind::wrapping, 1.0}}, Connectivity::full,
                        StepCost::sum_of_axes, std::vector<std::uint8_t>(20, 1));
  // Every cell has all 8 neighbours, the corner cell included; (4, 3) -> (0, 0) is one diagonal move.
  EXPECT_EQ(out_degree(torus.cell({0, 0}), torus), 8u);
  EXPECT_TRUE(neighbours(torus, torus.cell({4, 3})).count(torus.cell({0, 0})));
  EXPECT_DOUBLE_EQ(GridDistanceTo(torus, torus.cell({0, 0}), GridMetric::sum_of_axes)(torus.cell({4, 3})), 2.0);
}

// Independent reference: Dijkstra over a flat array, 8-connected with the MovingAI rule.
double flat_dijkstra(const std::vector<std::uint8_t>& free, int w, int h, int s, int t) {
  std::vector<double> dist(free.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[s] = 0;
  open.push({0, s});
  const auto ok = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && free[y * w + x]; };
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    if (u == t) return d;
    const int x = u % w, y = u / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((!dx && !dy) || !ok(x + dx, y + dy)) continue;
        if (dx && dy && (!ok(x + dx, y) || !ok(x, y + dy))) continue;
        const double nd = d + (dx && dy ? root2 : 1.0);
        const int v = (y + dy) * w + x + dx;
        if (nd < dist[v]) dist[v] = nd, open.push({nd, v});
      }
  }
  return -1;
}

TEST(GridGraph, RandomMapsMatchAnIndependentDijkstraForEveryAlgorithm) {
  std::mt19937 rng(7);
  const int w = 40, h = 30;
  for (int map = 0; map < 5; ++map) {
    std::vector<std::uint8_t> free(w * h);
    for (auto& f : free) f = std::bernoulli_distribution(0.7)(rng);
    const GridGraph g(plane_axes(w, h), Connectivity::full, StepCost::euclidean, free);
    SearchWorkspace<GridCell> dense;                          // automatic: a flat table (1200 cells)
    SearchWorkspace<GridCell> hashed(VertexStorage::hashed);  // the same results from a hash map
    for (int q = 0; q < 40; ++q) {
      int s, t;
      do s = std::uniform_int_distribution(0, w * h - 1)(rng);
      while (!free[s]);
      do t = std::uniform_int_distribution(0, w * h - 1)(rng);
      while (!free[t]);
      const double expected = flat_dijkstra(free, w, h, s, t);
      const GridDistanceTo octile(g, t, GridMetric::octile);
      const auto astar = shortest_path(g, GridCell(s), GridCell(t), {Search::astar}, octile, GridMoveCost{&g}, dense);
      const auto again = shortest_path(g, GridCell(s), GridCell(t), {Search::astar}, octile, GridMoveCost{&g}, hashed);
      const auto dijkstra =
          shortest_path(g, GridCell(s), GridCell(t), {Search::dijkstra}, octile, GridMoveCost{&g}, dense);
      const auto wastar =
          shortest_path(g, GridCell(s), GridCell(t), {Search::wastar, 2.0}, octile, GridMoveCost{&g}, dense);
      const auto greedy = shortest_path(g, GridCell(s), GridCell(t), {Search::greedy}, octile, GridMoveCost{&g}, dense);
      const auto bfs = shortest_path(g, GridCell(s), GridCell(t), {Search::bfs}, octile, GridMoveCost{&g}, dense);
      ASSERT_EQ(astar.found, expected >= 0);
      for (const auto* r : {&again, &dijkstra, &wastar, &greedy, &bfs}) EXPECT_EQ(r->found, astar.found);
      if (!astar.found) continue;
      EXPECT_NEAR(astar.cost, expected, 1e-9);
      EXPECT_NEAR(dijkstra.cost, expected, 1e-9);
      EXPECT_EQ(again.path, astar.path);
      EXPECT_EQ(again.expanded, astar.expanded);
      EXPECT_LE(wastar.cost, 2 * expected + 1e-9);
      EXPECT_GE(greedy.cost, expected - 1e-9);
      // Every step of every path is a move of the graph, and the reported cost is the steps' sum
      // (for weighted A* too, whose re-opened cells make the goal's g differ from a stale chain).
      for (const auto* r : {&astar, &dijkstra, &wastar, &greedy, &bfs}) {
        double sum = 0;
        for (std::size_t i = 0; i + 1 < r->path.size(); ++i) {
          EXPECT_TRUE(neighbours(g, r->path[i]).count(r->path[i + 1]));
          const auto a = g.coordinates(r->path[i]), b = g.coordinates(r->path[i + 1]);
          sum += a[0] != b[0] && a[1] != b[1] ? root2 : 1.0;
        }
        EXPECT_NEAR(r->cost, sum, 1e-9);
      }
    }
  }
}

TEST(GridGraph, LazyCellsAreEvaluatedOnceAndOnlyWhereTheSearchGoes) {
  std::map<std::vector<GridCoordinate>, int> calls;
  // 100 x 100 with a wall x = 50 for y < 90.
  GridGraph g(plane_axes(100, 100), Connectivity::full, StepCost::euclidean, [&](std::span<const GridCoordinate> at) {
    ++calls[{at.begin(), at.end()}];
    return !(at[0] == 50 && at[1] < 90);
  });
  const GridCell s = g.cell({40, 10}), t = g.cell({60, 10});
  const auto r = shortest_path(g, s, t, {Search::astar}, GridDistanceTo(g, t, GridMetric::octile), GridMoveCost{&g});
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.cost,
              flat_dijkstra(
                  [] {
                    std::vector<std::uint8_t> f(10000, 1);
                    for (int y = 0; y < 90; ++y) f[y * 100 + 50] = 0;
                    return f;
                  }(),
                  100, 100, 10 * 100 + 40, 10 * 100 + 60),
              1e-9);
  for (const auto& [cell, n] : calls) EXPECT_EQ(n, 1) << "cell evaluated twice";
  EXPECT_EQ(g.cells_evaluated(), calls.size());
  EXPECT_LT(g.cells_evaluated(), 10000u);  // not the whole grid
  EXPECT_EQ(g.state(g.cell({0, 99})), GridGraph::CellState::unknown);
  g.evaluate_all();
  EXPECT_EQ(g.cells_evaluated(), 10000u);
  EXPECT_EQ(g.state(g.cell({50, 0})), GridGraph::CellState::blocked);
}

TEST(GridGraph, SevenJointsAtFiveDegreesPlanWithMemoryForTouchedCellsOnly) {
  // 72^7 = 1.0e13 cells on a 7-torus; a slab theta_1 = 36 is blocked except where theta_2 = 8.
  const double step = 2 * M_PI / 72;
  std::vector<GridAxis> axes(7, GridAxis{72, AxisKind::wrapping, step});
  GridGraph g(axes, Connectivity::axis_aligned, StepCost::sum_of_axes,
              [](std::span<const GridCoordinate> at) { return !(at[0] == 36 && at[1] != 8); });
  EXPECT_EQ(g.cell_count(), 10030613004288ull);
  const GridCell s = g.cell({30, 10, 0, 0, 0, 0, 0}), t = g.cell({40, 10, 5, 5, 5, 5, 5});
  SearchWorkspace<GridCell> workspace;  // automatic: far too many cells for a flat table, so hashed
  const auto r = shortest_path(g, s, t, {Search::astar}, GridDistanceTo(g, t, GridMetric::sum_of_axes),
                               GridMoveCost{&g}, workspace);
  ASSERT_TRUE(r.found);
  // theta_1 must cross 36 where theta_2 = 8: 10 steps of theta_1, 2 + 2 of theta_2 (down to 8 and
  // back), 5 each for the other five joints: 39 steps.
  EXPECT_NEAR(r.cost, 39 * step, 1e-12);
  // About 6.4e5 cells touched (A* explores the detour's neighbourhood in 7D) of 1.0e13.
  EXPECT_LT(workspace.touched(), 2000000u);
  EXPECT_LT(g.cells_evaluated(), 2000000u);
}

TEST(GridGraph, MoveTestRejectsMovesBetweenFreeCells) {
  // A fence between x = 4 and x = 5 except at y = 9, visible only to the move test.
  GridGraph g(plane_axes(10, 10), Connectivity::axis_aligned, StepCost::euclidean, std::vector<std::uint8_t>(100, 1));
  g.set_move_test([&](GridCell a, GridCell b) {
    const auto pa = g.coordinates(a), pb = g.coordinates(b);
    const bool crosses = std::min(pa[0], pb[0]) == 4 && std::max(pa[0], pb[0]) == 5;
    return !crosses || pa[1] == 9;
  });
  const GridCell s = g.cell({0, 0}), t = g.cell({9, 0});
  const auto r =
      shortest_path(g, s, t, {Search::astar}, GridDistanceTo(g, t, GridMetric::sum_of_axes), GridMoveCost{&g});
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.cost, 9 + 2 * 9);
  EXPECT_GT(g.moves_checked(), 0u);
}

TEST(GridGraph, RejectsMalformedGrids) {
  const auto lazy = [](std::span<const GridCoordinate>) { return true; };
  EXPECT_THROW(GridGraph({}, Connectivity::full, StepCost::euclidean, lazy), std::invalid_argument);
  EXPECT_THROW(GridGraph({{2, AxisKind::wrapping}}, Connectivity::full, StepCost::euclidean, lazy),
               std::invalid_argument);
  EXPECT_THROW(GridGraph({{0, AxisKind::bounded}}, Connectivity::full, StepCost::euclidean, lazy),
               std::invalid_argument);
  EXPECT_THROW(GridGraph({{5, AxisKind::bounded, 0.0}}, Connectivity::full, StepCost::euclidean, lazy),
               std::invalid_argument);
  EXPECT_THROW(GridGraph(plane_axes(3, 3), Connectivity::full, StepCost::euclidean, std::vector<std::uint8_t>(8, 1)),
               std::invalid_argument);
  EXPECT_THROW(GridGraph(std::vector<GridAxis>(13, GridAxis{3}), Connectivity::axis_aligned, StepCost::euclidean, lazy),
               std::invalid_argument);
  EXPECT_THROW(
      GridGraph(std::vector<GridAxis>(12, GridAxis{1u << 20}), Connectivity::axis_aligned, StepCost::euclidean, lazy),
      std::invalid_argument);  // 2^240 cells
  const GridGraph g(plane_axes(3, 3), Connectivity::full, StepCost::euclidean, std::vector<std::uint8_t>(9, 1));
  EXPECT_THROW(g.cell({3, 0}), std::out_of_range);
  EXPECT_THROW(g.cell({0}), std::out_of_range);
  const GridGraph cube(std::vector<GridAxis>(3, GridAxis{3}), Connectivity::full, StepCost::euclidean, lazy);
  EXPECT_EQ(cube.direction_count(), 26u);
  EXPECT_THROW(GridDistanceTo(cube, 0, GridMetric::octile), std::invalid_argument);
  const GridGraph oblong({{3, AxisKind::bounded, 1.0}, {3, AxisKind::bounded, 0.1}}, Connectivity::full,
                         StepCost::euclidean, lazy);
  EXPECT_THROW(GridDistanceTo(oblong, 0, GridMetric::octile), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
