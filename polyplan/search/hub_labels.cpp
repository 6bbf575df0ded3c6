#include <polyplan/search/hub_labels.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

namespace polyplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The order in which vertices become hubs: highest degree first (they lie on many shortest paths),
// ties by how many shortest paths cross them, estimated from the shortest-path trees of a few
// roots spread over the graph (a vertex scores the size of its subtree in each). Mazes, where every
// corner has the same few neighbours, get 103 label entries per corner instead of degree order's
// 140 (ordering by the score alone gave 321).
std::vector<int> hub_order(const CompressedGraph& g) {
  const std::size_t n = g.vertex_count();
  std::vector<double> score(n, 0), dist(n), subtree(n);
  std::vector<int> parent(n), settled;
  std::vector<std::pair<double, int>> heap;
  const std::size_t roots = std::min<std::size_t>(n, 32);
  for (std::size_t k = 0; k < roots; ++k) {
    std::fill(dist.begin(), dist.end(), kInfinity);
    settled.clear();
    dijkstra(g, static_cast<int>(k * n / roots), dist.data(), parent.data(), heap,
             [&](int u) { settled.push_back(u); });
    std::fill(subtree.begin(), subtree.end(), 0);
    for (auto it = settled.rbegin(); it != settled.rend(); ++it) {  // leaves before their parents
      const auto v = static_cast<std::size_t>(*it);
      subtree[v] += 1;
      score[v] += subtree[v];
      if (parent[v] >= 0) subtree[static_cast<std::size_t>(parent[v])] += subtree[v];
    }
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return g.degree(a) != g.degree(b) ? g.degree(a) > g.degree(b)
                                      : score[static_cast<std::size_t>(a)] > score[static_cast<std::size_t>(b)];
  });
  return order;
}

}  // namespace

std::optional<HubLabels> HubLabels::build(const CompressedGraph& graph, std::size_t max_bytes) {
  const std::size_t n = graph.vertex_count();
  HubLabels labels;
  labels.order_ = hub_order(graph);
  const std::size_t max_entries = max_bytes / sizeof(Entry);
  std::vector<std::vector<Entry>> building(n);
  std::size_t entries = 0;
  std::vector<double> hub_distance(n, kInfinity);  // by hub rank: the current root's label
  std::vector<double> dist(n, kInfinity);
  std::vector<int> parent(n, -1), touched;
  std::vector<std::pair<double, int>> heap;
  for (std::size_t rank = 0; rank < n; ++rank) {
    const int root = labels.order_[rank];
    for (const Entry& e : building[static_cast<std::size_t>(root)])
      hub_distance[static_cast<std::size_t>(e.hub)] = e.distance;
    dist[static_cast<std::size_t>(root)] = 0;
    parent[static_cast<std::size_t>(root)] = -1;
    touched.assign(1, root);
    heap.assign(1, {0.0, root});
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [d, u] = heap.back();
      heap.pop_back();
      const auto node = static_cast<std::size_t>(u);
      if (d > dist[node]) continue;
      // Pruned: the hubs ranked before the root already give this distance.
      bool covered = false;
      for (const Entry& e : building[node])
        if (hub_distance[static_cast<std::size_t>(e.hub)] + e.distance <= d) {
          covered = true;
          break;
        }
      if (covered) continue;
      building[node].push_back({static_cast<int>(rank), parent[node], d});
      if (++entries > max_entries) return std::nullopt;
      for (std::size_t e = graph.row_begin(u); e < graph.row_end(u); ++e) {
        const auto v = static_cast<std::size_t>(graph.adjacent[e]);
        const double dv = d + graph.weight[e];
        if (dv < dist[v]) {
          if (dist[v] == kInfinity) touched.push_back(static_cast<int>(v));
          dist[v] = dv;
          parent[v] = u;
          heap.emplace_back(dv, static_cast<int>(v));
          std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
      }
    }
    for (int v : touched) dist[static_cast<std::size_t>(v)] = kInfinity;
    for (const Entry& e : building[static_cast<std::size_t>(root)])
      hub_distance[static_cast<std::size_t>(e.hub)] = kInfinity;
  }
  labels.label_begin_.assign(1, 0);
  labels.entries_.reserve(entries);
  for (auto& label : building) {
    labels.entries_.insert(labels.entries_.end(), label.begin(), label.end());
    labels.label_begin_.push_back(labels.entries_.size());
    std::vector<Entry>().swap(label);
  }
  return labels;
}

double HubLabels::distance(int s, int t) const {
  double best = kInfinity;
  const Entry *a = label_begin(s), *a_end = label_end(s), *b = label_begin(t), *b_end = label_end(t);
  while (a != a_end && b != b_end) {  // both sorted by hub rank
    if (a->hub < b->hub) ++a;
    else if (b->hub < a->hub) ++b;
    else {
      best = std::min(best, a->distance + b->distance);
      ++a;
      ++b;
    }
  }
  return best;
}

void HubLabels::path_to_hub(int v, int hub, std::vector<int>& out) const {
  for (;;) {
    out.push_back(v);
    const Entry* end = label_end(v);
    const Entry* e =
        std::lower_bound(label_begin(v), end, hub, [](const Entry& entry, int h) { return entry.hub < h; });
    if (e == end || e->hub != hub || e->parent < 0) return;  // at the hub
    v = e->parent;
  }
}

std::size_t HubLabels::memory_bytes() const {
  return order_.capacity() * sizeof(int) + label_begin_.capacity() * sizeof(std::size_t) +
         entries_.capacity() * sizeof(Entry);
}

}  // namespace polyplan
