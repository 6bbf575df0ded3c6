// The visibility graph's paths against an independent brute force (every pair of free-space
// boundary vertices joined when check_path accepts the segment, then Dijkstra), on the exactness
// worlds, and on the MovingAI maps against Polyanya's Euclidean lengths (data/movingai).
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/root_sum.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <queue>
#include <random>
#include <sstream>

using namespace polyplan;
using polyplan::test::between;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

double length(const ExactPoint& a, const ExactPoint& b) {
  return std::hypot(to_double(a.x) - to_double(b.x), to_double(a.y) - to_double(b.y));
}

using Report = PlanReport<ExactPoint>;

double path_length(const std::vector<ExactPoint>& path) {
  double total = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) total += length(path[i], path[i + 1]);
  return total;
}

// O(n^3) exact reference: nodes are all boundary vertices of the free space plus start and goal.
std::optional<double> brute_force_length(const CSpace& cspace, const ExactPoint& start, const ExactPoint& goal) {
  std::vector<ExactPoint> nodes{start, goal};
  for (const FreeComponent& c : cspace.free_components()) {
    nodes.insert(nodes.end(), c.outer.begin(), c.outer.end());
    for (const Ring& h : c.holes) nodes.insert(nodes.end(), h.begin(), h.end());
  }
  const std::size_t n = nodes.size();
  std::vector<double> dist(n, INFINITY);
  std::vector<bool> done(n, false);
  dist[0] = 0;
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t u = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && (u == n || dist[i] < dist[u])) u = i;
    if (u == n || dist[u] == INFINITY) break;
    done[u] = true;
    if (u == 1) return dist[1];
    for (std::size_t v = 0; v < n; ++v)
      if (!done[v] && dist[u] + length(nodes[u], nodes[v]) < dist[v] && check_path(cspace, {nodes[u], nodes[v]}).valid)
        dist[v] = dist[u] + length(nodes[u], nodes[v]);
  }
  return std::nullopt;
}

std::string random_world(std::mt19937& rng, int obstacles, const std::string& robot) {
  std::uniform_int_distribution<int> coordinate(5, 195), size(4, 30), angle(0, 359);
  std::ostringstream w;
  w << R"({"bounds": [0, 0, 20, 20], "obstacles": [)";
  for (int i = 0; i < obstacles; ++i) {
    // A convex polygon: points on a circle at sorted random angles (decimal coordinates).
    const double cx = coordinate(rng) / 10.0, cy = coordinate(rng) / 10.0, r = size(rng) / 20.0;
    std::vector<int> angles;
    for (int k = 0; k < 5; ++k) angles.push_back(angle(rng));
    std::sort(angles.begin(), angles.end());
    angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
    if (i) w << ", ";
    w << "[";
    for (std::size_t k = 0; k < angles.size(); ++k) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "[%.3f, %.3f]", cx + r * std::cos(angles[k] * M_PI / 180),
                    cy + r * std::sin(angles[k] * M_PI / 180));
      w << (k ? ", " : "") << buffer;
    }
    w << "]";
  }
  w << "]" << robot << "}";
  return w.str();
}

}  // namespace

TEST(VisibilityGraph, AroundOneSquare) {
  const CSpace c(world_from(R"({"obstacles": [[[1, 1], [3, 1], [3, 3], [1, 3]]]})"));
  VisibilityGraph graph(c);
  const Report plan = graph.plan(between(pt("0", "0"), pt("4", "4")));
  EXPECT_EQ(plan.facts.at(RoadmapFacts::vertices), 4);
  EXPECT_EQ(plan.facts.at(RoadmapFacts::edges), 4);  // the sides; the diagonals cross the square
  ASSERT_TRUE(plan.found);
  EXPECT_NEAR(plan.length, 2 * std::hypot(1, 3), 1e-12);
  EXPECT_EQ(plan.path.size(), 3u);
}

