// The sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) in polygon worlds: paths re-checked
// exactly on every shipped world with three seeds, one seed one path, RRT* converging to the
// visibility graph's optimum, the limits and their answers, the options' errors. The conformance
// test (registry_test.cpp) runs them with their defaults as well.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/polyline.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include <polyplan/sampling/sampling_planner.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

namespace polyplan {
namespace {

constexpr std::array<const char*, 5> sampling_planners{"prm", "lazyprm", "rrt", "rrtstar", "rrtconnect"};

World shipped_world(const std::string& name) {
  return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json");
}

std::unique_ptr<Planner<TranslatingRobot>> make(const std::string& name, const CSpace& cspace, OptionValues options) {
  const auto* entry = planners<TranslatingRobot>().find(name);
  if (!entry) throw std::logic_error("no planner " + name);
  return entry->make(cspace, options);
}

// Every query of worlds whose passages are wide enough to sample (decimal.json's 1e-17 slit and
// corridor_wide's 1e-9 corridor are not): found where the exact shortest path is, with a path that
// is checked exactly and no shorter than it; not found where it is not (office's room without a door).
class SamplingPlannerOnWorld : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(SamplingPlannerOnWorld, ThreeSeedsGiveExactlyCheckedPathsAndOneSeedOnePath) {
  const auto& [planner, world_name] = GetParam();
  const World world = shipped_world(world_name);
  const CSpace cspace(world);
  VisibilityGraph optimum(cspace);
  for (const std::string seed : {"1", "2", "3"}) {
    SCOPED_TRACE("seed " + seed);
    // RRT* is anytime and stops at its time limit by default: an iteration limit makes its runs
    // repeatable.
    OptionValues options{{"seed", seed}, {"time", "20"}};
    if (planner == "rrtstar") options.emplace_back("iterations", "20000");
    auto planner_of_seed = make(planner, cspace, options);
    // The first four queries (sphere_world_polygons has ten), to keep it quick.
    for (std::size_t i = 0; i < std::min<std::size_t>(4, world.queries.size()); ++i) {
      const Query& q = world.queries[i];
      SCOPED_TRACE(q.name);
      const auto best = optimum.plan(q);
      if (!best.found) {
        const auto none = make(planner, cspace, {{"seed", seed}, {"iterations", "500"}})->plan(q);
        EXPECT_FALSE(none.found);
        EXPECT_FALSE(none.why_not.empty());
        continue;
      }
      const auto report = planner_of_seed->plan(q);
      ASSERT_TRUE(report.found) << report.why_not;
      EXPECT_EQ(report.path.front(), q.start);
      EXPECT_EQ(report.path.back(), q.goal);
      const PathCheck check = check_path(cspace, report.path);
      EXPECT_TRUE(check.valid) << check.reason;
      EXPECT_NEAR(report.length, euclidean_length(report.path), 1e-9 * report.length);
      EXPECT_GE(report.length, best.length * (1 - 1e-12));
      EXPECT_LE(report.length, report.facts.at(SamplingFacts::raw_length) * (1 + 1e-12));  // shortcuts never lengthen
      EXPECT_GT(report.facts.at(SamplingFacts::motions_checked), 0);
      EXPECT_EQ(report.facts.at(QueryFacts::stopped_by),
                planner == "rrtstar" ? "iteration limit" : "solution");  // RRT* is anytime
      EXPECT_GE(report.facts.at(SamplingFacts::first_solution_seconds), 0);
      // The same seed, a planner of its own, the same first query: the same path.
      if (i == 0) {  // braces: EXPECT_EQ is an if-else of its own
        EXPECT_EQ(make(planner, cspace, options)->plan(q).path, report.path);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SamplingPlanners, SamplingPlannerOnWorld,
                         ::testing::Combine(::testing::ValuesIn(std::vector<std::string>(sampling_planners.begin(),
                                                                                         sampling_planners.end())),
                                            ::testing::ValuesIn(std::vector<std::string>{"maze", "office", "seed004",
                                                                                         "sphere_world_polygons",
                                                                                         "corridor_exact"})),
                         [](const auto& info) { return std::get<0>(info.param) + "_on_" + std::get<1>(info.param); });

TEST(SamplingPlanners, DifferentSeedsSampleDifferently) {
  const World world = shipped_world("maze");
  const CSpace cspace(world);
  const auto one = make("rrt", cspace, {{"seed", "1"}, {"shortcut", "false"}})->plan(world.queries[0]);
  const auto two = make("rrt", cspace, {{"seed", "2"}, {"shortcut", "false"}})->plan(world.queries[0]);
  ASSERT_TRUE(one.found && two.found);
  EXPECT_NE(one.path, two.path);
}

// Each query draws its own random stream, fixed by the seed and the query's ordinal: a tree
// planner's second answer is the same whatever its first query drew (a query cut by a time limit
// draws as many numbers as the machine's speed allows), and differs from a first query's answer.
TEST(SamplingPlanners, EachQueryDrawsItsOwnRandomStream) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  ASSERT_GE(world.queries.size(), 3u);
  for (const char* name : {"rrt", "rrtconnect"}) {  // RRT* draws for its whole iteration limit, whatever the query
    SCOPED_TRACE(name);
    const OptionValues options{{"shortcut", "false"}, {"time", "20"}};
    auto after_one = make(name, cspace, options), after_other = make(name, cspace, options);
    ASSERT_NE(after_one->plan(world.queries[0]).facts.at(SamplingFacts::samples),
              after_other->plan(world.queries[2]).facts.at(SamplingFacts::samples));
    const auto second = after_one->plan(world.queries[1]), second_too = after_other->plan(world.queries[1]);
    ASSERT_TRUE(second.found);
    EXPECT_EQ(second.path, second_too.path);
    const auto first = make(name, cspace, options)->plan(world.queries[1]);
    ASSERT_TRUE(first.found);
    EXPECT_NE(first.path, second.path);
  }
}

// RRT* without shortcuts: the path's cost never grows with more iterations of one seed (the first
// iterations are the same), and reaches within 10% of the exact optimum.
TEST(SamplingPlanners, RrtStarConvergesTowardTheVisibilityGraphOptimum) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  const Query& q = world.queries[0];
  const double optimum = VisibilityGraph(cspace).plan(q).length;
  double previous = std::numeric_limits<double>::infinity();
  for (const std::string iterations : {"2000", "8000", "32000"}) {
    const auto report =
        make("rrtstar", cspace, {{"iterations", iterations}, {"shortcut", "false"}, {"time", "60"}})->plan(q);
    ASSERT_TRUE(report.found) << report.why_not;
    SCOPED_TRACE(iterations + " iterations: " + std::to_string(report.length) + " against " + std::to_string(optimum));
    EXPECT_LE(report.length, previous);
    EXPECT_EQ(report.length, report.facts.at(SamplingFacts::raw_length));
    EXPECT_GE(report.length, optimum * (1 - 1e-12));
    previous = report.length;
  }
  EXPECT_LE(previous, 1.10 * optimum);
}

TEST(SamplingPlanners, RrtStarImprovesAsItRuns) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  auto planner = make("rrtstar", cspace, {{"iterations", "4000"}, {"shortcut", "false"}});
  const auto report = planner->plan(world.queries[0]);
  ASSERT_TRUE(report.found);
  const auto& improvements = dynamic_cast<const SamplingPlanner<TranslatingRobot>&>(*planner).improvements();
  ASSERT_GE(improvements.size(), 2u);
  EXPECT_EQ(static_cast<std::int64_t>(improvements.size()), report.facts.at(SamplingFacts::solutions));
  for (std::size_t i = 1; i < improvements.size(); ++i) {
    EXPECT_LT(improvements[i].length, improvements[i - 1].length);
    EXPECT_GE(improvements[i].seconds, improvements[i - 1].seconds);
  }
  EXPECT_EQ(improvements.back().length, report.length);
  EXPECT_EQ(improvements.front().seconds, report.facts.at(SamplingFacts::first_solution_seconds));
}

// The time limit bounds the whole query, shortcutting and the path's certification included
// (bench/time_limit_table.cpp measures every planner to within 20 ms; a loose bound here, one run,
// looser still under AddressSanitizer, whose every step is several times slower, beside another test).
#if defined(__SANITIZE_ADDRESS__)
constexpr double kLooseOvershoot = 1.0;
#else
constexpr double kLooseOvershoot = 0.25;
#endif

TEST(SamplingPlanners, RrtStarEndsAtItsTimeLimit) {
  const World world = shipped_world("maze");
  const CSpace cspace(world);
  const auto report = make("rrtstar", cspace, {{"time", "0.5"}, {"iterations", "100000000"}})->plan(world.queries[0]);
  ASSERT_TRUE(report.found);
  EXPECT_EQ(report.facts.at(QueryFacts::stopped_by), "time limit");
  EXPECT_GE(report.facts.at(QueryFacts::seconds), 0.5);
  EXPECT_LE(report.facts.at(QueryFacts::seconds), 0.5 + kLooseOvershoot);
}

// The report carries the solutions as found, the shortcut path last: what a benchmark's
// cost-over-time curve reads (PlanReport::improvements).
TEST(SamplingPlanners, ReportsItsImprovementsEndingAtTheReturnedLength) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  const std::vector<std::pair<std::string, OptionValues>> runs{{"rrt", {}},
                                                               {"rrtstar", {{"iterations", "3000"}, {"k", "3"}}}};
  for (const auto& [name, options] : runs) {
    const auto report = make(name, cspace, options)->plan(world.queries[0]);
    ASSERT_TRUE(report.found) << name;
    ASSERT_FALSE(report.improvements.empty()) << name;
    EXPECT_EQ(report.improvements.back().length, report.length) << name;  // the shortcut path, when shorter
    EXPECT_EQ(report.improvements.front().seconds, report.facts.at(SamplingFacts::first_solution_seconds)) << name;
    for (std::size_t i = 1; i < report.improvements.size(); ++i) {
      EXPECT_LT(report.improvements[i].length, report.improvements[i - 1].length) << name;
      EXPECT_GE(report.improvements[i].seconds, report.improvements[i - 1].seconds) << name;
    }
  }
  EXPECT_TRUE(planners<TranslatingRobot>().find("rrtstar")->anytime);
  EXPECT_FALSE(planners<TranslatingRobot>().find("rrt")->anytime);
}

// A goal walled in: every planner stops at its limit and says which.
TEST(SamplingPlanners, AnUnreachableGoalEndsAtTheLimitWithTheReason) {
  // The goal in the hole of a square ring.
  const World walled = test::world_from(R"({"bounds": [0, 0, 10, 10],
      "obstacles": [{"outer": [[6, 6], [9, 6], [9, 9], [6, 9]], "holes": [[[7, 7], [7, 8], [8, 8], [8, 7]]]}],
      "start": [1, 1], "goal": [7.5, 7.5]})");
  const CSpace cspace(walled);
  for (const char* name : sampling_planners) {
    SCOPED_TRACE(name);
    const auto by_count = make(name, cspace, {{"iterations", "300"}})->plan(walled.queries[0]);
    EXPECT_FALSE(by_count.found);
    EXPECT_NE(by_count.why_not.find("the iteration limit (300)"), std::string::npos) << by_count.why_not;
    EXPECT_EQ(by_count.facts.at(QueryFacts::stopped_by), "iteration limit");
    EXPECT_TRUE(by_count.path.empty());
    const auto by_time = make(name, cspace, {{"iterations", "100000000"}, {"time", "0.2"}})->plan(walled.queries[0]);
    EXPECT_FALSE(by_time.found);
    EXPECT_NE(by_time.why_not.find("the time limit (0.2 s)"), std::string::npos) << by_time.why_not;
    EXPECT_EQ(by_time.facts.at(QueryFacts::stopped_by), "time limit");
  }
}

