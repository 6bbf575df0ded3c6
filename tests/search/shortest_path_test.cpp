// search/: every algorithm on a hand-made graph with its counts worked out by hand, the classic
// comparisons (BFS vs Dijkstra, A* vs Dijkstra, greedy's suboptimality), workspace reuse on a big
// roadmap, an implicit graph, and random graphs against an independent Floyd–Warshall.
#include <polyplan/search/graph_search.hpp>
#include <polyplan/search/shortest_path.hpp>

#include <gtest/gtest.h>

#include <boost/container_hash/hash.hpp>
#include <boost/iterator/iterator_facade.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace polyplan {
namespace {

constexpr Search all_algorithms[] = {Search::astar, Search::dijkstra, Search::bfs,
                                     Search::dfs,   Search::greedy,   Search::wastar};

RoadmapVertexId add_point(Roadmap& g, long x, long y) { return add_vertex(g, ExactPoint{Rational(x), Rational(y)}); }

double distance(const Roadmap& g, RoadmapVertexId u, RoadmapVertexId v) {
  return std::hypot(g[u].x - g[v].x, g[u].y - g[v].y);
}

// ---------------------------------------------------------------------------------------------
// The hand-made graph (a course exercise): 8 vertices, 9 edges, start S, goal G = (6, 0).
//   y =  4                      T
//   y =  3                            X
//   y =  2
//   y =  1
//   y =  0             S                 G
//   y = -1          W        A     B
//   y = -2    V
//            -3 -2 -1  0  1  2  3  4  5  6   = x
// Edges, in the order added (this is each vertex's out-edge order, which fixes BFS and DFS):
//   S-W √2   S-T 5   S-A √5   S-X √34   W-V √5   A-B 2   B-G √5   T-G 5   X-G √10
// Euclidean distance h to G:  S 6   W √50=7.071   V √85=9.220   T 5   A √17=4.123
//                             B √5=2.236   X √10=3.162   G 0
// Shortest path S-A-B-G, cost 2 + 2√5 = 6.472 (3 edges). Fewest edges: S-T-G (10) or S-X-G
// (√34 + √10 = 8.993), 2 edges each.
//
// Ties: every priority compared below is distinct (checked in the comments), so the BGL heap's
// internal order never decides anything; BFS and DFS follow the out-edge order above.
struct CourseGraph {
  Roadmap g;
  RoadmapVertexId S, W, V, T, A, B, X, G;
};

CourseGraph course_graph() {
  CourseGraph c;
  c.S = add_point(c.g, 0, 0);
  c.W = add_point(c.g, -1, -1);
  c.V = add_point(c.g, -3, -2);
  c.T = add_point(c.g, 3, 4);
  c.A = add_point(c.g, 2, -1);
  c.B = add_point(c.g, 4, -1);
  c.X = add_point(c.g, 5, 3);
  c.G = add_point(c.g, 6, 0);
  add_edge(c.g, c.S, c.W);
  add_edge(c.g, c.S, c.T);
  add_edge(c.g, c.S, c.A);
  add_edge(c.g, c.S, c.X);
  add_edge(c.g, c.W, c.V);
  add_edge(c.g, c.A, c.B);
  add_edge(c.g, c.B, c.G);
  add_edge(c.g, c.T, c.G);
  add_edge(c.g, c.X, c.G);
  return c;
}

const double sqrt2 = std::sqrt(2.0), sqrt5 = std::sqrt(5.0), sqrt10 = std::sqrt(10.0), sqrt34 = std::sqrt(34.0);

TEST(CourseGraph, LengthsAreTheHandValues) {
  const CourseGraph c = course_graph();
  EXPECT_EQ(num_vertices(c.g), 8u);
  EXPECT_EQ(num_edges(c.g), 9u);
  EXPECT_DOUBLE_EQ(distance(c.g, c.S, c.W), sqrt2);
  EXPECT_DOUBLE_EQ(distance(c.g, c.S, c.X), sqrt34);
  EXPECT_DOUBLE_EQ(distance(c.g, c.X, c.G), sqrt10);
  EXPECT_EQ(c.g[c.A].exact, (ExactPoint{2, -1}));
  EXPECT_EQ(c.g[c.A].x, 2.0);
  EXPECT_EQ(c.g[c.A].y, -1.0);
}

// A*: f = g + h.
//   expand S (f 6):       generate W f=√2+√50=8.485, T f=5+5=10, A f=√5+√17=6.359, X f=√34+√10=8.993
//   expand A (f 6.359):   generate B f=(√5+2)+√5=6.472
//   expand B (f 6.472):   generate G f=6.472+0
//   expand G (f 6.472 < W 8.485 < X 8.993 < T 10): goal.
// expanded 4 (S A B G), generated 7 (all but V: W, the only way to V, is never expanded).
TEST(CourseGraph, AStar) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, Search::astar);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.A, c.B, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, 2 + 2 * sqrt5);
  EXPECT_EQ(r.expanded, 4u);
  EXPECT_EQ(r.generated, 7u);
  EXPECT_EQ(r.path_edges(), 3u);
  EXPECT_EQ(r.algorithm, Search::astar);
  EXPECT_GE(r.seconds, 0.0);
}

