// LPA* and D* Lite against an independent Dijkstra (written here, on the same exact costs) after
// every change of thousands of random ones; the cases other implementations got wrong.
#include <polyplan/search/changing_grid.hpp>
#include <polyplan/search/incremental_search.hpp>
#include <polyplan/search/octile_length.hpp>
#include <polyplan/search/roadmap_costs.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <ostream>
#include <queue>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace polyplan {

// gtest prints OctileLength as its exact value.
inline void PrintTo(const OctileLength& l, std::ostream* out) { *out << l.to_string(); }

namespace {

using Lpa = LpaStar<GridGraph, ChangingGridCosts, ChangingGridDistance>;
using DLite = DStarLite<GridGraph, ChangingGridCosts, ChangingGridDistance>;

// The reference: textbook Dijkstra from `from` on the grid's current costs.
OctileLength dijkstra(const ChangingGrid& grid, GridCell from, GridCell to) {
  std::vector<OctileLength> distance(grid.graph().cell_count(), OctileLength::infinity());
  using Item = std::pair<OctileLength, GridCell>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  distance[from] = {};
  open.push({{}, from});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d != distance[u]) continue;
    if (u == to) return d;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = grid.x(u) + dx, y = grid.y(u) + dy;
        if ((dx == 0 && dy == 0) || !grid.contains(x, y)) continue;
        const GridCell v = grid.cell(x, y);
        const OctileLength through = d + grid.cost(u, v);
        if (through < distance[v]) {
          distance[v] = through;
          open.push({through, v});
        }
      }
  }
  return OctileLength::infinity();
}

OctileLength path_cost(const ChangingGrid& grid, const std::vector<GridCell>& path) {
  OctileLength sum;
  for (std::size_t i = 1; i < path.size(); ++i) sum = sum + grid.cost(path[i - 1], path[i]);
  return sum;
}

template <class Search>
void expect_optimal(const ChangingGrid& grid, const Search& search, const std::string& when) {
  const OctileLength expected = dijkstra(grid, search.start(), search.goal());
  ASSERT_EQ(search.cost(), expected) << when << ": " << search.cost().to_string() << " against "
                                     << expected.to_string();
  const auto path = search.path();
  if (expected == OctileLength::infinity()) {
    EXPECT_TRUE(path.empty()) << when;
    return;
  }
  ASSERT_FALSE(path.empty()) << when;
  EXPECT_EQ(path.front(), search.start()) << when;
  EXPECT_EQ(path.back(), search.goal()) << when;
  EXPECT_EQ(path_cost(grid, path), expected) << when;
}

// Blocks or frees a cell and tells the search of every move it changed.
template <class Search>
void toggle(ChangingGrid& grid, Search& search, GridCell c, bool blocked) {
  std::vector<ChangedMove> changed;
  grid.set_blocked(c, blocked, changed);
  for (const ChangedMove& m : changed) search.edge_changed(m.from, m.to, m.old_cost);
}

void block_randomly(ChangingGrid& grid, double fraction, std::mt19937& random, std::set<GridCell> keep) {
  std::bernoulli_distribution blocked(fraction);
  std::vector<ChangedMove> ignored;
  for (GridCell c = 0; c < grid.graph().cell_count(); ++c)
    if (!keep.count(c) && blocked(random)) grid.set_blocked(c, true, ignored);
}