TEST(SamplingPlanners, AStartInAnObstacleIsAnAnswerNamingIt) {
  const World world = test::world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
      "start": [5, 5], "goal": [9, 9]})");
  const CSpace cspace(world);
  for (const char* name : sampling_planners) {
    const auto report = make(name, cspace, {})->plan(world.queries[0]);
    EXPECT_FALSE(report.found);
    EXPECT_EQ(report.why_not, "the start [5, 5] is not free: it is inside obstacles[0]") << name;
  }
}

TEST(SamplingPlanners, StartAtTheGoalIsATwoConfigurationPath) {
  const World world =
      test::world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [], "start": ["1/3", 2], "goal": ["1/3", 2]})");
  const CSpace cspace(world);
  for (const char* name : sampling_planners) {
    const auto report = make(name, cspace, {})->plan(world.queries[0]);
    ASSERT_TRUE(report.found) << name << ": " << report.why_not;
    EXPECT_EQ(report.length, 0) << name;
    EXPECT_EQ(report.path.front(), world.queries[0].start) << name;
  }
}

// Exact start and goal that no double represents stay exact in the path.
TEST(SamplingPlanners, ExactEndsThatNoDoubleRepresentsStayExact) {
  const World world = test::world_from(R"({"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [5, 0], [5, 8], [4, 8]]],
      "start": ["1/3", "1/7"], "goal": ["29/3", "2/7"]})");
  const CSpace cspace(world);
  for (const char* name : sampling_planners) {
    const auto report = make(name, cspace, {})->plan(world.queries[0]);
    ASSERT_TRUE(report.found) << name;
    EXPECT_EQ(report.path.front(), test::pt("1/3", "1/7")) << name;
    EXPECT_EQ(report.path.back(), test::pt("29/3", "2/7")) << name;
    EXPECT_TRUE(check_path(cspace, report.path).valid) << name;
  }
}