// Dijkstra: f = g. Expansion order by g: S 0, W √2=1.414, A √5=2.236, V √2+√5=3.650,
// B 2+√5=4.236, T 5, X √34=5.831, G 2+2√5=6.472 (distinct). Every vertex has g <= g(G), so all
// 8 are generated and expanded; G's g is final when B is expanded (via T: 10, via X: 8.993).
TEST(CourseGraph, Dijkstra) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, Search::dijkstra);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.A, c.B, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, 2 + 2 * sqrt5);
  EXPECT_EQ(r.expanded, 8u);
  EXPECT_EQ(r.generated, 8u);
}

// BFS, FIFO in out-edge order, goal test when a vertex is taken out:
//   expand S: generate W T A X      (queue W T A X)
//   expand W: generate V            (queue T A X V)
//   expand T: generate G            (queue A X V G)   G's predecessor is T
//   expand A: generate B            (queue X V G B)
//   expand X: nothing new (G already generated)
//   expand V: nothing new
//   expand G: goal.
// expanded 7 (all but B), generated 8. Path S-T-G: 2 edges, cost 10.
TEST(CourseGraph, BreadthFirst) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, Search::bfs);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.T, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, 10.0);
  EXPECT_EQ(r.expanded, 7u);
  EXPECT_EQ(r.generated, 8u);
}

// DFS (BGL's, recursive in effect; out-edge order; a vertex is expanded when discovered):
//   S -> W (first edge of S) -> V (W's edge to S leads back) -> V is a dead end, back to W,
//   back to S -> T (second edge of S) -> G (T's edge to S leads back): goal.
// Discovered, in order: S W V T G: expanded = generated = 5. Path S-T-G, cost 10.
TEST(CourseGraph, DepthFirst) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, Search::dfs);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.T, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, 10.0);
  EXPECT_EQ(r.expanded, 5u);
  EXPECT_EQ(r.generated, 5u);
}

// Greedy best-first: f = h.
//   expand S (h 6):      generate W h=7.071, T h=5, A h=4.123, X h=3.162
//   expand X (h 3.162):  generate G h=0
//   expand G: goal.
// expanded 3, generated 6 (S W T A X G). Path S-X-G costs √34+√10 = 8.993 > 6.472: greedy is
// lured by X, the neighbour of S nearest the goal, behind the long edge S-X.
TEST(CourseGraph, GreedyIsLuredAndSuboptimal) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, Search::greedy);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.X, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, sqrt34 + sqrt10);
  EXPECT_EQ(r.expanded, 3u);
  EXPECT_EQ(r.generated, 6u);
  const auto optimal = shortest_path(c.g, c.S, c.G, Search::dijkstra);
  EXPECT_GT(r.cost, optimal.cost + 2.5);
}

// Weighted A*, w = 2: f = g + 2h.
//   expand S (f 12):      generate W f=√2+2√50=15.556, T f=5+10=15, A f=√5+2√17=10.482,
//                         X f=√34+2√10=12.156
//   expand A (f 10.482):  generate B f=(√5+2)+2√5=8.708
//   expand B (f 8.708):   generate G f=6.472
//   expand G: goal. Same path and counts as A* here (the heuristic is already well informed).
TEST(CourseGraph, WeightedAStar) {
  const CourseGraph c = course_graph();
  const auto r = shortest_path(c.g, c.S, c.G, {Search::wastar, 2.0});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.path, (std::vector{c.S, c.A, c.B, c.G}));
  EXPECT_DOUBLE_EQ(r.cost, 2 + 2 * sqrt5);
  EXPECT_EQ(r.expanded, 4u);
  EXPECT_EQ(r.generated, 7u);
  EXPECT_EQ(r.algorithm, Search::wastar);
}

