// The trapezoid roadmap's paths: hand-computed lengths of both post-processings, the channel's
// shortest path against the exact visibility-graph optimum on random worlds, and the answers
// around pinch points, blocked ends and worlds without bounds.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/roadmaps/roadmap_facts.hpp>
#include <polyplan/roadmaps/trapezoid_planner.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include "movingai_fixtures.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace polyplan;
using polyplan::test::between;
using polyplan::test::pt;
using polyplan::test::world_from;

namespace {

const char* kSquareInABox = R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]]})";

TEST(TrapezoidPlanner, FunnelPathAroundASquareIsTheShortest) {
  const CSpace c(world_from(kSquareInABox));
  TrapezoidPlanner planner(c);
  const auto report = planner.plan(between(pt("1", "5"), pt("9", "5")));
  ASSERT_TRUE(report.found) << report.why_not;
  // Around a corner pair of the square: 2 sqrt(10) + 2, as the visibility graph finds.
  EXPECT_NEAR(report.length, 2 * std::sqrt(10.0) + 2, 1e-12);
  ASSERT_EQ(report.path.size(), 4u);
  EXPECT_EQ(report.path[1].x, 4);
  EXPECT_EQ(report.path[2].x, 6);
  EXPECT_EQ(report.path[1].y, report.path[2].y);  // both below or both above
  EXPECT_EQ(report.facts.at(TrapezoidFacts::cells), 4);
  EXPECT_EQ(report.facts.at(TrapezoidFacts::walls), 4);
  EXPECT_EQ(report.facts.at(RoadmapFacts::vertices), 8);
  EXPECT_EQ(report.facts.at(RoadmapFacts::edges), 8);
  EXPECT_EQ(report.facts.at(TrapezoidFacts::channel_cells), 3);
  EXPECT_EQ(report.facts.at(TrapezoidFacts::sweep_events), 8);
  EXPECT_EQ(report.facts.at(TrapezoidFacts::sweep_most_crossed), 4);
  // The zig-zag: 1 + sqrt(13) + 1 + 1 + sqrt(13) + 1 through (2, 5), a wall midpoint, (5, 2 or 8), ...
  EXPECT_NEAR(report.facts.at(TrapezoidFacts::zigzag_length), 4 + 2 * std::sqrt(13.0), 1e-12);
  EXPECT_NEAR(report.facts.at(TrapezoidFacts::funnel_length), report.length, 1e-12);
  EXPECT_TRUE(report.certificate.certified);
}

TEST(TrapezoidPlanner, ZigzagPathRunsThroughCentroidsAndWallMidpoints) {
  const CSpace c(world_from(kSquareInABox));
  TrapezoidPlanner planner(c, {ChannelPath::zigzag});
  const auto report = planner.plan(between(pt("1", "5"), pt("9", "5")));
  ASSERT_TRUE(report.found);
  EXPECT_NEAR(report.length, 4 + 2 * std::sqrt(13.0), 1e-12);
  // Below or above the square; the centroid (5, 2) or (5, 8) lies on the straight run between the
  // two wall midpoints, so the path does not list it.
  const std::string y = report.path[2].y < 5 ? "2" : "8";
  EXPECT_EQ(report.path,
            (std::vector<ExactPoint>{pt("1", "5"), pt("2", "5"), pt("4", y), pt("6", y), pt("8", "5"), pt("9", "5")}));
  EXPECT_TRUE(check_path(c, report.path).valid);
}

TEST(TrapezoidPlanner, StartAndGoalInOneTrapezoidAreJoinedDirectly) {
  const CSpace c(world_from(kSquareInABox));
  TrapezoidPlanner planner(c, {ChannelPath::zigzag});
  const auto report = planner.plan(between(pt("0.5", "1"), pt("3.5", "9")));
  ASSERT_TRUE(report.found);
  EXPECT_EQ(report.path, (std::vector<ExactPoint>{pt("0.5", "1"), pt("3.5", "9")}));
  EXPECT_EQ(report.facts.at(SearchFacts::expanded), 0);
}

// Two obstacles touching at (5, 5) close a band across the box.
const char* kPinchedBand = R"({"bounds": [0, 0, 10, 10], "obstacles": [
    [[0, 4], [4, 4], [5, 5], [4, 6], [0, 6]], [[10, 4], [10, 6], [6, 6], [5, 5], [6, 4]]]})";