TEST(OctileLength, ComparesExactlyWhereDoublesAreClose) {
  // 70√2 = 98.9949..., 99 - 70√2 ≈ 0.005; 5741√2 - 8119 ≈ 6e-5 (a convergent of √2).
  EXPECT_LT(OctileLength(0, 70), OctileLength(99, 0));
  EXPECT_GT(OctileLength(0, 5741), OctileLength(8119, 0));
  EXPECT_LT(OctileLength(8119, -5741), OctileLength(0, 0));  // 8119² = 2·5741² - 1
  EXPECT_GT(OctileLength(8119, -5741), OctileLength(-1, 0));
  EXPECT_GT(OctileLength(-8119, 5741), OctileLength(0, 0));
  EXPECT_EQ(OctileLength(3, 2) + OctileLength(1, 1), OctileLength(4, 3));
  EXPECT_EQ(OctileLength(3, 2) + OctileLength::infinity(), OctileLength::infinity());
  EXPECT_LT(OctileLength(1'000'000'000, 1'000'000'000), OctileLength::infinity());
  EXPECT_EQ(OctileLength::octile(-5, 2), OctileLength(3, 2));
  EXPECT_EQ(OctileLength(3, 2).to_string(), "3 + 2√2");
  EXPECT_EQ(OctileLength(0, 1).to_string(), "√2");
  EXPECT_EQ(OctileLength::infinity().to_string(), "∞");
  EXPECT_DOUBLE_EQ(OctileLength(3, 2).to_double(), 3 + 2 * std::sqrt(2.0));
}

TEST(ChangingGrid, ABlockedCellChangesTheMovesThroughItAndAcrossItsCorners) {
  ChangingGrid grid(5, 5);
  std::vector<ChangedMove> changed;
  EXPECT_TRUE(grid.set_blocked(grid.cell(2, 2), true, changed));
  EXPECT_EQ(changed.size(), 24u);  // 8 in, 8 out, 8 diagonals brushing it
  EXPECT_EQ(grid.cost(grid.cell(1, 2), grid.cell(2, 1)), OctileLength::infinity());  // cuts the corner
  EXPECT_EQ(grid.cost(grid.cell(1, 1), grid.cell(2, 1)), OctileLength(1, 0));
  EXPECT_FALSE(grid.set_blocked(grid.cell(2, 2), true, changed));
  // A second blocked cell beside it changes fewer moves: some are blocked already.
  changed.clear();
  grid.set_blocked(grid.cell(3, 2), true, changed);
  EXPECT_LT(changed.size(), 24u);
  for (const ChangedMove& m : changed) EXPECT_NE(grid.cost(m.from, m.to), m.old_cost);
}

TEST(IncrementalSearch, StartEqualsGoal) {
  ChangingGrid grid(4, 3);
  const GridCell s = grid.cell(1, 1);
  Lpa lpa(grid.graph(), {&grid}, {&grid}, s, s);
  DLite dlite(grid.graph(), {&grid}, {&grid}, s, s);
  EXPECT_TRUE(lpa.compute_shortest_path());
  EXPECT_TRUE(dlite.compute_shortest_path());
  EXPECT_EQ(lpa.cost(), OctileLength());
  EXPECT_EQ(dlite.path(), std::vector<GridCell>{s});
  EXPECT_EQ(lpa.counts().expanded, 1u);
}

TEST(IncrementalSearch, AGoalWalledOffIsReportedAtOnceAndFoundAgainWhenFreed) {
  ChangingGrid grid(7, 5);
  const GridCell start = grid.cell(0, 2), goal = grid.cell(6, 2);
  DLite search(grid.graph(), {&grid}, {&grid}, start, goal);
  ASSERT_TRUE(search.compute_shortest_path());
  for (int y = 0; y < 5; ++y) toggle(grid, search, grid.cell(3, y), true);
  EXPECT_FALSE(search.compute_shortest_path());
  EXPECT_EQ(search.cost(), OctileLength::infinity());
  EXPECT_TRUE(search.path().empty());
  // A second search on the unchanged graph does nothing: no oscillation, no work.
  const std::size_t expanded = search.counts().expanded;
  EXPECT_FALSE(search.compute_shortest_path());
  EXPECT_EQ(search.counts().expanded, expanded);
  toggle(grid, search, grid.cell(3, 4), false);
  ASSERT_TRUE(search.compute_shortest_path());
  expect_optimal(grid, search, "after the wall opened");
}