TEST(CourseGraph, BreadthFirstFindsFewestEdgesAtAHigherCostThanDijkstra) {
  const CourseGraph c = course_graph();
  const auto bfs = shortest_path(c.g, c.S, c.G, Search::bfs);
  const auto dijkstra = shortest_path(c.g, c.S, c.G, Search::dijkstra);
  EXPECT_LT(bfs.path_edges(), dijkstra.path_edges());
  EXPECT_GT(bfs.cost, dijkstra.cost);
}

TEST(CourseGraph, AStarExpandsFewerThanDijkstraForTheSameCost) {
  const CourseGraph c = course_graph();
  const auto astar = shortest_path(c.g, c.S, c.G, Search::astar);
  const auto dijkstra = shortest_path(c.g, c.S, c.G, Search::dijkstra);
  EXPECT_LT(astar.expanded, dijkstra.expanded);
  EXPECT_LT(astar.generated, dijkstra.generated);
  EXPECT_EQ(astar.cost, dijkstra.cost);
  EXPECT_EQ(astar.path, dijkstra.path);
}

void expect_same(const SearchResult<RoadmapVertexId>& a, const SearchResult<RoadmapVertexId>& b) {
  EXPECT_EQ(a.found, b.found);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_EQ(a.expanded, b.expanded);
  EXPECT_EQ(a.generated, b.generated);
}

TEST(CourseGraph, WeightedAStarWithWeightOneIsAStar) {
  const CourseGraph c = course_graph();
  for (RoadmapVertexId s = 0; s < num_vertices(c.g); ++s)
    for (RoadmapVertexId t = 0; t < num_vertices(c.g); ++t)
      expect_same(shortest_path(c.g, s, t, {Search::wastar, 1.0}), shortest_path(c.g, s, t, Search::astar));
}

TEST(CourseGraph, StartEqualsGoalIsAOneVertexPathOfCostZero) {
  const CourseGraph c = course_graph();
  for (Search algorithm : all_algorithms) {
    const auto r = shortest_path(c.g, c.A, c.A, {algorithm, 2.0});
    ASSERT_TRUE(r.found) << to_string(algorithm);
    EXPECT_EQ(r.path, std::vector{c.A});
    EXPECT_EQ(r.cost, 0.0);
    EXPECT_EQ(r.path_edges(), 0u);
    EXPECT_EQ(r.expanded, 1u);
    EXPECT_EQ(r.generated, 1u);
  }
}

TEST(CourseGraph, UnreachableGoalIsNotFoundAfterExhaustingTheComponent) {
  CourseGraph c = course_graph();
  const RoadmapVertexId island = add_point(c.g, 10, 10);
  const RoadmapVertexId shore = add_point(c.g, 10, 12);
  add_edge(c.g, island, shore);
  for (Search algorithm : all_algorithms) {
    const auto r = shortest_path(c.g, c.S, island, {algorithm, 2.0});
    EXPECT_FALSE(r.found) << to_string(algorithm);
    EXPECT_TRUE(r.path.empty());
    EXPECT_EQ(r.cost, 0.0);
    EXPECT_EQ(r.path_edges(), 0u);
    EXPECT_EQ(r.generated, 8u) << to_string(algorithm);  // the whole component of S, once
    if (algorithm != Search::wastar) {
      EXPECT_EQ(r.expanded, 8u) << to_string(algorithm);
    } else {
      EXPECT_GE(r.expanded, 8u);  // an inflated heuristic may re-open vertices
    }
  }
  // And an isolated start: only itself.
  const RoadmapVertexId alone = add_point(c.g, -10, -10);
  const auto r = shortest_path(c.g, alone, c.G, Search::astar);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.expanded, 1u);
  EXPECT_EQ(r.generated, 1u);
}