TEST(SamplingPlanners, TheirOptionsAreListedAndBadValuesNamed) {
  const auto names = [](const char* planner) {
    std::vector<std::string> out;
    for (const OptionInfo& o : planners<TranslatingRobot>().find(planner)->options) out.push_back(o.name);
    return out;
  };
  const std::vector<std::string> limits{"seed", "time", "iterations", "shortcut"};
  const auto with_limits = [&](std::vector<std::string> own) {
    own.insert(own.end(), limits.begin(), limits.end());
    return own;
  };
  EXPECT_EQ(names("rrt"), with_limits({"goal-bias", "step", "extend"}));
  EXPECT_EQ(names("rrtstar"), with_limits({"rewire", "k", "goal-bias", "step", "extend"}));
  EXPECT_EQ(names("rrtconnect"), with_limits({"step"}));
  EXPECT_EQ(names("prm"), with_limits({"k", "search", "weight", "reopen", "bidirectional", "roadmap-size"}));
  EXPECT_EQ(names("lazyprm"), with_limits({"k", "roadmap-size"}));

  const World world = shipped_world("maze");
  const CSpace cspace(world);
  const auto error = [&](const char* planner, OptionValues options) {
    return test::input_error_of([&] { make(planner, cspace, options); });
  };
  EXPECT_EQ(error("rrt", {{"goal-bias", "1.5"}}), "planner rrt: option goal-bias=1.5: expected a number in [0, 1]");
  EXPECT_EQ(error("rrt", {{"extend", "e3"}}), "planner rrt: option extend=e3: expected one of e1|e2");
  EXPECT_EQ(error("rrtconnect", {{"step", "-1"}}), "planner rrtconnect: option step=-1: expected a number in [0, inf)");
  EXPECT_EQ(error("prm", {{"time", "0"}}), "planner prm: option time=0: expected a number in (0, inf)");
  EXPECT_EQ(error("lazyprm", {{"iterations", "0"}}),
            "planner lazyprm: option iterations=0: expected a whole number in [1, inf)");
  EXPECT_EQ(error("rrtstar", {{"rewire", "all"}}), "planner rrtstar: option rewire=all: expected one of k|radius");
  EXPECT_EQ(error("rrt", {{"seed", "-1"}}), "planner rrt: option seed=-1: expected a whole number >= 0");
}