TEST(IncrementalSearch, ADiagonalWallOfSingleCellsIsNotCrossedAtItsCorners) {
  // Cells (k, k) blocked: an 8-connected path could slip between (k, k) and (k+1, k+1) only by
  // cutting both corners, which the grid forbids.
  ChangingGrid grid(6, 6);
  Lpa search(grid.graph(), {&grid}, {&grid}, grid.cell(0, 5), grid.cell(5, 0));
  ASSERT_TRUE(search.compute_shortest_path());
  for (int k = 0; k < 6; ++k) toggle(grid, search, grid.cell(k, k), true);
  EXPECT_FALSE(search.compute_shortest_path());
  toggle(grid, search, grid.cell(5, 5), false);  // a gap at the corner: round it
  ASSERT_TRUE(search.compute_shortest_path());
  expect_optimal(grid, search, "through the gap");
}

TEST(IncrementalSearch, TiesGiveTheOptimumWhateverTheOrder) {
  // An open grid where a great many paths tie, and its mirror image (the vertex ids in another
  // order): the same exact cost, each path optimal.
  for (const bool mirrored : {false, true}) {
    ChangingGrid grid(9, 9);
    const auto at = [&](int x, int y) { return mirrored ? grid.cell(8 - x, y) : grid.cell(x, y); };
    DLite search(grid.graph(), {&grid}, {&grid}, at(0, 0), at(8, 3));
    ASSERT_TRUE(search.compute_shortest_path());
    EXPECT_EQ(search.cost(), OctileLength(5, 3));
    toggle(grid, search, at(4, 1), true);
    toggle(grid, search, at(4, 2), true);
    ASSERT_TRUE(search.compute_shortest_path());
    expect_optimal(grid, search, mirrored ? "mirrored" : "as is");
  }
}

// The search the cost functor may set: update_edge on moves given one by one.
struct SettableCosts {
  std::map<std::pair<GridCell, GridCell>, OctileLength>* set_costs;
  OctileLength operator()(GridCell a, GridCell b) const {
    const auto it = set_costs->find({a, b});
    return it == set_costs->end() ? OctileLength(1, 0) : it->second;
  }
  void set(GridCell a, GridCell b, OctileLength c) { (*set_costs)[{a, b}] = c; }
};

TEST(IncrementalSearch, UpdateEdgeTakesCostsToInfinityAndBack) {
  // A 4-connected 5 x 1 corridor where every move costs 1 until told otherwise.
  GridGraph corridor({{5, AxisKind::bounded, 1.0}, {1, AxisKind::bounded, 1.0}}, Connectivity::axis_aligned,
                     StepCost::euclidean, std::vector<std::uint8_t>(5, 1));
  std::map<std::pair<GridCell, GridCell>, OctileLength> costs;
  const auto h = [](GridCell a, GridCell b) { return OctileLength(a > b ? a - b : b - a, 0); };
  LpaStar<GridGraph, SettableCosts, decltype(h)> search(corridor, SettableCosts{&costs}, h, 0, 4);
  ASSERT_TRUE(search.compute_shortest_path());
  EXPECT_EQ(search.cost(), OctileLength(4, 0));
  search.update_edge(2, 3, OctileLength(0, 3));
  ASSERT_TRUE(search.compute_shortest_path());
  EXPECT_EQ(search.cost(), OctileLength(3, 3));
  search.update_edge(2, 3, OctileLength::infinity());
  EXPECT_FALSE(search.compute_shortest_path());
  search.update_edge(2, 3, OctileLength(1, 0));
  ASSERT_TRUE(search.compute_shortest_path());
  EXPECT_EQ(search.cost(), OctileLength(4, 0));
  EXPECT_EQ(search.path(), (std::vector<GridCell>{0, 1, 2, 3, 4}));
}

