// search/search_trace.hpp and search/weighted_digraph.hpp: the course's graph-search homework's graphs searched by
// every algorithm, checked against an independent A* written as the seed's Algorithm 1 (an open list searched for its
// first minimum, so ties go to the vertex that entered it first) and an independent Dijkstra; and every trace checked
// for consistency: f from g and h as the algorithm orders, each label's g its backpointer's g plus the edge's cost, the
// expansions those of SearchResult, the open list's size what was discovered and not yet expanded.
#include <polyplan/io/graph_reader.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {
namespace {

constexpr Search all_algorithms[] = {Search::astar, Search::dijkstra, Search::bfs,
                                     Search::dfs,   Search::greedy,   Search::wastar};
constexpr double inf = std::numeric_limits<double>::infinity();

GraphFile shipped(const std::string& name) {
  std::vector<std::string> warnings;
  return read_graph(std::string(POLYPLAN_SOURCE_DIR) + "/data/graphs/" + name, &warnings);
}

double heuristic(const GraphFile& graph, std::size_t v, std::size_t goal) {
  const double dx = graph.vertices[v].x - graph.vertices[goal].x, dy = graph.vertices[v].y - graph.vertices[goal].y;
  return std::sqrt(dx * dx + dy * dy);
}

// The cheapest edge u → v (infinity when there is none).
double cheapest_edge(const GraphFile& graph, std::size_t u, std::size_t v) {
  double cost = inf;
  for (std::size_t k = 0; k < graph.vertices[u].neighbors.size(); ++k)
    if (graph.vertices[u].neighbors[k] == v) cost = std::min(cost, graph.vertices[u].neighbors_cost[k]);
  return cost;
}

struct SeedAnswer {
  std::vector<std::size_t> path, expanded;
  double cost = inf;
};

// The course's graph-search homework's Algorithm 1, Ver. 2, with its priority queue: a list in insertion order whose
// first minimum is extracted; an improved vertex keeps its place with its new f. Closed vertices are never reopened.
// weight: the textbook's weighted A*, f = g + weight * h, on the same algorithm.
SeedAnswer seed_astar(const GraphFile& graph, std::size_t start, std::size_t goal, double weight = 1) {
  const std::size_t n = graph.vertices.size();
  std::vector<double> g(n, inf), f(n, inf);
  std::vector<std::optional<std::size_t>> backpointer(n);
  std::vector<bool> closed(n, false);
  std::vector<std::size_t> open{start};
  g[start] = 0;
  f[start] = weight * heuristic(graph, start, goal);
  SeedAnswer r;
  while (!open.empty()) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < open.size(); ++i)
      if (f[open[i]] < f[open[best]]) best = i;
    const std::size_t u = open[best];
    open.erase(open.begin() + static_cast<std::ptrdiff_t>(best));
    closed[u] = true;
    r.expanded.push_back(u);
    if (u == goal) {
      r.cost = g[u];
      for (std::optional<std::size_t> v = u; v; v = backpointer[*v]) r.path.insert(r.path.begin(), *v);
      return r;
    }
    const GraphVertex& vertex = graph.vertices[u];
    for (std::size_t k = 0; k < vertex.neighbors.size(); ++k) {
      const std::size_t x = vertex.neighbors[k];
      if (closed[x]) continue;
      const double through = g[u] + vertex.neighbors_cost[k];
      const bool is_open = std::find(open.begin(), open.end(), x) != open.end();
      if (!is_open) open.push_back(x);
      if (!is_open || through < g[x]) {
        g[x] = through;
        f[x] = through + weight * heuristic(graph, x, goal);
        backpointer[x] = u;
      }
    }
  }
  return r;
}

// Plain O(V²) Dijkstra: the optimal cost.
double dijkstra_cost(const GraphFile& graph, std::size_t start, std::size_t goal) {
  const std::size_t n = graph.vertices.size();
  std::vector<double> d(n, inf);
  std::vector<bool> done(n, false);
  d[start] = 0;
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t u = n;
    for (std::size_t v = 0; v < n; ++v)
      if (!done[v] && d[v] < inf && (u == n || d[v] < d[u])) u = v;
    if (u == n) break;
    done[u] = true;
    for (std::size_t k = 0; k < graph.vertices[u].neighbors.size(); ++k) {
      const std::size_t v = graph.vertices[u].neighbors[k];
      d[v] = std::min(d[v], d[u] + graph.vertices[u].neighbors_cost[k]);
    }
  }
  return d[goal];
}

SearchResult<DigraphVertexId> run_search(const GraphFile& file, std::size_t start, std::size_t goal, Search algorithm,
                                         bool seed_ties = true) {
  SearchOptions options;
  options.algorithm = algorithm;
  options.weight = 2;
  options.record_expanded = true;
  options.record_trace = true;
  options.ties_first_discovered = seed_ties;
  return shortest_path(make_weighted_digraph(file.vertices), start, goal, options);
}

double expected_key(Search algorithm, double g, double h) {
  switch (algorithm) {
    case Search::wastar: return g + 2 * h;
    case Search::dijkstra: return g;
    case Search::greedy: return h;
    default: return g + h;
  }
}

