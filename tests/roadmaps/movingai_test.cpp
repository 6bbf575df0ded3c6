// Euclidean shortest paths on the MovingAI maps against Polyanya's reference lengths.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace polyplan;

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
  const auto reference = read_reference_lengths(kBenchmarks + "/reference/" + name + ".csv");
  Outcome outcome;
  for (std::size_t i = 0; i < scenarios.size(); i += stride) {
    if (i >= reference.size() || !reference[i]) continue;
    const ScenarioQuery& q = scenarios[i];
    const Plan plan = graph.plan({q.start_x, q.start_y}, {q.goal_x, q.goal_y});
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

TEST(MovingAI, ArenaMatchesTheReferenceEverywhere) {
  const Outcome o = run_map("arena", 1);
  EXPECT_GE(o.queries, 150u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(MovingAI, Den312dMatchesTheReferenceEverywhere) {
  const Outcome o = run_map("den312d", 1);
  EXPECT_GE(o.queries, 300u);
  EXPECT_EQ(o.mismatches, 0u);
}

TEST(MovingAI, Lak303dSampleMatchesTheReference) {
  const Outcome o = run_map("lak303d", 10);
  EXPECT_GE(o.queries, 100u);
  EXPECT_EQ(o.mismatches, 0u);
}