// Thousands of random changes, a few at a time: after each batch both searches report the
// optimum, exactly. D* Lite's start moves along its path meanwhile (k_m), LPA*'s goal jumps.
TEST(IncrementalSearch, EqualsAFreshDijkstraAfterThousandsOfRandomChanges) {
  std::mt19937 random(2026);
  std::size_t changes = 0, checks = 0;
  for (int map = 0; map < 6; ++map) {
    ChangingGrid grid(24, 16);
    GridCell start = grid.cell(1, 1), goal = grid.cell(22, 14);
    block_randomly(grid, 0.25, random, {start, goal});
    DLite dlite(grid.graph(), {&grid}, {&grid}, start, goal);
    Lpa lpa(grid.graph(), {&grid}, {&grid}, start, goal);
    std::uniform_int_distribution<GridCell> any(0, grid.graph().cell_count() - 1);
    std::uniform_int_distribution<int> batch(1, 12);
    for (int round = 0; round < 60; ++round) {
      for (int k = batch(random); k > 0; --k) {
        const GridCell c = any(random);
        if (c == dlite.start() || c == goal || c == lpa.goal()) continue;
        std::vector<ChangedMove> changed;
        grid.set_blocked(c, !grid.blocked(c), changed);
        for (const ChangedMove& m : changed) {
          dlite.edge_changed(m.from, m.to, m.old_cost);
          lpa.edge_changed(m.from, m.to, m.old_cost);
        }
        ++changes;
      }
      dlite.compute_shortest_path();
      lpa.compute_shortest_path();
      expect_optimal(grid, dlite, "D* Lite, map " + std::to_string(map) + " round " + std::to_string(round));
      expect_optimal(grid, lpa, "LPA*, map " + std::to_string(map) + " round " + std::to_string(round));
      checks += 2;
      if (const auto path = dlite.path(); path.size() > 2) dlite.move_start(path[1]);
      if (round % 7 == 3) {
        GridCell other = any(random);
        if (!grid.blocked(other)) {
          lpa.move_goal(other);
          lpa.compute_shortest_path();
          expect_optimal(grid, lpa, "LPA* after its goal moved");
        }
      }
    }
  }
  EXPECT_GT(changes, 2000u);
  EXPECT_EQ(checks, 6u * 60u * 2u);
}

TEST(IncrementalSearch, RestartIsAFreshSearchThatExpandsWhatAStarExpands) {
  std::mt19937 random(7);
  ChangingGrid grid(30, 30);
  const GridCell start = grid.cell(0, 0), goal = grid.cell(29, 29);
  block_randomly(grid, 0.2, random, {start, goal});
  DLite search(grid.graph(), {&grid}, {&grid}, start, goal);
  search.compute_shortest_path();
  const std::size_t first = search.counts().expanded;
  search.restart();
  search.compute_shortest_path();
  EXPECT_EQ(search.counts().expanded, 2 * first);  // the same search again, from nothing
  expect_optimal(grid, search, "after restart");
  // A* with a consistent heuristic expands each vertex at most once: no more than those generated.
  EXPECT_LE(first, search.counts().generated);
}

// The observer sees each pass: the popped vertex, the kind of pass, and an open list in which
// every entry is inconsistent, labelled as the seed labels it.
struct Recorder : IncrementalObserver<DLite> {
  std::size_t steps = 0, over = 0, under = 0, mislabelled = 0;
  void step(const DLite& search, const IncrementalStep<GridCell, OctileLength>& s) override {
    ++steps;
    over += s.kind == IncrementalStep<GridCell, OctileLength>::Kind::overconsistent;
    under += s.kind == IncrementalStep<GridCell, OctileLength>::Kind::underconsistent;
    for (const auto& e : search.open_list()) {
      const Consistency expected = e.g > e.rhs ? Consistency::overconsistent : Consistency::underconsistent;
      // A queued key is a lower bound of the current one (k_m grew since it was computed).
      mislabelled += e.state != expected || e.g == e.rhs || e.key > search.key(e.vertex);
    }
  }
};

TEST(IncrementalSearch, TheObserverSeesOverAndUnderconsistentPasses) {
  ChangingGrid grid(8, 8);
  DLite search(grid.graph(), {&grid}, {&grid}, grid.cell(0, 0), grid.cell(7, 7));
  Recorder recorder;
  search.set_observer(&recorder);
  ASSERT_TRUE(search.compute_shortest_path());
  EXPECT_EQ(recorder.steps, search.counts().expanded);  // no stale keys yet
  EXPECT_EQ(recorder.under, 0u);
  search.move_start(search.path()[1]);
  for (int k = 2; k < 7; ++k) toggle(grid, search, grid.cell(k, k), true);  // on the diagonal it was taking
  ASSERT_TRUE(search.compute_shortest_path());
  EXPECT_GT(recorder.under, 0u);
  EXPECT_EQ(recorder.mislabelled, 0u);
  expect_optimal(grid, search, "after the diagonal closed");
}

