// Hub labels against Dijkstra on random weighted graphs: every distance, and every path to a hub
// is a chain of edges whose weights add up to the label's distance.
#include <polyplan/search/hub_labels.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <random>

namespace polyplan {
namespace {

using Graph = CompressedGraph;

// n vertices, a random spanning path plus `extra` random edges, weights in [1, 10) (some equal,
// for ties), plus `isolated` vertices at the end with no edge.
Graph random_graph(std::mt19937& random, int n, int extra, int isolated) {
  std::vector<std::vector<std::pair<int, double>>> lists(static_cast<std::size_t>(n + isolated));
  std::uniform_int_distribution<int> vertex(0, n - 1), whole(1, 9);
  auto add = [&](int u, int v, double w) {
    lists[static_cast<std::size_t>(u)].push_back({v, w});
    lists[static_cast<std::size_t>(v)].push_back({u, w});
  };
  for (int v = 1; v < n; ++v) add(v - 1, v, whole(random));
  for (int e = 0; e < extra; ++e) {
    const int u = vertex(random), v = vertex(random);
    if (u != v) add(u, v, whole(random) + (e % 3 == 0 ? 0.5 : 0.0));
  }
  Graph g;
  for (const auto& list : lists) {
    for (auto [v, w] : list) {
      g.adjacent.push_back(v);
      g.weight.push_back(w);
    }
    g.begin.push_back(g.adjacent.size());
  }
  return g;
}

// The reference, written here apart from the library's (hub labels order their hubs with that one).
std::vector<double> dijkstra(const Graph& g, int source) {
  std::vector<double> dist(g.vertex_count(), std::numeric_limits<double>::infinity());
  std::vector<std::pair<double, int>> heap{{0.0, source}};
  dist[static_cast<std::size_t>(source)] = 0;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    auto [d, u] = heap.back();
    heap.pop_back();
    if (d > dist[static_cast<std::size_t>(u)]) continue;
    for (std::size_t e = g.row_begin(u); e < g.row_end(u); ++e)
      if (d + g.weight[e] < dist[static_cast<std::size_t>(g.adjacent[e])]) {
        dist[static_cast<std::size_t>(g.adjacent[e])] = d + g.weight[e];
        heap.emplace_back(d + g.weight[e], g.adjacent[e]);
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
      }
  }
  return dist;
}

double edge_weight(const Graph& g, int u, int v) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = g.begin[static_cast<std::size_t>(u)]; e < g.begin[static_cast<std::size_t>(u) + 1]; ++e)
    if (g.adjacent[e] == v) best = std::min(best, g.weight[e]);
  return best;
}

TEST(HubLabels, DistancesAndPathsAreDijkstras) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 8; ++trial) {
    const Graph g = random_graph(random, 40 + 20 * trial, 60 + 40 * trial, 2);
    const auto labels = HubLabels::build(g, std::size_t{1} << 30);
    ASSERT_TRUE(labels);
    const int n = static_cast<int>(g.begin.size()) - 1;
    ASSERT_EQ(labels->vertex_count(), static_cast<std::size_t>(n));
    EXPECT_LT(labels->entry_count(), static_cast<std::size_t>(n) * static_cast<std::size_t>(n) / 2)
        << "labels prune nothing";
    for (int s = 0; s < n; ++s) {
      const std::vector<double> dist = dijkstra(g, s);
      for (int t = 0; t < n; ++t)
        EXPECT_DOUBLE_EQ(labels->distance(s, t), dist[static_cast<std::size_t>(t)]) << s << "-" << t;
      for (const HubLabels::Entry* e = labels->label_begin(s); e != labels->label_end(s); ++e) {
        std::vector<int> path;
        labels->path_to_hub(s, e->hub, path);
        ASSERT_EQ(path.front(), s);
        ASSERT_EQ(path.back(), labels->hub_vertex(e->hub));
        double length = 0;
        for (std::size_t i = 0; i + 1 < path.size(); ++i) length += edge_weight(g, path[i], path[i + 1]);
        EXPECT_DOUBLE_EQ(length, e->distance);
        EXPECT_DOUBLE_EQ(length, dijkstra(g, path.back())[static_cast<std::size_t>(s)]);
      }
    }
  }
}

TEST(HubLabels, ABudgetTooSmallIsRefused) {
  std::mt19937 random(9);
  const Graph g = random_graph(random, 200, 400, 0);
  EXPECT_FALSE(HubLabels::build(g, 100 * sizeof(HubLabels::Entry)));
  EXPECT_TRUE(HubLabels::build(g, std::size_t{1} << 24));
}

}  // namespace
}  // namespace polyplan