TEST(TrapezoidPlanner, APinchPointIsNoPassage) {
  const CSpace c(world_from(kPinchedBand));
  TrapezoidPlanner planner(c);
  const auto report = planner.plan(between(pt("5", "1"), pt("5", "9")));
  EXPECT_FALSE(report.found);
  EXPECT_EQ(report.why_not, "start and goal lie in different components of the free space");
  EXPECT_TRUE(report.path.empty());
}

TEST(TrapezoidPlanner, FromAPinchPointIntoEitherWedge) {
  const CSpace c(world_from(kPinchedBand));
  TrapezoidPlanner planner(c);
  for (const char* goal_y : {"9", "1"}) {
    const auto report = planner.plan(between(pt("5", "5"), pt("2", goal_y)));
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_TRUE(check_path(c, report.path).valid);
  }
}

TEST(TrapezoidPlanner, ABlockedStartIsAnAnswerNamingTheObstacle) {
  const CSpace c(world_from(kSquareInABox));
  TrapezoidPlanner planner(c);
  const auto report = planner.plan(between(pt("5", "5"), pt("9", "5")));
  EXPECT_FALSE(report.found);
  EXPECT_NE(report.why_not.find("obstacles[0]"), std::string::npos) << report.why_not;
}

TEST(TrapezoidPlanner, WithoutBoundsAQueryBeyondTheFrameIsFramedAnew) {
  const CSpace c(world_from(R"({"obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "start": [1, 5], "goal": [9, 5]})"));
  TrapezoidPlanner planner(c);
  VisibilityGraph optimum(c);
  const auto near = planner.plan(between(pt("1", "5"), pt("9", "5")));
  ASSERT_TRUE(near.found) << near.why_not;
  EXPECT_NEAR(near.length, 2 * std::sqrt(10.0) + 2, 1e-12);
  const Query far = between(pt("-1000", "5.5"), pt("2000", "4.5"));
  const auto report = planner.plan(far);
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_TRUE(check_path(c, report.path).valid);
  const auto best = optimum.plan(far);
  ASSERT_TRUE(best.found) << best.why_not;
  // The channel the search found passes the square on one side; the optimum may take the other.
  EXPECT_GE(report.length, best.length - 1e-9);
  EXPECT_LT(report.length, best.length + 0.01);
}

// A world of random triangles with decimal corners (one to three decimals) in a 10 x 10 box.
std::string random_world(std::mt19937& rng) {
  std::uniform_int_distribution<int> coordinate(0, 1000);
  std::ostringstream json;
  json << R"({"bounds": [0, 0, 10, 10], "obstacles": [)";
  for (int t = 0; t < 8; ++t) {
    const int cx = coordinate(rng), cy = coordinate(rng);
    json << (t ? ", " : "") << "[";
    for (int k = 0; k < 3; ++k) {
      std::uniform_int_distribution<int> offset(-150, 150);
      const int x = std::clamp(cx + offset(rng), 0, 1000), y = std::clamp(cy + offset(rng), 0, 1000);
      json << (k ? ", " : "") << "[" << x / 100.0 << ", " << y / 100.0 << "]";
    }
    json << "]";
  }
  json << "]}";
  return json.str();
}

TEST(TrapezoidPlanner, OnRandomWorldsTheChannelPathIsValidAndBetweenTheOptimumAndTheZigzag) {
  std::mt19937 rng(20261201);
  std::uniform_int_distribution<int> coordinate(0, 1000);
  int answered = 0, found = 0;
  for (int w = 0; w < 40; ++w) {
    std::optional<World> world;
    try {
      world = world_from(random_world(rng));
    } catch (const InputError&) {
      continue;  // a degenerate triangle
    }
    const CSpace c(*world);
    TrapezoidPlanner planner(c);
    TrapezoidPlanner uniform_cost(c, {ChannelPath::funnel, {Search::dijkstra}});
    VisibilityGraph optimum(c);
    for (int q = 0; q < 6; ++q) {
      const Query query = between({Rational(coordinate(rng)) / 100, Rational(coordinate(rng)) / 100},
                                  {Rational(coordinate(rng)) / 100, Rational(coordinate(rng)) / 100});
      if (c.query_not_free(query)) continue;
      ++answered;
      const auto report = planner.plan(query);
      const auto best = optimum.plan(query);
      ASSERT_EQ(report.found, best.found) << report.why_not;
      if (!report.found) continue;
      ++found;
      EXPECT_TRUE(check_path(c, report.path).valid);
      EXPECT_GE(report.length, best.length - 1e-9);
      EXPECT_LE(report.length, report.facts.at(TrapezoidFacts::zigzag_length) + 1e-9);
      // A* finds the shortest zig-zag on the roadmap, as Dijkstra does (an admissible heuristic
      // and true edge lengths from the query's own start and goal).
      EXPECT_NEAR(report.facts.at(TrapezoidFacts::zigzag_length),
                  uniform_cost.plan(query).facts.at(TrapezoidFacts::zigzag_length), 1e-9);
    }
  }
  EXPECT_GT(answered, 100);
  EXPECT_GT(found, 80);
}