// A stored Roadmap: random points joined to their nearest neighbours, edges set to infinity, to
// dearer and back, both ways at once or one way only; against Dijkstra on the same integer costs.
ScaledLength roadmap_dijkstra(const Roadmap& g, const RoadmapCosts& costs, RoadmapVertexId from, RoadmapVertexId to) {
  std::vector<ScaledLength> d(num_vertices(g), ScaledLength::infinity());
  using Item = std::pair<ScaledLength, RoadmapVertexId>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  d[from] = ScaledLength();
  open.push({d[from], from});
  while (!open.empty()) {
    const auto [du, u] = open.top();
    open.pop();
    if (du != d[u]) continue;
    for (auto [e, end] = out_edges(u, g); e != end; ++e) {
      const RoadmapVertexId v = target(*e, g);
      if (const ScaledLength through = du + costs(u, v); through < d[v]) {
        d[v] = through;
        open.push({through, v});
      }
    }
  }
  return d[to];
}

TEST(IncrementalSearch, OnAStoredRoadmapWithEdgesChangingEitherWay) {
  std::mt19937 random(11);
  std::uniform_int_distribution<long> coordinate(0, 1000);
  Roadmap g;
  for (int i = 0; i < 80; ++i) add_vertex(g, ExactPoint{Rational(coordinate(random)), Rational(coordinate(random))});
  for (RoadmapVertexId u = 0; u < 80; ++u) {
    std::vector<std::pair<double, RoadmapVertexId>> near;
    for (RoadmapVertexId v = 0; v < 80; ++v)
      if (v != u) near.push_back({std::hypot(g[u].x - g[v].x, g[u].y - g[v].y), v});
    std::sort(near.begin(), near.end());
    for (int k = 0; k < 4; ++k)
      if (!boost::edge(u, near[k].second, g).second) add_edge(g, u, near[k].second);
  }
  using Lpa = LpaStar<Roadmap, RoadmapCosts, RoadmapDistance>;
  using DLite = DStarLite<Roadmap, RoadmapCosts, RoadmapDistance>;
  Lpa lpa(g, RoadmapCosts(g), RoadmapDistance{&g}, 0, 79);
  DLite dlite(g, RoadmapCosts(g), RoadmapDistance{&g}, 0, 79);
  std::vector<std::pair<RoadmapVertexId, RoadmapVertexId>> edges;
  for (auto [e, end] = boost::edges(g); e != end; ++e) edges.push_back({source(*e, g), target(*e, g)});
  std::uniform_int_distribution<std::size_t> any(0, edges.size() - 1);
  std::uniform_int_distribution<int> change(0, 3);
  for (int round = 0; round < 400; ++round) {
    const auto [u, v] = edges[any(random)];
    const ScaledLength length = ScaledLength::at_least(std::hypot(g[u].x - g[v].x, g[u].y - g[v].y));
    const int c = change(random);
    const ScaledLength cost = c == 0 ? ScaledLength::infinity() : c == 1 ? ScaledLength(3 * length.units()) : length;
    lpa.update_edge(u, v, cost);
    dlite.update_edge(u, v, cost);
    if (c != 3) {  // the other way too, but for one change in four
      lpa.update_edge(v, u, cost);
      dlite.update_edge(v, u, cost);
    }
    lpa.compute_shortest_path();
    dlite.compute_shortest_path();
    ASSERT_EQ(lpa.cost(), roadmap_dijkstra(g, lpa.costs(), 0, 79)) << "round " << round;
    ASSERT_EQ(dlite.cost(), roadmap_dijkstra(g, dlite.costs(), 0, 79)) << "round " << round;
    if (const auto path = lpa.path(); !path.empty()) {
      ScaledLength sum;
      for (std::size_t i = 1; i < path.size(); ++i) sum = sum + lpa.costs()(path[i - 1], path[i]);
      ASSERT_EQ(sum, lpa.cost());
    }
  }
}

}  // namespace
}  // namespace polyplan