// Everything a trace says, checked against the graph and the result.
void expect_consistent_trace(const GraphFile& graph, std::size_t start, std::size_t goal, Search algorithm,
                             const SearchResult<DigraphVertexId>& r) {
  const std::string what = std::string(to_string(algorithm));
  const auto& expansions = r.trace.expansions;
  ASSERT_EQ(expansions.size(), r.expanded) << what;
  ASSERT_EQ(r.expanded_order.size(), expansions.size()) << what;
  // Each label's g is its backpointer's g at that moment plus the edge's cost; h and f as ordered.
  std::map<std::size_t, double> g_now;
  std::map<std::size_t, std::optional<std::size_t>> backpointer_now;
  std::size_t next_label = 0, discovered = 0;
  for (std::size_t k = 0; k < expansions.size(); ++k) {
    const auto& e = expansions[k];
    // The labels set before this expansion (during the previous ones).
    for (; next_label < r.trace.labels.size() && r.trace.labels[next_label].step <= k; ++next_label) {
      const auto& l = r.trace.labels[next_label];
      if (l.backpointer) {
        ASSERT_TRUE(g_now.count(*l.backpointer)) << what;
        EXPECT_EQ(l.g, g_now[*l.backpointer] + cheapest_edge(graph, *l.backpointer, l.vertex))
            << what << " label " << next_label;
      } else {
        EXPECT_EQ(l.vertex, start) << what;
        EXPECT_EQ(l.g, 0) << what;
      }
      EXPECT_EQ(l.discovered, !g_now.count(l.vertex)) << what;
      discovered += l.discovered;
      EXPECT_EQ(l.h, heuristic(graph, l.vertex, goal)) << what;
      EXPECT_EQ(l.f, expected_key(algorithm, l.g, l.h)) << what;
      g_now[l.vertex] = l.g;
      backpointer_now[l.vertex] = l.backpointer;
    }
    EXPECT_EQ(e.step, k + 1) << what;
    EXPECT_EQ(e.vertex, r.expanded_order[k]) << what;
    ASSERT_TRUE(g_now.count(e.vertex)) << what << ": expanded before it was labelled";
    EXPECT_EQ(e.g, g_now[e.vertex]) << what << " step " << e.step;
    EXPECT_EQ(e.backpointer, backpointer_now[e.vertex]) << what << " step " << e.step;
    EXPECT_EQ(e.h, heuristic(graph, e.vertex, goal)) << what;
    EXPECT_EQ(e.f, expected_key(algorithm, e.g, e.h)) << what;
    // Without reopening (weighted A* reopens only when asked) the open list is what was discovered
    // and not yet expanded; DFS's is its stack of unfinished vertices, expanded before this one.
    if (algorithm == Search::dfs) {
      EXPECT_LE(e.open, k) << what;
    } else {
      EXPECT_EQ(e.open, discovered - (k + 1)) << what << " step " << e.step;
    }
  }
  // The path follows the backpointers from the goal, and its cost is their sum.
  if (r.found) {
    EXPECT_EQ(r.path.front(), start);
    EXPECT_EQ(r.path.back(), goal);
    double cost = 0;
    for (std::size_t i = 0; i + 1 < r.path.size(); ++i) cost += cheapest_edge(graph, r.path[i], r.path[i + 1]);
    EXPECT_NEAR(r.cost, cost, 1e-12) << what;
    EXPECT_EQ(expansions.back().vertex, goal) << what;
    if (algorithm != Search::dfs) {
      EXPECT_DOUBLE_EQ(expansions.back().g, r.cost) << what;
    }
  }
}

struct GraphQuery {
  const char* file;
  std::size_t start, goal;
};
const GraphQuery queries[] = {{"small.json", 0, 6},        {"small.json", 6, 2},        {"small.json", 3, 0},
                              {"grid_medium.json", 0, 37}, {"grid_medium.json", 37, 0}, {"grid_medium.json", 5, 30}};

}  // namespace

TEST(SearchTrace, AStarExpandsAsTheSeedsAlgorithm) {
  for (const GraphQuery& q : queries) {
    const GraphFile graph = shipped(q.file);
    const SeedAnswer reference = seed_astar(graph, q.start, q.goal);
    const auto r = run_search(graph, q.start, q.goal, Search::astar);
    ASSERT_TRUE(r.found) << q.file;
    EXPECT_EQ(r.path, reference.path) << q.file << " " << q.start << " → " << q.goal;
    EXPECT_EQ(r.cost, reference.cost) << q.file;
    EXPECT_EQ(r.expanded_order, reference.expanded) << q.file << " " << q.start << " → " << q.goal;
    EXPECT_DOUBLE_EQ(r.cost, dijkstra_cost(graph, q.start, q.goal)) << q.file;
  }
}