// E1 reaches each sample in one motion; E2 takes steps of at most `step`, so every tree edge is
// that short.
TEST(SamplingPlanners, ExtensionE2StepsAtMostTheStepAndE1GoesToTheSample) {
  const World world = shipped_world("maze");
  const CSpace cspace(world);
  const Query& q = world.queries[0];
  const auto e2 = make("rrt", cspace, {{"step", "0.5"}, {"shortcut", "false"}})->plan(q, QueryOptions{true});
  ASSERT_TRUE(e2.found && e2.recording.graph);
  for (const auto& [u, v] : e2.recording.graph->edges)
    EXPECT_LE(euclidean_length({e2.recording.graph->vertices[u], e2.recording.graph->vertices[v]}), 0.5 * (1 + 1e-12));
  for (std::size_t i = 0; i + 1 < e2.path.size(); ++i)
    EXPECT_LE(euclidean_length({e2.path[i], e2.path[i + 1]}), 0.5 * (1 + 1e-12));
  const auto e1 = make("rrt", cspace, {{"extend", "e1"}, {"shortcut", "false"}})->plan(q, QueryOptions{true});
  ASSERT_TRUE(e1.found) << e1.why_not;
  EXPECT_EQ(e1.recording.graph->kind, "tree");
  EXPECT_EQ(e1.recording.graph->vertices.size(), static_cast<std::size_t>(e1.facts.at(SamplingFacts::tree_size)));
}