TEST(SearchOptions, WeightedAStarRejectsWeightsBelowOneOrNotFinite) {
  const CourseGraph c = course_graph();
  EXPECT_THROW(shortest_path(c.g, c.S, c.G, {Search::wastar, 0.5}), std::invalid_argument);
  EXPECT_THROW(shortest_path(c.g, c.S, c.G, {Search::wastar, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(shortest_path(c.g, c.S, c.G, {Search::wastar, std::numeric_limits<double>::infinity()}),
               std::invalid_argument);
  EXPECT_NO_THROW(shortest_path(c.g, c.S, c.G, {Search::astar, 0.5}));  // weight is wastar's only
}

TEST(SearchOptions, VertexOutsideTheRoadmapThrows) {
  const CourseGraph c = course_graph();
  SearchWorkspace<RoadmapVertexId> workspace;
  EXPECT_THROW(shortest_path(c.g, c.S, 8, {}, workspace), std::out_of_range);
  EXPECT_THROW(shortest_path(c.g, 99, c.G, {}), std::out_of_range);
}

TEST(SearchOptions, NamesRoundTrip) {
  for (Search algorithm : all_algorithms) EXPECT_EQ(search_from_string(to_string(algorithm)), algorithm);
  EXPECT_EQ(to_string(Search::astar), "astar");
  EXPECT_EQ(to_string(Search::wastar), "wastar");
  EXPECT_EQ(search_from_string("dijkstra"), Search::dijkstra);
  EXPECT_EQ(search_from_string("A*"), std::nullopt);
  EXPECT_EQ(search_from_string("BFS"), std::nullopt);
  EXPECT_EQ(search_from_string(""), std::nullopt);
}

// ---------------------------------------------------------------------------------------------
// A grid-like roadmap of 400 x 250 = 10^5 vertices, 8-connected, with walls (vertices left
// without edges): gapped walls that force detours, and a closed box whose inside is cut off.
bool in_wall(int x, int y) {
  if (x % 50 == 25 && y % 60 > 3) return true;  // vertical walls with gaps at y % 60 in 0..3
  const bool box_x = x >= 100 && x <= 120, box_y = y >= 100 && y <= 120;
  return box_x && box_y && (x == 100 || x == 120 || y == 100 || y == 120);
}
bool in_box(int x, int y) { return x >= 100 && x <= 120 && y >= 100 && y <= 120; }

Roadmap walled_grid(int width, int height) {
  Roadmap g;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) add_point(g, x, y);
  const auto id = [width](int x, int y) { return static_cast<RoadmapVertexId>(y * width + x); };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (in_wall(x, y)) continue;
      const int dx[] = {1, 0, 1, -1}, dy[] = {0, 1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || nx >= width || ny >= height || in_wall(nx, ny)) continue;
        add_edge(g, id(x, y), id(nx, ny));
      }
    }
  return g;
}

// Every query runs on a workspace reused since the first query (versioned array, and hash map)
// and on a fresh one; a stale distance, colour or predecessor would change a path or a count.
// Queries alternate the algorithms; most are local (the workspaces then hold state far from the
// next query's), every 50th crosses the map, some start inside the box or on an isolated wall
// vertex (goal unreachable), some have start == goal.
TEST(SearchWorkspace, ReusedAcrossAThousandQueriesOnABigRoadmapGivesTheResultsOfAFreshOne) {
  const int width = 400, height = 250;
  const Roadmap g = walled_grid(width, height);
  ASSERT_EQ(num_vertices(g), 100000u);
  std::mt19937 random(12345);
  std::uniform_int_distribution<int> any_x(0, width - 1), any_y(0, height - 1), near(-20, 20), box(101, 119);
  const auto free_near = [&](int x, int y, bool anywhere) {
    for (;;) {
      const int nx = anywhere ? any_x(random) : std::clamp(x + near(random), 0, width - 1);
      const int ny = anywhere ? any_y(random) : std::clamp(y + near(random), 0, height - 1);
      if (!in_wall(nx, ny) && !in_box(nx, ny)) return std::pair{nx, ny};
    }
  };
  SearchWorkspace<RoadmapVertexId> reused_dense;                          // versioned array
  SearchWorkspace<RoadmapVertexId> reused_hashed(VertexStorage::hashed);  // hash map
  std::size_t found = 0, not_found = 0;
  for (int i = 0; i < 1000; ++i) {
    auto [sx, sy] = free_near(0, 0, true);
    auto [gx, gy] = free_near(sx, sy, i % 50 == 0);
    if (i % 100 == 7) sx = box(random), sy = box(random);  // inside the box: the goal is out of reach
    if (i % 100 == 13) sx = 25, sy = 30;                   // a wall vertex: no edges at all
    if (i % 100 == 21) gx = sx, gy = sy;                   // start == goal
    const RoadmapVertexId start = sy * width + sx, goal = gy * width + gx;
    const SearchOptions options{all_algorithms[i % 6], 1.5};
    const auto a = shortest_path(g, start, goal, options, reused_dense);
    const auto b = shortest_path(g, start, goal, options, reused_hashed);
    const auto fresh = shortest_path(g, start, goal, options);  // a new (hash) workspace each time
    SCOPED_TRACE(testing::Message() << "query " << i << " " << to_string(options.algorithm));
    expect_same(a, fresh);
    expect_same(b, fresh);
    EXPECT_EQ(reused_dense.touched(), reused_hashed.touched());
    if (i % 100 == 0) {
      SearchWorkspace<RoadmapVertexId> fresh_dense;
      expect_same(shortest_path(g, start, goal, options, fresh_dense), fresh);
    }
    (a.found ? found : not_found) += 1;
    if (a.found) {
      ASSERT_EQ(a.path.front(), start);
      ASSERT_EQ(a.path.back(), goal);
    }
  }
  EXPECT_EQ(not_found, 20u);
  EXPECT_EQ(found, 980u);
}

