#include <polyplan/search/hub_labels.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

namespace polyplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

std::optional<HubLabels> HubLabels::build(const std::vector<std::size_t>& begin, const std::vector<int>& adjacent,
                                          const std::vector<double>& weight, std::size_t max_bytes) {
  const std::size_t n = begin.empty() ? 0 : begin.size() - 1;
  HubLabels labels;
  labels.order_.resize(n);
  std::iota(labels.order_.begin(), labels.order_.end(), 0);
  // Vertices of high degree first: they lie on many shortest paths, so their labels prune most.
  std::stable_sort(labels.order_.begin(), labels.order_.end(), [&](int a, int b) {
    return begin[static_cast<std::size_t>(a) + 1] - begin[static_cast<std::size_t>(a)] >
           begin[static_cast<std::size_t>(b) + 1] - begin[static_cast<std::size_t>(b)];
  });
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
