#pragma once
// The MovingAI maps of data/movingai traced into polygon worlds, for the planners that answer
// their scenario queries: each found exactly when the reference says a path exists, valid under
// the exact check, and no shorter than the reference's optimum.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/io/movingai_map.hpp>
#include <polyplan/io/movingai_scenario.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace polyplan::test {

// A width x height map whose cells are blocked with the given probability (at 0.3 it has pinch
// points: blocked cells that touch only at a corner).
inline GridMap random_grid(std::mt19937& random, int width, int height, double blocked) {
  GridMap map;
  map.source = "random grid";
  map.width = width;
  map.height = height;
  std::bernoulli_distribution coin(blocked);
  for (int i = 0; i < width * height; ++i) map.blocked.push_back(coin(random));
  return map;
}

// Every `stride`-th query of the map `name` with a reference length; at least `at_least` of them.
template <class Planner>
void expect_answers_to_the_scenarios(const std::string& name, std::size_t stride, std::size_t at_least) {
  const std::string dir = data_file("movingai");
  const CSpace c(world_from_grid(read_movingai_map(dir + "/maps/" + name + ".map")));
  Planner planner(c);
  const auto scenarios = read_scenarios(dir + "/scenarios/" + name + ".map.scen");
  const auto reference = read_reference_lengths(dir + "/reference/" + name + ".csv", scenarios.size());
  std::size_t answered = 0;
  for (std::size_t i = 0; i < scenarios.size(); i += stride) {
    if (i >= reference.size() || !reference[i]) continue;
    const ScenarioQuery& q = scenarios[i];
    const auto report = planner.plan(Query{{q.start_x, q.start_y}, {q.goal_x, q.goal_y}, "q"});
    ++answered;
    ASSERT_EQ(report.found, *reference[i] >= 0) << name << " query " << i << ": " << report.why_not;
    if (!report.found) continue;
    const PathCheck check = check_path(c, report.path);
    EXPECT_TRUE(check.valid) << name << " query " << i << ": " << check.reason;
    EXPECT_GE(report.length, *reference[i] - 1e-9 * std::max(1.0, *reference[i])) << name << " query " << i;
  }
  EXPECT_GE(answered, at_least);
}

}  // namespace polyplan::test
