// Bidirectional Dijkstra against BGL's Dijkstra on random weighted graphs, undirected and directed:
// the same costs, valid paths whose weights add up to the cost, no path between components, the
// trivial query.
#include <polyplan/search/bidirectional_search.hpp>
#include <polyplan/search/weighted_digraph.hpp>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace polyplan {
namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, double>>;

// n vertices, m random edges with random weights (a few of weight 0), as two halves that a
// single edge may or may not join.
Graph random_graph(std::size_t n, std::size_t m, std::mt19937_64& random, bool joined) {
  Graph g(n);
  std::uniform_int_distribution<std::size_t> half(0, n / 2 - 1);
  std::uniform_real_distribution<double> weight(0, 10);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t offset = i % 2 ? n / 2 : 0;
    const double w = i % 17 == 0 ? 0.0 : weight(random);
    boost::add_edge(offset + half(random), offset + half(random), w, g);
  }
  if (joined) boost::add_edge(half(random), n / 2 + half(random), weight(random), g);
  return g;
}

// The sum of the weights along `path`, each step the lightest out-edge to the next vertex; inf
// when a step is no edge (in its direction).
template <class G, class WeightFn>
double path_weight(const G& g, const std::vector<std::size_t>& path, const WeightFn& weight) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    double lightest = std::numeric_limits<double>::infinity();
    for (auto [e, end] = boost::out_edges(path[i], g); e != end; ++e)
      if (boost::target(*e, g) == path[i + 1]) lightest = std::min(lightest, weight(*e));
    sum += lightest;
  }
  return sum;
}

TEST(BidirectionalDijkstra, FindsDijkstrasCostsWithValidPaths) {
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Graph g = random_graph(400, 1600, random, trial % 4 != 0);
    const auto weights = boost::get(boost::edge_weight, g);
    std::uniform_int_distribution<std::size_t> vertex(0, 399);
    for (int q = 0; q < 20; ++q) {
      const std::size_t s = vertex(random), t = vertex(random);
      std::vector<double> distance(400);
      boost::dijkstra_shortest_paths(g, s, boost::distance_map(distance.data()));
      const auto result = bidirectional_dijkstra(g, s, t, [&](const Graph::edge_descriptor& e) { return weights[e]; });
      const bool reachable = distance[t] < std::numeric_limits<double>::max();
      ASSERT_EQ(result.found, reachable) << s << " to " << t;
      if (!reachable) continue;
      EXPECT_NEAR(result.cost, distance[t], 1e-9 * (1 + distance[t]));
      ASSERT_FALSE(result.path.empty());
      EXPECT_EQ(result.path.front(), s);
      EXPECT_EQ(result.path.back(), t);
      const double sum = path_weight(g, result.path, [&](const Graph::edge_descriptor& e) { return weights[e]; });
      EXPECT_NEAR(sum, result.cost, 1e-9 * (1 + sum));
      EXPECT_LE(result.expanded, result.generated);
    }
  }
}

// The course's directed graphs (search/weighted_digraph.hpp): the backward search walks the edges
// reversed, so one-way edges and asymmetric costs give Dijkstra's costs along edges in their direction.
TEST(BidirectionalDijkstra, DirectedGraphsGiveDijkstrasCostsAlongEdgesInTheirDirection) {
  std::mt19937_64 random(48);
  std::uniform_int_distribution<std::size_t> vertex(0, 199);
  std::uniform_real_distribution<double> cost(0, 10);
  for (int trial = 0; trial < 10; ++trial) {
    WeightedDigraph g(200);
    for (int i = 0; i < 500; ++i) boost::add_edge(vertex(random), vertex(random), DigraphEdge{cost(random)}, g);
    const auto edge_cost = [&](const WeightedDigraph::edge_descriptor& e) { return g[e].cost; };
    for (int q = 0; q < 20; ++q) {
      const std::size_t s = vertex(random), t = vertex(random);
      std::vector<double> distance(200);
      boost::dijkstra_shortest_paths(
          g, s, boost::distance_map(distance.data()).weight_map(boost::get(&DigraphEdge::cost, g)));
      const auto result = bidirectional_shortest_path(g, s, t);
      const bool reachable = distance[t] < std::numeric_limits<double>::max();
      ASSERT_EQ(result.found, reachable) << s << " to " << t;
      if (!reachable) continue;
      EXPECT_NEAR(result.cost, distance[t], 1e-9 * (1 + distance[t]));
      ASSERT_EQ(result.path.front(), s);
      ASSERT_EQ(result.path.back(), t);
      EXPECT_NEAR(path_weight(g, result.path, edge_cost), result.cost, 1e-9 * (1 + result.cost));
    }
  }
}

TEST(BidirectionalDijkstra, StartAtTheGoalAndOutOfRange) {
  Graph g(3);
  boost::add_edge(0, 1, 1.0, g);
  const auto weights = boost::get(boost::edge_weight, g);
  const auto w = [&](const Graph::edge_descriptor& e) { return weights[e]; };
  const auto same = bidirectional_dijkstra(g, 1, 1, w);
  EXPECT_TRUE(same.found);
  EXPECT_EQ(same.path, (std::vector<std::size_t>{1}));
  EXPECT_EQ(same.cost, 0);
  EXPECT_FALSE(bidirectional_dijkstra(g, 0, 2, w).found);
  EXPECT_THROW(bidirectional_dijkstra(g, 0, 3, w), std::out_of_range);
}

// On a path graph the two searches meet in the middle: each settles about half the vertices.
TEST(BidirectionalDijkstra, SettlesAboutHalfOfALineFromEachEnd) {
  Graph g(101);
  for (std::size_t i = 0; i < 100; ++i) boost::add_edge(i, i + 1, 1.0, g);
  const auto weights = boost::get(boost::edge_weight, g);
  const auto result = bidirectional_dijkstra(g, 0, 100, [&](const Graph::edge_descriptor& e) { return weights[e]; });
  EXPECT_EQ(result.cost, 100);
  EXPECT_EQ(result.path.size(), 101u);
  EXPECT_LE(result.expanded, 102u);
  EXPECT_GE(result.expanded, 100u);
}

}  // namespace
}  // namespace polyplan
