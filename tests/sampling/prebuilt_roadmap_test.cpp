// prm and lazyprm with roadmap-size N in polygon worlds: the K-PRM of N free samples built before
// any query, the same for one seed, every edge re-certified by the C-space's exact segment test
// (not the triangulation walk the planners use), its components counted again here, queries
// answered on it without growing it, and not_found naming the components of an unjoined query.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <numeric>
#include <string>

namespace polyplan {
namespace {

std::unique_ptr<Planner<TranslatingRobot>> roadmap_planner(const std::string& name, const CSpace& cspace,
                                                           const OptionValues& options) {
  return planners<TranslatingRobot>().find(name)->make(cspace, options);
}

// The goal in the hole of a square ring: free, but no motion reaches it from the start.
World ring_of_two_regions() {
  return test::world_from(R"({"bounds": [0, 0, 10, 10],
      "obstacles": [{"outer": [[6, 6], [9, 6], [9, 9], [6, 9]], "holes": [[[7, 7], [7, 8], [8, 8], [8, 7]]]}],
      "queries": [{"start": [1, 1], "goal": [9.5, 9.5]},
                  {"start": [1, 1], "goal": [7.5, 7.5]}]})");
}

// The components of a graph of `vertices` vertices, counted by union-find over its edges.
std::size_t components_counted(std::size_t vertices, const std::vector<std::pair<std::size_t, std::size_t>>& edges) {
  std::vector<std::size_t> parent(vertices);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v];
    return v;
  };
  std::size_t count = vertices;
  for (const auto& [a, b] : edges)
    if (root(a) != root(b)) parent[root(a)] = root(b), --count;
  return count;
}

// The roadmap alone from a query's picture: its first `samples` vertices and the edges among them.
std::vector<std::pair<std::size_t, std::size_t>> roadmap_edges(const PlanGraph<ExactPoint>& graph,
                                                               std::size_t samples) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& [a, b] : graph.edges)
    if (a < samples && b < samples) edges.emplace_back(a, b);
  return edges;
}

TEST(PrebuiltRoadmap, BuildsNSamplesWithCertifiedEdgesCountedComponentsAndOneRoadmapPerSeed) {
  const World world = ring_of_two_regions();
  const CSpace cspace(world);
  for (const char* name : {"prm", "lazyprm"}) {
    SCOPED_TRACE(name);
    const OptionValues options{{"roadmap-size", "150"}, {"k", "6"}, {"seed", "4"}};
    const auto report = roadmap_planner(name, cspace, options)->plan(world.queries[0], {true});
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.facts.at(SamplingFacts::roadmap_samples), 150);
    EXPECT_EQ(report.facts.at(RoadmapFacts::vertices), 150);
    EXPECT_EQ(report.facts.at(SamplingFacts::samples), 0);  // the query draws nothing
    const auto& graph = *report.recording.graph;
    ASSERT_EQ(graph.vertices.size(), 152u);  // the roadmap, then the query's start and goal
    const auto edges = roadmap_edges(graph, 150);
    EXPECT_EQ(static_cast<std::int64_t>(edges.size()), report.facts.at(RoadmapFacts::edges));
    EXPECT_LE(edges.size(), 150u * 6);
    for (const auto& [a, b] : edges) {
      const PathCheck check = check_segment(cspace, graph.vertices[a], graph.vertices[b]);
      EXPECT_TRUE(check.valid) << check.reason;
    }
    const std::int64_t counted = static_cast<std::int64_t>(components_counted(150, edges));
    EXPECT_EQ(report.facts.at(SamplingFacts::roadmap_components), counted);
    EXPECT_GE(counted, 1);
    // One seed, one roadmap: another planner of the same options builds the very same one.
    const auto again = roadmap_planner(name, cspace, options)->plan(world.queries[0], {true});
    EXPECT_EQ(again.recording.graph->vertices, graph.vertices);
    EXPECT_EQ(again.recording.graph->edges, graph.edges);
    EXPECT_EQ(again.path, report.path);
  }
}

TEST(PrebuiltRoadmap, MoreNeighboursJoinTheSameSamplesIntoNoMoreComponents) {
  const World world = ring_of_two_regions();
  const CSpace cspace(world);
  std::int64_t previous = std::numeric_limits<std::int64_t>::max();
  std::vector<ExactPoint> samples;
  for (const char* k : {"1", "3", "10"}) {
    SCOPED_TRACE(k);
    const auto report = roadmap_planner("prm", cspace, {{"roadmap-size", "100"}, {"k", k}, {"seed", "2"}})
                            ->plan(world.queries[0], {true});
    const std::int64_t now = report.facts.at(SamplingFacts::roadmap_components);
    EXPECT_LE(now, previous);
    previous = now;
    const std::vector<ExactPoint> these(report.recording.graph->vertices.begin(),
                                        report.recording.graph->vertices.begin() + 100);
    if (!samples.empty()) EXPECT_EQ(these, samples);  // K changes the edges, not the samples
    samples = these;
  }
  // k = 1 joins each sample to one earlier sample at most: a forest, whose edges and components
  // add up to its samples.
  const auto one =
      roadmap_planner("prm", cspace, {{"roadmap-size", "100"}, {"k", "1"}, {"seed", "2"}})->plan(world.queries[0]);
  EXPECT_EQ(one.facts.at(RoadmapFacts::edges) + one.facts.at(SamplingFacts::roadmap_components), 100);
}

TEST(PrebuiltRoadmap, QueriesDoNotGrowTheRoadmapAndAnUnjoinedOneIsNotFoundNamingComponents) {
  const World world = ring_of_two_regions();
  const CSpace cspace(world);
  for (const char* name : {"prm", "lazyprm"}) {
    SCOPED_TRACE(name);
    auto planner = roadmap_planner(name, cspace, {{"roadmap-size", "300"}, {"k", "8"}, {"seed", "1"}});
    const auto inside = planner->plan(world.queries[1]);
    EXPECT_FALSE(inside.found);
    EXPECT_EQ(inside.status, PlanStatus::not_found);
    EXPECT_NE(inside.why_not.find("does not join start and goal: start in component"), std::string::npos)
        << inside.why_not;
    const auto outside = planner->plan(world.queries[0]);
    ASSERT_TRUE(outside.found) << outside.why_not;
    EXPECT_EQ(outside.facts.at(RoadmapFacts::vertices), 300);
    EXPECT_EQ(outside.facts.at(RoadmapFacts::edges), inside.facts.at(RoadmapFacts::edges));
    const PathCheck check = check_path(cspace, outside.path);
    EXPECT_TRUE(check.valid) << check.reason;
    // Asked again after another query, the same path before shortcutting (which draws from each
    // query's own stream): nothing of the queries before stayed in the roadmap.
    EXPECT_EQ(planner->plan(world.queries[0]).facts.at(SamplingFacts::raw_length),
              outside.facts.at(SamplingFacts::raw_length));
  }
}

TEST(PrebuiltRoadmap, WithoutRoadmapSizeAQueryStillGrowsTheRoadmap) {
  const World world = ring_of_two_regions();
  const CSpace cspace(world);
  const auto report = roadmap_planner("prm", cspace, {{"seed", "1"}})->plan(world.queries[0]);
  ASSERT_TRUE(report.found);
  EXPECT_FALSE(report.facts.find(SamplingFacts::roadmap_samples));
  EXPECT_GT(report.facts.at(SamplingFacts::samples), 0);
}

}  // namespace
}  // namespace polyplan
