// The arm homework's K-PRM: prm with roadmap-size N builds its roadmap of N free samples before any
// query, the same one for one seed, the same samples whatever K (only the edges differ), every edge
// free by an independent check (the collision checker every 0.1° along it), and every query of the
// file answered on that one roadmap.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/sampling_facts.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polyplan {
namespace {

constexpr double tenth_degree = test::kPi / 1800;

ArmProblem two_link_points() { return read_arm_problem(test::arm_data_file("two_link_points.json")); }

PlanReport<JointAngles> first_query(const ArmProblem& problem, const std::string& k) {
  return planners<PlanarArm>()
      .find("prm")
      ->make(problem, {{"roadmap-size", "120"}, {"k", k}, {"seed", "7"}})
      ->plan(problem.queries.front(), {true});
}

TEST(ArmPrebuiltRoadmap, OneSeedOneRoadmapWhoseEdgesAreFreeAndMoreNeighboursMeanNoMoreComponents) {
  const ArmProblem problem = two_link_points();
  const ArmCollisionChecker checker(problem);
  std::int64_t previous_components = 1 << 30;
  std::vector<JointAngles> samples;
  for (const char* k : {"3", "10"}) {
    SCOPED_TRACE(k);
    const auto report = first_query(problem, k);
    EXPECT_EQ(report.facts.at(SamplingFacts::roadmap_samples), 120);
    const auto& graph = *report.recording.graph;
    std::size_t roadmap_edges = 0;
    for (const auto& [a, b] : graph.edges) {
      EXPECT_TRUE(checker.is_free(graph.vertices[a]));
      EXPECT_TRUE(test::samples_free(checker, graph.vertices[a], graph.vertices[b], tenth_degree));
      if (a < 120 && b < 120) ++roadmap_edges;
    }
    EXPECT_EQ(static_cast<std::int64_t>(roadmap_edges), report.facts.at(RoadmapFacts::edges));
    const std::int64_t components = report.facts.at(SamplingFacts::roadmap_components);
    EXPECT_LE(components, previous_components);
    previous_components = components;
    const std::vector<JointAngles> these(graph.vertices.begin(), graph.vertices.begin() + 120);
    if (!samples.empty()) EXPECT_EQ(these, samples);
    samples = these;
    // The same seed and K: the same roadmap.
    const auto again = first_query(problem, k);
    EXPECT_EQ(again.recording.graph->vertices, graph.vertices);
    EXPECT_EQ(again.recording.graph->edges, graph.edges);
  }
}

TEST(ArmPrebuiltRoadmap, EveryQueryIsAnsweredOnTheOneRoadmap) {
  const ArmProblem problem = two_link_points();
  const ArmCollisionChecker checker(problem);
  auto planner = planners<PlanarArm>().find("prm")->make(problem, {{"roadmap-size", "300"}, {"k", "10"}});
  for (const ArmQuery& q : problem.queries) {
    SCOPED_TRACE(q.name);
    const auto report = planner->plan(q);
    EXPECT_EQ(report.facts.at(RoadmapFacts::vertices), 300);
    EXPECT_EQ(report.facts.at(SamplingFacts::samples), 0);
    if (!report.found) {  // an honest not_found naming the components, never a limit
      EXPECT_EQ(report.status, PlanStatus::not_found);
      EXPECT_NE(report.why_not.find("component"), std::string::npos);
      continue;
    }
    for (std::size_t i = 0; i + 1 < report.path.size(); ++i)
      EXPECT_TRUE(test::samples_free(checker, report.path[i], report.path[i + 1], tenth_degree));
  }
}

}  // namespace
}  // namespace polyplan
