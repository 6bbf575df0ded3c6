#pragma once
// A weighted undirected graph as compressed rows (the neighbours of u are adjacent[begin[u] ..
// begin[u+1]) with weight[...]), and Dijkstra on it: the flat form that many-query engines
// (euclidean_shortest_paths, hub_labels) search millions of times, where Roadmap's BGL adjacency
// lists would cost a pointer chase per edge.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace polyplan {

struct CompressedGraph {
  std::vector<std::size_t> begin{0};
  std::vector<int> adjacent;
  std::vector<double> weight;

  std::size_t vertex_count() const { return begin.size() - 1; }
  std::size_t row_begin(int u) const { return begin[static_cast<std::size_t>(u)]; }
  std::size_t row_end(int u) const { return begin[static_cast<std::size_t>(u) + 1]; }
  std::size_t degree(int u) const { return row_end(u) - row_begin(u); }

  // From undirected edges (u, v, w), each given once.
  template <class Edges>
  static CompressedGraph from_edges(std::size_t vertices, const Edges& edges) {
    CompressedGraph g;
    g.begin.assign(vertices + 1, 0);
    for (const auto& [u, v, w] : edges) {
      ++g.begin[static_cast<std::size_t>(u) + 1];
      ++g.begin[static_cast<std::size_t>(v) + 1];
    }
    for (std::size_t u = 0; u < vertices; ++u) g.begin[u + 1] += g.begin[u];
    g.adjacent.resize(g.begin.back());
    g.weight.resize(g.begin.back());
    std::vector<std::size_t> fill(g.begin.begin(), g.begin.end() - 1);
    for (const auto& [u, v, w] : edges) {
      g.adjacent[fill[static_cast<std::size_t>(u)]] = v;
      g.weight[fill[static_cast<std::size_t>(u)]++] = w;
      g.adjacent[fill[static_cast<std::size_t>(v)]] = u;
      g.weight[fill[static_cast<std::size_t>(v)]++] = w;
    }
    return g;
  }
};

// Dijkstra from `source`: dist[v] (infinity where unreached; the caller fills it so first) and
// parent[v] (the vertex before v, -1 at the source); each settled vertex is passed to `settle` in
// order. `heap` is the caller's, to be reused.
template <class Settle = void (*)(int)>
void dijkstra(
    const CompressedGraph& g, int source, double* dist, int* parent, std::vector<std::pair<double, int>>& heap,
    Settle settle = [](int) {}) {
  dist[source] = 0;
  parent[source] = -1;
  heap.assign(1, {0.0, source});
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    const auto [d, u] = heap.back();
    heap.pop_back();
    if (d > dist[u]) continue;
    settle(u);
    for (std::size_t e = g.row_begin(u); e < g.row_end(u); ++e) {
      const int v = g.adjacent[e];
      if (d + g.weight[e] < dist[v]) {
        dist[v] = d + g.weight[e];
        parent[v] = u;
        heap.emplace_back(dist[v], v);
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
      }
    }
  }
}

}  // namespace polyplan