// ---------------------------------------------------------------------------------------------
// Random geometric graphs against an independent all-pairs Floyd–Warshall.

struct RandomGraph {
  Roadmap g;
  std::vector<std::vector<double>> length;  // all-pairs shortest lengths
  std::vector<std::vector<int>> hops;       // all-pairs fewest edges
};

RandomGraph random_graph(std::mt19937& random, int n, double edge_probability) {
  RandomGraph r;
  std::uniform_int_distribution<long> coordinate(-1000, 1000);
  for (int i = 0; i < n; ++i) add_point(r.g, coordinate(random), coordinate(random));
  const double inf = std::numeric_limits<double>::infinity();
  r.length.assign(n, std::vector<double>(n, inf));
  r.hops.assign(n, std::vector<int>(n, n + 1));
  std::bernoulli_distribution edge(edge_probability);
  for (int i = 0; i < n; ++i) {
    r.length[i][i] = 0;
    r.hops[i][i] = 0;
    for (int j = i + 1; j < n; ++j)
      if (edge(random)) {
        add_edge(r.g, i, j);
        r.length[i][j] = r.length[j][i] = std::min(r.length[i][j], distance(r.g, i, j));
        r.hops[i][j] = r.hops[j][i] = 1;
      }
  }
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        r.length[i][j] = std::min(r.length[i][j], r.length[i][k] + r.length[k][j]);
        r.hops[i][j] = std::min(r.hops[i][j], r.hops[i][k] + r.hops[k][j]);
      }
  return r;
}

// The path is a walk along edges from start to goal whose lengths sum to the reported cost.
void expect_valid_path(const Roadmap& g, const SearchResult<RoadmapVertexId>& r, RoadmapVertexId s, RoadmapVertexId t) {
  ASSERT_FALSE(r.path.empty());
  EXPECT_EQ(r.path.front(), s);
  EXPECT_EQ(r.path.back(), t);
  double cost = 0;
  for (std::size_t i = 0; i + 1 < r.path.size(); ++i) {
    ASSERT_TRUE(edge(r.path[i], r.path[i + 1], g).second);
    cost += distance(g, r.path[i], r.path[i + 1]);
  }
  EXPECT_NEAR(r.cost, cost, 1e-9 * (1 + cost));
}

TEST(RandomGraphs, CostsAgreeWithFloydWarshall) {
  std::mt19937 random(2024);
  SearchWorkspace<RoadmapVertexId> workspace;
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 10 + trial * 2;
    const RandomGraph r = random_graph(random, n, trial % 2 ? 0.08 : 0.25);
    for (int s = 0; s < n; ++s)
      for (int t = 0; t < n; ++t) {
        const double optimal = r.length[s][t];
        const double tolerance = 1e-9 * (1 + optimal);
        const bool reachable = optimal < std::numeric_limits<double>::infinity();
        SCOPED_TRACE(testing::Message() << "trial " << trial << " " << s << " -> " << t);
        for (Search algorithm : all_algorithms) {
          const auto result = shortest_path(r.g, s, t, {algorithm, 1.5}, workspace);
          ASSERT_EQ(result.found, reachable) << to_string(algorithm);
          if (!reachable) continue;
          expect_valid_path(r.g, result, s, t);
          switch (algorithm) {
            case Search::astar:
            case Search::dijkstra: EXPECT_NEAR(result.cost, optimal, tolerance) << to_string(algorithm); break;
            case Search::wastar: EXPECT_LE(result.cost, 1.5 * optimal + tolerance); break;
            case Search::bfs: EXPECT_EQ(static_cast<int>(result.path_edges()), r.hops[s][t]); break;
            case Search::dfs:
            case Search::greedy: EXPECT_GE(result.cost, optimal - tolerance); break;
          }
        }
        // The heuristic is admissible: A* never expands more than Dijkstra (up to ties at f = cost).
        const auto astar = shortest_path(r.g, s, t, {Search::astar}, workspace);
        const auto dijkstra = shortest_path(r.g, s, t, {Search::dijkstra}, workspace);
        if (reachable) {
          EXPECT_LE(astar.expanded, dijkstra.expanded + 1);
        }
      }
  }
}

