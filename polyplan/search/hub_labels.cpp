#include <polyplan/search/hub_labels.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

namespace polyplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The order in which vertices become hubs: those on the most shortest paths first, estimated from
// the shortest-path trees of a few roots spread over the graph (a vertex scores the size of its
// subtree in each: the number of the tree's paths through it), ties by degree. Mazes, where every
// corner has the same few neighbours, get labels a fraction of the size degree order gives.
std::vector<int> hub_order(const std::vector<std::size_t>& begin, const std::vector<int>& adjacent,
                           const std::vector<double>& weight) {
  const std::size_t n = begin.size() - 1;
  std::vector<double> score(n, 0), dist(n);
  std::vector<int> parent(n), settled;
  std::vector<std::pair<double, int>> heap;
  const std::size_t roots = std::min<std::size_t>(n, 32);
  for (std::size_t k = 0; k < roots; ++k) {
    const int root = static_cast<int>(k * n / roots);
    std::fill(dist.begin(), dist.end(), kInfinity);
    settled.clear();
    dist[static_cast<std::size_t>(root)] = 0;
    parent[static_cast<std::size_t>(root)] = -1;
    heap.assign(1, {0.0, root});
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [d, u] = heap.back();
      heap.pop_back();
      if (d > dist[static_cast<std::size_t>(u)]) continue;
      settled.push_back(u);
      for (std::size_t e = begin[static_cast<std::size_t>(u)]; e < begin[static_cast<std::size_t>(u) + 1]; ++e) {
        const auto v = static_cast<std::size_t>(adjacent[e]);
        if (d + weight[e] < dist[v]) {
          dist[v] = d + weight[e];
          parent[v] = u;
          heap.emplace_back(dist[v], static_cast<int>(v));
          std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
      }
    }
    std::vector<double> subtree(n, 0);
    for (auto it = settled.rbegin(); it != settled.rend(); ++it) {  // leaves before their parents
      const auto v = static_cast<std::size_t>(*it);
      subtree[v] += 1;
      score[v] += subtree[v];
      if (parent[v] >= 0) subtree[static_cast<std::size_t>(parent[v])] += subtree[v];
    }
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto degree = [&](int v) { return begin[static_cast<std::size_t>(v) + 1] - begin[static_cast<std::size_t>(v)]; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const double sa = score[static_cast<std::size_t>(a)], sb = score[static_cast<std::size_t>(b)];
    return degree(a) != degree(b) ? degree(a) > degree(b) : sa > sb;
  });
  return order;
}

}  // namespace

std::optional<HubLabels> HubLabels::build(const std::vector<std::size_t>& begin, const std::vector<int>& adjacent,
                                          const std::vector<double>& weight, std::size_t max_bytes) {
  const std::size_t n = begin.empty() ? 0 : begin.size() - 1;
  HubLabels labels;
  labels.order_.resize(n);
  std::iota(labels.order_.begin(), labels.order_.end(), 0);
  labels.order_ = hub_order(begin, adjacent, weight);
  const std::size_t max_entries = max_bytes / sizeof(Entry);
  std::vector<std::vector<Entry>> building(n);
  std::size_t entries = 0;
  std::vector<double> hub_distance(n, kInfinity);  // by hub rank: the current root's label
  std::vector<double> dist(n, kInfinity);
  std::vector<int> parent(n, -1), touched;
  std::vector<std::pair<double, int>> heap;
  for (std::size_t rank = 0; rank < n; ++rank) {
    const int root = labels.order_[rank];
    for (const Entry& e : building[static_cast<std::size_t>(root)]) hub_distance[static_cast<std::size_t>(e.hub)] = e.distance;
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
      for (std::size_t e = begin[node]; e < begin[node + 1]; ++e) {
        const auto v = static_cast<std::size_t>(adjacent[e]);
        const double dv = d + weight[e];
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
    for (const Entry& e : building[static_cast<std::size_t>(root)]) hub_distance[static_cast<std::size_t>(e.hub)] = kInfinity;
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
    const Entry* e = std::lower_bound(label_begin(v), end, hub, [](const Entry& entry, int h) { return entry.hub < h; });
    if (e == end || e->hub != hub || e->parent < 0) return;  // at the hub
    v = e->parent;
  }
}

std::size_t HubLabels::memory_bytes() const {
  return order_.capacity() * sizeof(int) + label_begin_.capacity() * sizeof(std::size_t) + entries_.capacity() * sizeof(Entry);
}

}  // namespace polyplan