TEST(VisibilityGraph, MatchesBruteForceOnRandomWorlds) {
  std::mt19937 rng(7);
  int compared = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const std::string robot =
        trial % 2 ? "" : R"(, "robot": {"parts": [[[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]]]})";
    const std::string text = random_world(rng, 4 + trial % 5, robot);
    SCOPED_TRACE(text);
    const World world = world_from(text);
    const CSpace cspace(world);
    VisibilityGraph graph(cspace);
    std::uniform_int_distribution<int> coordinate(1, 199);
    for (int q = 0; q < 5; ++q) {
      const ExactPoint s{Rational(coordinate(rng), 10), Rational(coordinate(rng), 10)};
      const ExactPoint g{Rational(coordinate(rng), 10), Rational(coordinate(rng), 10)};
      if (cspace.locate(s).kind == Location::Kind::blocked || cspace.locate(g).kind == Location::Kind::blocked)
        continue;
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      Report plan;
      try {
        plan = graph.plan(between(s, g));
      } catch (const std::exception& e) {
        FAIL() << e.what() << " from " << to_string(s.x) << "," << to_string(s.y) << " to " << to_string(g.x) << ","
               << to_string(g.y) << " in " << text;
      }
      const auto expected = brute_force_length(cspace, s, g);
      ASSERT_EQ(plan.found, expected.has_value());
      if (!expected) continue;
      EXPECT_NEAR(plan.length, *expected, 1e-9 * std::max(1.0, *expected));
      EXPECT_NEAR(path_length(plan.path), plan.length, 1e-9 * std::max(1.0, plan.length));
      // Independent of the triangulation that found and verified it: the arrangement's check.
      EXPECT_TRUE(check_path(cspace, plan.path).valid) << check_path(cspace, plan.path).reason;
      ++compared;
    }
  }
  EXPECT_GT(compared, 30);
}

namespace {

World shipped(const std::string& name) { return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name); }

std::vector<Report> plan_all(const World& world, VisibilityKind kind = VisibilityKind::reduced) {
  const CSpace cspace(world);
  VisibilityGraph graph(cspace, kind);
  std::vector<Report> plans;
  for (const Query& q : world.queries) plans.push_back(graph.plan(q));
  return plans;
}

}  // namespace

TEST(VisibilityGraph, DecimalApexesOnTheSegmentAreGrazedNotHit) {
  // Both triangle apexes lie exactly on the start-goal segment, on opposite sides; in doubles
  // each falls on the wrong side of the line. The answer is the straight segment, sqrt(117).
  const auto plans = plan_all(shipped("decimal.json"));
  ASSERT_TRUE(plans[0].found);
  EXPECT_EQ(plans[0].path.size(), 2u);
  EXPECT_DOUBLE_EQ(plans[0].length, std::sqrt(117.0));
  // The vault's door is 1e-17 wide: open exactly, shut for anything reading doubles.
  EXPECT_TRUE(plans[1].found);
}

TEST(VisibilityGraph, ExactFitCorridorIsClosedAndOneBillionthWiderIsOpen) {
  EXPECT_FALSE(plan_all(shipped("corridor_exact.json"))[0].found);
  const Report wide = plan_all(shipped("corridor_wide.json"))[0];
  ASSERT_TRUE(wide.found);
  EXPECT_NEAR(wide.length, 15.0, 1e-12);  // straight along y = 4.5, sliding on the lower block
}

TEST(VisibilityGraph, ARobotThatFitsNowhereHasNoPathNotACrash) {
  // A 6×6 robot in a 4×4 box: no free space, so an empty triangulation (its flood fill once
  // walked off the empty triangulation's infinite face).
  const World world = test::world_from(R"({"bounds": [0, 0, 4, 4], "obstacles": [],
      "robot": {"parts": [[[-3, -3], [3, -3], [3, 3], [-3, 3]]]}, "start": [2, 2], "goal": [2, 2]})");
  const CSpace cspace(world);
  EXPECT_TRUE(cspace.free_components().empty());
  VisibilityGraph graph(cspace);
  const Report report = graph.plan(world.queries.front());
  EXPECT_FALSE(report.found);
  EXPECT_NE(report.why_not.find("not free"), std::string::npos) << report.why_not;
}

TEST(VisibilityGraph, PinchPointIsNotAPassage) { EXPECT_FALSE(plan_all(shipped("touching_corners.json"))[0].found); }