// Weighted A* without reopening is the textbook's: the same algorithm with f = g + w·h, expansion
// for expansion.
TEST(SearchTrace, WeightedAStarExpandsAsTheSeedsAlgorithmWithWeightedH) {
  for (const GraphQuery& q : queries) {
    const GraphFile graph = shipped(q.file);
    const SeedAnswer reference = seed_astar(graph, q.start, q.goal, 2);
    const auto r = run_search(graph, q.start, q.goal, Search::wastar);
    ASSERT_TRUE(r.found) << q.file;
    EXPECT_EQ(r.path, reference.path) << q.file << " " << q.start << " → " << q.goal;
    EXPECT_EQ(r.cost, reference.cost) << q.file;
    EXPECT_EQ(r.expanded_order, reference.expanded) << q.file << " " << q.start << " → " << q.goal;
  }
}

TEST(SearchTrace, TheShippedGraphsHaveTheirDocumentedAnswers) {
  const auto small = run_search(shipped("small.json"), 0, 6, Search::astar);
  EXPECT_EQ(small.path, (std::vector<DigraphVertexId>{0, 1, 4, 6}));
  EXPECT_EQ(small.cost, 5);
  EXPECT_EQ(small.expanded_order, (std::vector<DigraphVertexId>{0, 1, 2, 4, 3, 6}));
  const auto back = run_search(shipped("small.json"), 6, 2, Search::astar);
  EXPECT_EQ(back.path, (std::vector<DigraphVertexId>{6, 5, 3, 2}));  // 2 → 5 is one-way
  EXPECT_EQ(back.cost, 5.5);
  const auto medium = run_search(shipped("grid_medium.json"), 0, 37, Search::astar);
  EXPECT_EQ(medium.path,
            (std::vector<DigraphVertexId>{0, 8, 15, 20, 25, 26, 27, 21, 16, 10, 11, 12, 13, 18, 23, 30, 37}));
  EXPECT_NEAR(medium.cost, 14 + 2 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(medium.expanded, 33u);
}

TEST(SearchTrace, EveryAlgorithmsTraceIsConsistent) {
  for (const GraphQuery& q : queries) {
    const GraphFile graph = shipped(q.file);
    const double optimal = dijkstra_cost(graph, q.start, q.goal);
    for (const Search algorithm : all_algorithms)
      for (const bool seed_ties : {true, false}) {
        const auto r = run_search(graph, q.start, q.goal, algorithm, seed_ties);
        ASSERT_TRUE(r.found) << q.file << " " << to_string(algorithm);
        expect_consistent_trace(graph, q.start, q.goal, algorithm, r);
        if (algorithm == Search::astar || algorithm == Search::dijkstra) {
          EXPECT_DOUBLE_EQ(r.cost, optimal) << to_string(algorithm);
        }
        if (algorithm == Search::wastar) {
          EXPECT_LE(r.cost, 2 * optimal + 1e-12);
        }
        EXPECT_GE(r.cost, optimal - 1e-12) << to_string(algorithm);
      }
  }
}

// A* expands vertices in nondecreasing f (the heuristic is consistent), and whatever the ties,
// exactly the vertices whose f is below the optimal cost are expanded before the goal.
TEST(SearchTrace, BoostsOwnTieOrderExpandsTheSameVerticesBelowTheOptimum) {
  for (const GraphQuery& q : queries) {
    const GraphFile graph = shipped(q.file);
    const auto heap = run_search(graph, q.start, q.goal, Search::astar, false),
               seed = run_search(graph, q.start, q.goal, Search::astar, true);
    EXPECT_EQ(heap.cost, seed.cost);
    const auto below = [&](const SearchResult<DigraphVertexId>& r) {
      std::vector<DigraphVertexId> v;
      for (const auto& e : r.trace.expansions)
        if (e.f < r.cost - 1e-9) v.push_back(e.vertex);
      std::sort(v.begin(), v.end());
      return v;
    };
    EXPECT_EQ(below(heap), below(seed)) << q.file;
    for (std::size_t k = 1; k < heap.trace.expansions.size(); ++k)
      EXPECT_LE(heap.trace.expansions[k - 1].f, heap.trace.expansions[k].f + 1e-12) << q.file;
  }
}

TEST(SearchTrace, NoTraceUnlessAskedFor) {
  const GraphFile graph = shipped("small.json");
  const auto r = shortest_path(make_weighted_digraph(graph.vertices), 0, 6, SearchOptions{});
  EXPECT_TRUE(r.found);
  EXPECT_TRUE(r.trace.expansions.empty());
  EXPECT_TRUE(r.trace.labels.empty());
}

TEST(SearchTrace, AnUnreachableGoalExhaustsTheStartsComponent) {
  // 0 → 1 one way: from 1 nothing is reachable.
  GraphFile graph;
  graph.vertices = {{0, 0, {1}, {1}}, {1, 0, {}, {}}, {2, 0, {1}, {1}}};
  const auto r = run_search(graph, 1, 0, Search::astar);
  EXPECT_FALSE(r.found);
  ASSERT_EQ(r.trace.expansions.size(), 1u);
  EXPECT_EQ(r.trace.expansions[0].open, 0u);
  EXPECT_THROW(shortest_path(make_weighted_digraph(graph.vertices), 0, 3, SearchOptions{}), std::out_of_range);
}

}  // namespace polyplan
