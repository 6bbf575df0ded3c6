// Where a search keeps its per-vertex state, measured on a Roadmap, against plain BGL as the peer.
// Belongs in bench/ (Google Benchmark; performance claims are not timed unit tests).
//
// Roadmap: the 400 x 250 8-connected grid (10^5 vertices, ~4 * 10^5 edges); random queries, the goal
// within `radius` cells of the start (1000 queries; radius 400: anywhere, 100 queries). Variants:
//   dense_reused   SearchWorkspace reused, versioned array (VertexStorage::automatic on a Roadmap)
//   hashed_reused  SearchWorkspace reused, std::unordered_map (VertexStorage::hashed)
//   hashed_fresh   shortest_path(roadmap, s, t, options): a fresh hash workspace per query
//   dense_fresh    a fresh versioned-array workspace per query (pays O(V) allocation every time)
//   bgl_peer       boost::astar_search with vector property maps: O(V) initialisation per query
#include <polyplan/search/shortest_path.hpp>

#include <benchmark/benchmark.h>
#include <boost/graph/astar_search.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace polyplan;

const Roadmap& grid() {
  static const Roadmap g = [] {
    const int width = 400, height = 250;
    Roadmap r;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) add_vertex(r, ExactPoint{x, y});
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const int dx[] = {1, 0, 1, -1}, dy[] = {0, 1, 1, 1};
        for (int k = 0; k < 4; ++k) {
          const int nx = x + dx[k], ny = y + dy[k];
          if (nx >= 0 && nx < width && ny < height)
            add_edge(r, static_cast<RoadmapVertexId>(y * width + x), static_cast<RoadmapVertexId>(ny * width + nx));
        }
      }
    return r;
  }();
  return g;
}

std::vector<std::pair<RoadmapVertexId, RoadmapVertexId>> queries(int radius) {
  const int width = 400, height = 250;
  std::mt19937 random(1);
  std::uniform_int_distribution<int> any_x(0, width - 1), any_y(0, height - 1), near(-radius, radius);
  std::vector<std::pair<RoadmapVertexId, RoadmapVertexId>> q;
  for (int i = 0; i < (radius >= 400 ? 100 : 1000); ++i) {
    const int sx = any_x(random), sy = any_y(random);
    const int gx = std::clamp(sx + near(random), 0, width - 1), gy = std::clamp(sy + near(random), 0, height - 1);
    q.emplace_back(sy * width + sx, gy * width + gx);
  }
  return q;
}

enum Variant { dense_reused, hashed_reused, hashed_fresh, dense_fresh, bgl_peer };

struct FoundGoal {};
struct PeerVisitor : boost::default_astar_visitor {
  RoadmapVertexId goal;
  std::size_t* expanded;
  void examine_vertex(RoadmapVertexId u, const Roadmap&) {
    ++*expanded;
    if (u == goal) throw FoundGoal{};
  }
};

template <Variant variant>
void search(benchmark::State& state) {
  const Roadmap& g = grid();
  const Search algorithm = static_cast<Search>(state.range(0));
  const auto q = queries(static_cast<int>(state.range(1)));
  SearchWorkspace<RoadmapVertexId> dense, hashed(VertexStorage::hashed);
  std::vector<double> distance(num_vertices(g)), rank(num_vertices(g));
  std::vector<RoadmapVertexId> predecessor(num_vertices(g));
  std::size_t expanded = 0;
  for (auto _ : state) {
    for (auto [s, t] : q) {
      if constexpr (variant == dense_reused) expanded += shortest_path(g, s, t, {algorithm}, dense).expanded;
      if constexpr (variant == hashed_reused) expanded += shortest_path(g, s, t, {algorithm}, hashed).expanded;
      if constexpr (variant == hashed_fresh) expanded += shortest_path(g, s, t, {algorithm}).expanded;
      if constexpr (variant == dense_fresh) {
        SearchWorkspace<RoadmapVertexId> fresh;
        expanded += shortest_path(g, s, t, {algorithm}, fresh).expanded;
      }
      if constexpr (variant == bgl_peer) {
        const double gx = g[t].x, gy = g[t].y;
        const bool zero = algorithm == Search::dijkstra;
        const auto h = [&](RoadmapVertexId v) { return zero ? 0.0 : std::hypot(g[v].x - gx, g[v].y - gy); };
        try {
          boost::astar_search(g, s, h,
                              boost::visitor(PeerVisitor{{}, t, &expanded})
                                  .predecessor_map(predecessor.data())
                                  .distance_map(distance.data())
                                  .rank_map(rank.data())
                                  .weight_map(get(&RoadmapEdge::length, g)));
        } catch (const FoundGoal&) {
        }
      }
    }
  }
  state.counters["queries_per_s"] =
      benchmark::Counter(static_cast<double>(q.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["expanded_per_query"] =
      static_cast<double>(expanded) / static_cast<double>(state.iterations() * q.size());
}

void arguments(benchmark::internal::Benchmark* b, bool with_bfs) {
  for (Search a : {Search::astar, Search::dijkstra, Search::bfs}) {
    if (a == Search::bfs && !with_bfs) continue;
    for (int radius : {3, 30, 400}) b->Args({static_cast<int>(a), radius});
  }
  b->ArgNames({"algorithm", "radius"})->Unit(benchmark::kMillisecond);
}

BENCHMARK(search<dense_reused>)->Apply([](auto* b) { arguments(b, true); });
BENCHMARK(search<hashed_reused>)->Apply([](auto* b) { arguments(b, true); });
BENCHMARK(search<hashed_fresh>)->Apply([](auto* b) { arguments(b, true); });
BENCHMARK(search<dense_fresh>)->Apply([](auto* b) { arguments(b, true); });
BENCHMARK(search<bgl_peer>)->Apply([](auto* b) { arguments(b, false); });

}  // namespace

BENCHMARK_MAIN();