TEST(VisibilityGraph, EnclosedGoalIsNotFound) {
  const auto plans = plan_all(shipped("office.json"));
  ASSERT_EQ(plans.size(), 4u);
  EXPECT_TRUE(plans[0].found && plans[1].found && plans[2].found);
  EXPECT_FALSE(plans[3].found);  // starts inside the hollow pillar
}

TEST(VisibilityGraph, CollinearCornersAlongThePath) {
  // Three squares whose corners (1,1) (3,3) (5,5) lie on the line y = x, alternating sides: the
  // shortest path from (0,0) to (6,6) is that line, grazing every corner.
  const CSpace c(world_from(R"({"obstacles": [[[1, 0], [2, 0], [2, 1], [1, 1]], [[2, 3], [3, 3], [3, 4], [2, 4]],
                                              [[5, 4], [6, 4], [6, 5], [5, 5]]]})"));
  VisibilityGraph graph(c);
  const Report plan = graph.plan(between(pt("0", "0"), pt("6", "6")));
  ASSERT_TRUE(plan.found);
  EXPECT_NEAR(plan.length, 6 * std::sqrt(2.0), 1e-12);
  // Blocked line: push the middle square onto the diagonal and the path must bend.
  const CSpace blocked(world_from(R"({"obstacles": [[[2.5, 2.5], [3.5, 2.5], [3.5, 3.5], [2.5, 3.5]]]})"));
  VisibilityGraph bent(blocked);
  const Report around = bent.plan(between(pt("0", "0"), pt("6", "6")));
  ASSERT_TRUE(around.found);
  EXPECT_NEAR(around.length, 2 * std::hypot(3.5, 2.5), 1e-12);
}

TEST(VisibilityGraph, TwoPartRobotMatchesBruteForce) {
  const World world = shipped("seed004.json");
  const CSpace cspace(world);
  VisibilityGraph graph(cspace);
  const Query& q = world.queries.front();
  const Report plan = graph.plan(q);
  const auto expected = brute_force_length(cspace, q.start, q.goal);
  ASSERT_TRUE(plan.found && expected);
  EXPECT_NEAR(plan.length, *expected, 1e-9);
  // The full graph (every visible pair, as courses draw it) finds the same length with more edges.
  VisibilityGraph full(cspace, VisibilityKind::full);
  EXPECT_NEAR(full.plan(q).length, *expected, 1e-9);
  EXPECT_GT(full.plan(q).facts.at(RoadmapFacts::edges), plan.facts.at(RoadmapFacts::edges));
}

TEST(VisibilityGraph, EverySearchFindsAValidPathAndTheOptimalOnesAgree) {
  const World world = shipped("seed004.json");
  const CSpace cspace(world);
  VisibilityGraph graph(cspace);
  const Query& q = world.queries.front();
  const double optimal = graph.plan(q, SearchOptions{Search::astar}).length;
  EXPECT_DOUBLE_EQ(graph.plan(q, SearchOptions{Search::dijkstra}).length, optimal);
  for (Search s : {Search::bfs, Search::dfs, Search::greedy, Search::wastar}) {
    const Report p = graph.plan(q, SearchOptions{s, 2.0});
    ASSERT_TRUE(p.found) << to_string(s);
    EXPECT_GE(p.length, optimal - 1e-9) << to_string(s);  // plan() checked the path exactly
  }
  EXPECT_LE(graph.plan(q, SearchOptions{Search::wastar, 2.0}).length, 2 * optimal);
}