// The shortest zig-zag on the roadmap by a plain O(V^2) Dijkstra over the planner's own roadmap,
// start and goal joined to the centroids of the cells around them.
double shortest_zigzag(const TrapezoidPlanner& planner, const ExactPoint& start, const ExactPoint& goal) {
  const Roadmap& g = planner.roadmap();
  const std::size_t corners = boost::num_vertices(g) - 2, source = corners, target = corners + 1;
  std::vector<std::vector<std::pair<std::size_t, double>>> next(corners + 2);
  auto distance = [](const ExactPoint& a, const ExactPoint& b) {
    return std::hypot(to_double(a.x) - to_double(b.x), to_double(a.y) - to_double(b.y));
  };
  for (auto [e, end] = boost::edges(g); e != end; ++e) {
    const std::size_t u = boost::source(*e, g), v = boost::target(*e, g);
    if (u >= corners || v >= corners) continue;
    next[u].push_back({v, distance(g[u].exact, g[v].exact)});
    next[v].push_back({u, distance(g[u].exact, g[v].exact)});
  }
  for (std::size_t c : planner.decomposition().cells_at(start))
    next[source].push_back({c, distance(start, g[c].exact)});
  for (std::size_t c : planner.decomposition().cells_at(goal)) next[c].push_back({target, distance(g[c].exact, goal)});
  std::vector<double> best(corners + 2, INFINITY);
  std::vector<bool> done(corners + 2, false);
  best[source] = 0;
  for (;;) {
    std::size_t u = corners + 2;
    for (std::size_t v = 0; v < corners + 2; ++v)
      if (!done[v] && best[v] < INFINITY && (u == corners + 2 || best[v] < best[u])) u = v;
    if (u == corners + 2) return INFINITY;
    if (u == target) return best[u];
    done[u] = true;
    for (const auto& [v, w] : next[u]) best[v] = std::min(best[v], best[u] + w);
  }
}

TEST(TrapezoidPlanner, TheZigzagIsTheShortestPathOnTheRoadmapFromStartsOnWallsAndCorners) {
  // Starts and goals on walls and at wall ends touch two or more cells: the search must weigh
  // the joins to each from the query's own points (they once were measured from the origin).
  std::mt19937 rng(7);
  int compared = 0;
  for (int w = 0; w < 20; ++w) {
    std::optional<World> world;
    try {
      world = world_from(random_world(rng));
    } catch (const InputError&) {
      continue;
    }
    const CSpace c(*world);
    TrapezoidPlanner planner(c, {ChannelPath::zigzag});
    const auto& walls = planner.decomposition().walls();
    if (walls.size() < 2) continue;
    std::uniform_int_distribution<std::size_t> pick(0, walls.size() - 1);
    for (int q = 0; q < 10; ++q) {
      const TrapezoidWall &a = walls[pick(rng)], &b = walls[pick(rng)];
      const ExactPoint start{a.lower.x, (a.lower.y + 3 * a.upper.y) / 4}, goal = q % 2 ? b.lower : b.upper;
      if (c.query_not_free(between(start, goal))) continue;
      const auto report = planner.plan(between(start, goal));
      const double expected = shortest_zigzag(planner, start, goal);
      ASSERT_EQ(report.found, expected < INFINITY) << report.why_not;
      if (!report.found || report.facts.at(SearchFacts::expanded) == 0) continue;
      ++compared;
      EXPECT_NEAR(report.facts.at(TrapezoidFacts::zigzag_length), expected, 1e-9);
    }
  }
  EXPECT_GT(compared, 60);
}

TEST(TrapezoidPlannerOnMovingAi, ArenaAnswersEveryScenario) {
  test::expect_answers_to_the_scenarios<TrapezoidPlanner>("arena", 1, 150);
}
TEST(TrapezoidPlannerOnMovingAi, Den312dAnswersEveryScenario) {
  test::expect_answers_to_the_scenarios<TrapezoidPlanner>("den312d", 1, 300);
}
TEST(TrapezoidPlannerOnMovingAi, Lak303dAnswersASample) {
  test::expect_answers_to_the_scenarios<TrapezoidPlanner>("lak303d", 10, 100);
}

}  // namespace