// ---------------------------------------------------------------------------------------------
// The generic entry point on another Boost graph: the course graph as an adjacency_list with listS
// vertices (descriptors are pointers, so the workspace uses its hash storage) gives the Roadmap's
// paths, costs and counts exactly, for every algorithm and every pair of vertices.
TEST(GenericGraphs, ListVertexStorageGivesTheRoadmapResults) {
  using ListGraph = boost::adjacency_list<boost::vecS, boost::listS, boost::undirectedS, RoadmapVertex, RoadmapEdge>;
  using ListVertex = boost::graph_traits<ListGraph>::vertex_descriptor;
  static_assert(!has_dense_vertex_ids<ListGraph>::value);
  static_assert(has_dense_vertex_ids<Roadmap>::value);
  const CourseGraph c = course_graph();
  ListGraph l;
  std::vector<ListVertex> to_list;
  for (RoadmapVertexId v = 0; v < num_vertices(c.g); ++v) {
    to_list.push_back(boost::add_vertex(l));
    l[to_list.back()] = c.g[v];
  }
  for (auto [e, end] = edges(c.g); e != end; ++e)  // in the order added: same out-edge order
    boost::add_edge(to_list[source(*e, c.g)], to_list[target(*e, c.g)], c.g[*e], l);
  SearchWorkspace<ListVertex> workspace;
  const auto length = [&l](const boost::graph_traits<ListGraph>::edge_descriptor& e) { return l[e].length; };
  for (Search algorithm : all_algorithms)
    for (RoadmapVertexId s = 0; s < num_vertices(c.g); ++s)
      for (RoadmapVertexId t = 0; t < num_vertices(c.g); ++t) {
        const double gx = l[to_list[t]].x, gy = l[to_list[t]].y;
        const auto euclidean = [&](ListVertex v) { return std::hypot(l[v].x - gx, l[v].y - gy); };
        const auto expected = shortest_path(c.g, s, t, {algorithm, 2.0});
        const auto r = shortest_path(l, to_list[s], to_list[t], {algorithm, 2.0}, euclidean, length, workspace);
        std::vector<ListVertex> expected_path;
        for (RoadmapVertexId v : expected.path) expected_path.push_back(to_list[v]);
        EXPECT_EQ(r.path, expected_path) << to_string(algorithm);
        EXPECT_EQ(r.cost, expected.cost);
        EXPECT_EQ(r.expanded, expected.expanded);
        EXPECT_EQ(r.generated, expected.generated);
      }
}

// ---------------------------------------------------------------------------------------------
// The generic search on an implicit graph: an unbounded 4-connected grid of cells, decided on the
// fly, with a wall. No vertex list, nothing stored: the workspace's hash storage holds only what
// the search touches.
namespace plane {

struct Cell {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const Cell&, const Cell&) = default;
  friend std::size_t hash_value(const Cell& c) {
    std::size_t seed = 0;
    boost::hash_combine(seed, c.x);
    boost::hash_combine(seed, c.y);
    return seed;
  }
};

struct Step {
  Cell from, to;
  friend bool operator==(const Step&, const Step&) = default;
};

// The wall x = 0 for -50 <= y <= 50; every other cell of Z^2 is free.
struct WalledPlane {
  static bool blocked(const Cell& c) { return c.x == 0 && c.y >= -50 && c.y <= 50; }
};

class StepIterator : public boost::iterator_facade<StepIterator, Step, std::forward_iterator_tag, Step> {
 public:
  StepIterator() = default;
  StepIterator(Cell from, int direction) : from_(from), direction_(direction) { skip_blocked(); }