TEST(SamplingPlanners, PrmKeepsItsRoadmapAcrossQueries) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  auto planner = make("prm", cspace, {});
  const auto first = planner->plan(world.queries[0]);
  const auto again = planner->plan(world.queries[0]);
  ASSERT_TRUE(first.found && again.found);
  EXPECT_GE(again.facts.at(RoadmapFacts::vertices), first.facts.at(RoadmapFacts::vertices) + 2);
  EXPECT_LT(again.facts.at(SamplingFacts::samples), first.facts.at(SamplingFacts::samples));
  EXPECT_EQ(again.facts.at(SamplingFacts::samples), 0);  // joined at once through the roadmap kept
}

// One seed, one roadmap: bidirectional Dijkstra finds the cost Dijkstra finds (in the maze it
// settles more milestones: the goal's side of the maze is the larger one).
TEST(SamplingPlanners, PrmSearchesBothWaysForTheSameCost) {
  const World world = shipped_world("maze");
  const CSpace cspace(world);
  const auto one_way = make("prm", cspace, {{"search", "dijkstra"}, {"shortcut", "false"}})->plan(world.queries[0]);
  const auto both_ways =
      make("prm", cspace, {{"bidirectional", "true"}, {"shortcut", "false"}})->plan(world.queries[0]);
  ASSERT_TRUE(one_way.found && both_ways.found);
  EXPECT_NEAR(both_ways.length, one_way.length, 1e-9 * one_way.length);
  EXPECT_EQ(both_ways.facts.at(SearchFacts::algorithm), "bidirectional dijkstra");
  EXPECT_GT(both_ways.facts.at(SearchFacts::expanded), 0);
}

TEST(SamplingPlanners, LazyPrmChecksFewerMotionsThanPrm) {
  const World world = shipped_world("office");
  const CSpace cspace(world);
  const auto lazy = make("lazyprm", cspace, {})->plan(world.queries[0]);
  const auto eager = make("prm", cspace, {})->plan(world.queries[0]);
  ASSERT_TRUE(lazy.found && eager.found);
  EXPECT_LT(lazy.facts.at(SamplingFacts::motions_checked), eager.facts.at(SamplingFacts::motions_checked));
}

// touching_corners: two free squares that meet only at the pinch point (2, 2). A roadmap kept
// across queries holds the earlier queries' ends, so after (1,1)→(2,2) and (3,3)→(2,2) the pinch
// point is a milestone of both squares; each motion onto it and off it is certified, but the path
// (1,1)→(2,2)→(3,3) crosses a zero-width place. Every planner must answer that query without a
// path (the open free spaces of the two squares are not joined), and every path it does return
// must pass the exact whole-path check.
TEST(SamplingPlanners, NoPathThroughAPinchPointMilestone) {
  const CSpace cspace(shipped_world("touching_corners"));
  const Query into_a{{1, 1}, {2, 2}, "into the pinch from below"}, into_b{{3, 3}, {2, 2}, "into the pinch from above"};
  const Query across{{1, 1}, {3, 3}, "across the pinch"};
  for (const char* name : sampling_planners) {
    SCOPED_TRACE(name);
    auto planner = make(name, cspace, {{"seed", "1"}, {"iterations", "3000"}, {"time", "20"}});
    for (const Query* q : {&into_a, &into_b, &across}) {
      const auto report = planner->plan(*q);
      if (report.found) {
        EXPECT_TRUE(check_path(cspace, report.path).valid) << q->name;
      }
      if (q == &across) {
        EXPECT_FALSE(report.found);
        EXPECT_NE(report.status, PlanStatus::solved);
      }
    }
  }
}

}  // namespace
}  // namespace polyplan
