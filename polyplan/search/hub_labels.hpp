#pragma once
// Hub labels of an undirected graph with non-negative edge weights, by pruned landmark labelling
// (Akiba, Iwata, Yoshida, SIGMOD 2013): vertices in order of decreasing degree each run a
// Dijkstra that stops wherever the labels made so far already give the distance, and leave
// themselves as a hub, with the distance and the previous vertex, in the label of every vertex it
// reaches. Then the distance between s and t is the least d(s, h) + d(h, t) over the hubs h their
// labels share, and a shortest path is read back hop by hop through the previous vertices (each
// of which holds the same hub).
#include <polyplan/search/compressed_graph.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace polyplan {

class HubLabels {
 public:
  struct Entry {
    int hub;     // the hub's rank (labels are sorted by it)
    int parent;  // the vertex before this one on a shortest path from the hub; -1 at the hub
    double distance;
  };

  // nullopt when the labels would take more than max_bytes.
  static std::optional<HubLabels> build(const CompressedGraph& graph, std::size_t max_bytes);

  std::size_t vertex_count() const { return label_begin_.empty() ? 0 : label_begin_.size() - 1; }
  const Entry* label_begin(int v) const { return entries_.data() + label_begin_[static_cast<std::size_t>(v)]; }
  const Entry* label_end(int v) const { return entries_.data() + label_begin_[static_cast<std::size_t>(v) + 1]; }
  int hub_vertex(int rank) const { return order_[static_cast<std::size_t>(rank)]; }

  // The shortest-path distance (infinity when none).
  double distance(int s, int t) const;
  // The vertices of a shortest path from v to the hub of rank `hub` (in v's label), v first and
  // the hub last, appended to `out`.
  void path_to_hub(int v, int hub, std::vector<int>& out) const;

  std::size_t entry_count() const { return entries_.size(); }
  std::size_t memory_bytes() const;

 private:
  std::vector<int> order_;  // rank -> vertex
  std::vector<std::size_t> label_begin_;
  std::vector<Entry> entries_;
};

}  // namespace polyplan
