#pragma once
// What the tests of the planners of round worlds (RoundRobot) share: a found path checked again,
// exactly, among the world's discs, walls and polygons.
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/plan/plan_report.hpp>

#include <gtest/gtest.h>

namespace polyplan::test {

// Found, from the query's exact start to its exact goal, valid by RoundWorld::check_path (asked
// afresh, not the planner's word), and certified.
inline void expect_checked(const RoundWorld& world, const PlanReport<ExactPoint>& report, const Query& query) {
  ASSERT_TRUE(report.found) << report.why_not;
  EXPECT_EQ(report.path.front(), query.start);
  EXPECT_EQ(report.path.back(), query.goal);
  const PathCheck check = world.check_path(report.path);
  EXPECT_TRUE(check.valid) << check.reason;
  EXPECT_TRUE(report.certificate.certified);
}

}  // namespace polyplan::test