namespace {

// Which side of the directed line a→b the C-obstacle ring turning at its vertex i lies on, from its
// two neighbours: +1 left, −1 right, 0 both (not tangent there).
int ring_side(const Ring& ring, std::size_t i, const ExactPoint& a, const ExactPoint& b) {
  const auto side = [&](const ExactPoint& p) { return sgn((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)); };
  const int s1 = side(ring[(i + ring.size() - 1) % ring.size()]), s2 = side(ring[(i + 1) % ring.size()]);
  if (s1 >= 0 && s2 >= 0 && s1 + s2 > 0) return 1;
  if (s1 <= 0 && s2 <= 0 && s1 + s2 < 0) return -1;
  return 0;
}

// The kind of the sight line a→b between two C-obstacle corners, read off the C-obstacles' rings
// (not the arrangement the planner uses); none where an end is no C-obstacle's vertex.
std::optional<std::string> kind_from_rings(const CSpace& cspace, const ExactPoint& a, const ExactPoint& b) {
  const auto side_at = [&](const ExactPoint& p) -> std::optional<int> {
    for (const PolygonWithHoles& c : cspace.cobstacles()) {
      std::vector<Ring> rings{c.outer};
      rings.insert(rings.end(), c.holes.begin(), c.holes.end());
      for (const Ring& ring : rings)
        for (std::size_t i = 0; i < ring.size(); ++i)
          if (ring[i] == p) return ring_side(ring, i, a, b);
    }
    return std::nullopt;
  };
  const auto here = side_at(a), there = side_at(b);
  if (!here || !there) return std::nullopt;
  if (*here == 0 || *there == 0) return "other";
  return *here == *there ? "supporting" : "separating";
}

}  // namespace

// Two squares side by side: their four sides each (supporting), the two outer bitangents
// (supporting) and the two crossing between them (separating); and on the course's C-space world
// every edge's kind as the C-obstacles' rings tell it.
TEST(VisibilityGraph, EdgesAreSupportingOrSeparatingBitangents) {
  const CSpace squares(world_from(R"({"bounds": [0, 0, 20, 10], "start": [1, 5], "goal": [19, 5],
      "obstacles": [[[4, 3], [7, 3], [7, 6], [4, 6]], [[12, 4], [15, 4], [15, 7], [12, 7]]]})"));
  const Report two = VisibilityGraph(squares).plan(squares.world().queries[0], QueryOptions{.record = true});
  EXPECT_EQ(two.facts.at(RoadmapFacts::supporting_edges), 10);
  EXPECT_EQ(two.facts.at(RoadmapFacts::separating_edges), 2);
  for (const VisibilityKind kind : {VisibilityKind::reduced, VisibilityKind::full}) {
    const World world = shipped("seed004.json");
    const CSpace cspace(world);
    const Report report = VisibilityGraph(cspace, kind).plan(world.queries[0], QueryOptions{.record = true});
    const PlanGraph<ExactPoint>& graph = *report.recording.graph;
    ASSERT_EQ(graph.edge_kinds.size(), graph.edges.size());
    std::size_t compared = 0;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
      const auto expected =
          kind_from_rings(cspace, graph.vertices[graph.edges[e].first], graph.vertices[graph.edges[e].second]);
      if (!expected) continue;  // an end on the bounds
      EXPECT_EQ(graph.edge_kinds[e], *expected) << "edge " << e;
      ++compared;
    }
    EXPECT_GT(compared, graph.edges.size() / 2);
    if (kind == VisibilityKind::reduced) {  // braces: EXPECT_EQ is an if-else of its own
      EXPECT_EQ(std::count(graph.edge_kinds.begin(), graph.edge_kinds.end(), "other"), 0);
    }
  }
}

namespace {

const std::string kBenchmarks = POLYPLAN_SOURCE_DIR "/data/movingai";

struct Outcome {
  std::size_t queries = 0, mismatches = 0;
  double max_difference = 0;
};

// Every `stride`-th query of the map's scenario file, compared with the reference to 1e-9 relative.
Outcome run_map(const std::string& name, std::size_t stride) {
  const GridMap map = read_movingai_map(kBenchmarks + "/maps/" + name + ".map");
  const CSpace cspace(world_from_grid(map));
  VisibilityGraph graph(cspace);
  const auto scenarios = read_scenarios(kBenchmarks + "/scenarios/" + name + ".map.scen");
  const auto reference = read_reference_lengths(kBenchmarks + "/reference/" + name + ".csv", scenarios.size());
  Outcome outcome;
  for (std::size_t i = 0; i < scenarios.size(); i += stride) {
    if (i >= reference.size() || !reference[i]) continue;
    const ScenarioQuery& q = scenarios[i];
    const Report plan = graph.plan(between({q.start_x, q.start_y}, {q.goal_x, q.goal_y}));
    const double expected = *reference[i];
    ++outcome.queries;
    if (plan.found) {  // an independent exact check, on the arrangement rather than the triangulation
      const PathCheck check = check_path(cspace, plan.path);
      EXPECT_TRUE(check.valid) << name << " query " << i << ": " << check.reason;
    }
    if (expected < 0) {
      if (plan.found) ++outcome.mismatches;
      continue;
    }
    const double difference = plan.found ? std::abs(plan.length - expected) : INFINITY;
    outcome.max_difference = std::max(outcome.max_difference, difference);
    if (difference > 1e-9 * std::max(1.0, expected)) {
      ++outcome.mismatches;
      ADD_FAILURE() << name << " query " << i << ": length " << plan.length << " (found " << plan.found
                    << "), reference " << expected;
    }
  }
  return outcome;
}

}  // namespace

