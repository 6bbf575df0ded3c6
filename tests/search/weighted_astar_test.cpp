// Weighted A* as the textbook's (SearchOptions::reopen false, the default): on seeded random
// digraphs and random grids, each against an independent Dijkstra written here, its cost is at most
// w times the optimum, no vertex is expanded twice and expanded <= generated; with reopen the bound
// still holds and closed vertices are expanded again (the option does something).
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/grid_graph.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

constexpr double weights_tried[] = {1.0, 1.5, 2.0, 5.0, 20.0};

// Dijkstra over an adjacency list of (neighbour, cost): the optimum from s to t (inf when none).
double independent_dijkstra(const std::vector<std::vector<std::pair<int, double>>>& out, int s, int t) {
  std::vector<double> dist(out.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[s] = 0;
  open.push({0.0, s});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    if (u == t) return d;
    for (const auto& [v, c] : out[u])
      if (d + c < dist[v]) open.push({dist[v] = d + c, v});
  }
  return std::numeric_limits<double>::infinity();
}

// What every weighted A* result must satisfy against the optimum.
template <class Vertex>
void expect_textbook_result(const SearchResult<Vertex>& r, double optimal, double weight, bool reopen) {
  ASSERT_EQ(r.found, optimal < std::numeric_limits<double>::infinity());
  if (r.found) {
    EXPECT_GE(r.cost, optimal * (1 - 1e-9));
    EXPECT_LE(r.cost, weight * optimal * (1 + 1e-9));
  }
  if (reopen) return;
  EXPECT_LE(r.expanded, r.generated);
  EXPECT_EQ(r.expanded_order.size(), r.expanded);
  EXPECT_EQ(std::set<Vertex>(r.expanded_order.begin(), r.expanded_order.end()).size(), r.expanded)
      << "a vertex was expanded twice";
}

// Weighted A* with every weight tried, without and with reopening, on one query whose optimum is
// `optimal`: `search(options)` answers it. Returns how many searches with reopen expanded a vertex
// twice.
template <class SearchFn>
std::size_t expect_textbook_for_every_weight(double optimal, const SearchFn& search) {
  std::size_t reexpanding = 0;
  for (double weight : weights_tried)
    for (bool reopen : {false, true}) {
      SCOPED_TRACE(testing::Message() << "w " << weight << (reopen ? " reopen" : ""));
      SearchOptions options{Search::wastar, weight};
      options.reopen = reopen;
      options.record_expanded = true;
      const auto r = search(options);
      expect_textbook_result(r, optimal, weight, reopen);
      using Vertex = typename decltype(r.expanded_order)::value_type;
      reexpanding += std::set<Vertex>(r.expanded_order.begin(), r.expanded_order.end()).size() != r.expanded;
    }
  return reexpanding;
}

// Points in a 100 x 100 square, each vertex with out-edges to random others costing their distance
// times a factor in [1, 3]: asymmetric costs, and the Euclidean heuristic stays consistent.
std::vector<std::vector<std::pair<int, double>>> random_digraph(std::mt19937& random, int n,
                                                                std::vector<std::pair<double, double>>& at) {
  std::uniform_real_distribution<double> coordinate(0, 100), factor(1, 3);
  std::uniform_int_distribution<int> vertex(0, n - 1), degree(1, 5);
  at.resize(n);
  for (auto& p : at) p = {coordinate(random), coordinate(random)};
  std::vector<std::vector<std::pair<int, double>>> out(n);
  for (int u = 0; u < n; ++u)
    for (int k = degree(random); k > 0; --k) {
      const int v = vertex(random);
      out[u].push_back({v, std::hypot(at[u].first - at[v].first, at[u].second - at[v].second) * factor(random)});
    }
  return out;
}

struct ListVertex {
  double x, y;
  std::vector<int> neighbors;
  std::vector<double> neighbors_cost;
};

TEST(WeightedAStar, RandomDigraphsStayWithinWTimesTheOptimumExpandingEachVertexOnce) {
  std::mt19937 random(48);
  std::size_t reopened_somewhere = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 20 + 10 * trial;
    std::vector<std::pair<double, double>> at;
    const auto out = random_digraph(random, n, at);
    std::vector<ListVertex> list;
    for (int u = 0; u < n; ++u) {
      list.push_back({at[u].first, at[u].second, {}, {}});
      for (const auto& [v, c] : out[u]) {
        list.back().neighbors.push_back(v);
        list.back().neighbors_cost.push_back(c);
      }
    }
    const WeightedDigraph g = make_weighted_digraph(list);
    std::uniform_int_distribution<int> vertex(0, n - 1);
    for (int q = 0; q < 10; ++q) {
      const int s = vertex(random), t = vertex(random);
      const double optimal = independent_dijkstra(out, s, t);
      SCOPED_TRACE(testing::Message() << "trial " << trial << " " << s << " -> " << t);
      reopened_somewhere += expect_textbook_for_every_weight(
          optimal, [&](const SearchOptions& options) { return shortest_path(g, s, t, options); });
    }
  }
  EXPECT_GT(reopened_somewhere, 0u) << "reopen never re-expanded a vertex: the option does nothing";
}

TEST(WeightedAStar, RandomGridsStayWithinWTimesTheOptimumExpandingEachCellOnce) {
  std::mt19937 random(4848);
  const int w = 60, h = 45;
  std::size_t reopened_somewhere = 0;
  for (int map = 0; map < 6; ++map) {
    std::vector<std::uint8_t> free(w * h);
    for (auto& f : free) f = std::bernoulli_distribution(0.72)(random);
    const GridGraph g({{w, AxisKind::bounded, 1.0}, {h, AxisKind::bounded, 1.0}}, Connectivity::full,
                      StepCost::euclidean, free);
    // The same moves as an adjacency list for the independent Dijkstra: 8-connected, no corner cut.
    std::vector<std::vector<std::pair<int, double>>> out(w * h);
    for (int c = 0; c < w * h; ++c)
      for (auto [e, end] = out_edges(GridCell(c), g); e != end; ++e)
        out[c].push_back({static_cast<int>(target(*e, g)), GridMoveCost{&g}(*e)});
    SearchWorkspace<GridCell> workspace;
    for (int q = 0; q < 15; ++q) {
      int s, t;
      do s = std::uniform_int_distribution(0, w * h - 1)(random);
      while (!free[s]);
      do t = std::uniform_int_distribution(0, w * h - 1)(random);
      while (!free[t]);
      const double optimal = independent_dijkstra(out, s, t);
      const GridDistanceTo octile(g, GridCell(t), GridMetric::octile);
      SCOPED_TRACE(testing::Message() << "map " << map << " " << s << " -> " << t);
      reopened_somewhere += expect_textbook_for_every_weight(optimal, [&](const SearchOptions& options) {
        return shortest_path(g, GridCell(s), GridCell(t), options, octile, GridMoveCost{&g}, workspace);
      });
    }
  }
  EXPECT_GT(reopened_somewhere, 0u) << "reopen never re-expanded a cell: the option does nothing";
}

}  // namespace
}  // namespace polyplan