 private:
  friend class boost::iterator_core_access;
  static constexpr std::int64_t dx[] = {1, 0, -1, 0}, dy[] = {0, 1, 0, -1};
  Cell neighbour() const { return {from_.x + dx[direction_], from_.y + dy[direction_]}; }
  void skip_blocked() {
    while (direction_ < 4 && WalledPlane::blocked(neighbour())) ++direction_;
  }
  Step dereference() const { return {from_, neighbour()}; }
  void increment() {
    ++direction_;
    skip_blocked();
  }
  bool equal(const StepIterator& other) const { return direction_ == other.direction_ && from_ == other.from_; }
  Cell from_;
  int direction_ = 4;
};

std::pair<StepIterator, StepIterator> out_edges(const Cell& c, const WalledPlane&) {
  return {StepIterator(c, 0), StepIterator(c, 4)};
}
std::size_t out_degree(const Cell& c, const WalledPlane& g) {
  auto [b, e] = out_edges(c, g);
  return static_cast<std::size_t>(std::distance(b, e));
}
Cell source(const Step& s, const WalledPlane&) { return s.from; }
Cell target(const Step& s, const WalledPlane&) { return s.to; }

}  // namespace plane
}  // namespace
}  // namespace polyplan

namespace boost {
template <>
struct graph_traits<polyplan::plane::WalledPlane> {
  using vertex_descriptor = polyplan::plane::Cell;
  using edge_descriptor = polyplan::plane::Step;
  using out_edge_iterator = polyplan::plane::StepIterator;
  using directed_category = directed_tag;
  using edge_parallel_category = disallow_parallel_edge_tag;
  using traversal_category = incidence_graph_tag;
  using degree_size_type = std::size_t;
  static vertex_descriptor null_vertex() { return {INT64_MIN, INT64_MIN}; }
};
}  // namespace boost

namespace polyplan {
namespace {

TEST(ImplicitGraph, SameEntryPointSearchesAnUnboundedGridWithMemoryForTouchedCellsOnly) {
  using plane::Cell;
  const plane::WalledPlane g;
  const Cell start{-3, 0}, goal{3, 0};
  const auto manhattan = [goal](const Cell& c) { return double(std::abs(c.x - goal.x) + std::abs(c.y - goal.y)); };
  const auto unit = [](const plane::Step&) { return 1.0; };
  SearchWorkspace<Cell> workspace;  // automatic: hash storage, the plane has no dense ids
  // Around the wall: 51 up to y = 51, 6 across (x -3 -> 3), 51 down: 108 steps.
  const auto astar = shortest_path(g, start, goal, {Search::astar}, manhattan, unit, workspace);
  ASSERT_TRUE(astar.found);
  EXPECT_EQ(astar.cost, 108.0);
  EXPECT_EQ(astar.path_edges(), 108u);
  EXPECT_EQ(astar.path.front(), start);
  EXPECT_EQ(astar.path.back(), goal);
  EXPECT_LT(workspace.touched(), 20000u);  // an infinite graph; touched cells only

  const auto dijkstra = shortest_path(g, start, goal, {Search::dijkstra}, manhattan, unit, workspace);
  EXPECT_EQ(dijkstra.cost, 108.0);
  EXPECT_LT(astar.expanded, dijkstra.expanded);
  const auto bfs = shortest_path(g, start, goal, {Search::bfs}, manhattan, unit, workspace);
  EXPECT_EQ(bfs.path_edges(), 108u);
  const auto greedy = shortest_path(g, start, goal, {Search::greedy}, manhattan, unit, workspace);
  ASSERT_TRUE(greedy.found);
  EXPECT_GE(greedy.cost, 108.0);
  const auto wastar = shortest_path(g, start, goal, {Search::wastar, 3.0}, manhattan, unit, workspace);
  ASSERT_TRUE(wastar.found);
  EXPECT_LE(wastar.cost, 3 * 108.0);
  EXPECT_LE(wastar.expanded, astar.expanded);
  // Each step of a path is an edge of the plane.
  for (std::size_t i = 0; i + 1 < greedy.path.size(); ++i) {
    const Cell a = greedy.path[i], b = greedy.path[i + 1];
    EXPECT_EQ(std::abs(a.x - b.x) + std::abs(a.y - b.y), 1);
    EXPECT_FALSE(plane::WalledPlane::blocked(b));
  }
}

}  // namespace
}  // namespace polyplan