TEST(VisibilityGraphOnMovingAi, ArenaMatchesTheReferenceEverywhere) {
  const Outcome o = run_map("arena", 1);
  EXPECT_GE(o.queries, 150u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(VisibilityGraphOnMovingAi, Den312dMatchesTheReferenceEverywhere) {
  const Outcome o = run_map("den312d", 1);
  EXPECT_GE(o.queries, 300u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(VisibilityGraphOnMovingAi, Lak303dSampleMatchesTheReference) {
  const Outcome o = run_map("lak303d", 10);
  EXPECT_GE(o.queries, 100u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(VisibilityGraph, WithoutBoundsAQueryBeyondTheFrameIsFramedAnew) {
  // The world's own query sets the first frame; a query a thousand units away is answered too
  // (it once was "different components": the triangulation's frame did not hold it).
  const CSpace c(world_from(R"({"obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 5], "goal": [9, 5]})"));
  VisibilityGraph graph(c);
  const Report far = graph.plan(between(pt("-1000", "5"), pt("2000", "5")));
  ASSERT_TRUE(far.found) << far.why_not;
  EXPECT_NEAR(far.length, length(pt("-1000", "5"), pt("4", "4")) + 2 + length(pt("6", "4"), pt("2000", "5")), 1e-9);
  const Report near = graph.plan(between(pt("1", "5"), pt("9", "5")));
  ASSERT_TRUE(near.found);
  EXPECT_NEAR(near.length, 2 * std::sqrt(10.0) + 2, 1e-12);
}

// A thin diamond between (0, 0) and (1.02, 0): over the apex (0.51, 0.68) the path is 0.85 + 0.85
// = 1.7, under the other apex 1.6e-16 longer or shorter — the same sum of doubles, so a search in
// doubles takes either. A* and Dijkstra return the exactly shorter; at an exact tie, a shortest.
TEST(VisibilityGraph, PathsThatDoublesTieAreRankedExactly) {
  const auto diamond = [](const char* top, const char* bottom) {
    return world_from(std::string(R"({"bounds": [-0.5, -1, 1.5, 1], "obstacles": [[[0.51, )") + top +
                      "], [0.41, 0], [0.51, -" + bottom + R"(], [0.61, 0]]], "start": [0, 0], "goal": [1.02, 0]})");
  };
  for (const char* search : {"astar", "dijkstra"}) {
    for (const bool top_shorter : {true, false}) {
      const World world = top_shorter ? diamond("0.68", "0.6800000000000001") : diamond("0.6800000000000001", "0.68");
      const CSpace cspace(world);
      SearchOptions options;
      options.algorithm = *search_from_string(search);
      const Report plan = VisibilityGraph(cspace, VisibilityKind::reduced, options).plan(world.queries[0]);
      ASSERT_TRUE(plan.found) << search;
      ASSERT_EQ(plan.path.size(), 3u);
      EXPECT_EQ(sgn(plan.path[1].y), top_shorter ? 1 : -1) << search << ": the exactly shorter side";
      EXPECT_EQ(compare(RootSum::polyline(plan.path), Rational(17, 10)), 0);
    }
    const World tie = diamond("0.68", "0.68");
    const Report plan = VisibilityGraph(CSpace(tie), VisibilityKind::reduced).plan(tie.queries[0]);
    ASSERT_TRUE(plan.found);
    EXPECT_EQ(compare(RootSum::polyline(plan.path), Rational(17, 10)), 0);
  }
}
