// arm/arm_grid_planner: the arm's C-space grid searched on the torus or the square, lazily or
// eagerly. Every returned path is re-checked here, configuration by configuration and along every
// motion at the stated resolution, with the collision checker alone.
#include <polyplan/arm/arm_grid_planner.hpp>

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/io/arm_reader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

const std::string arms = std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/";

const ArmQuery& query_named(const ArmProblem& p, const std::string& name) {
  const auto it = std::find_if(p.queries.begin(), p.queries.end(), [&](const ArmQuery& q) { return q.name == name; });
  if (it == p.queries.end()) throw std::out_of_range("no query " + name);
  return *it;
}

// The planner's promise, checked independently: exact ends, every configuration free, every motion
// between consecutive ones free at the check resolution, length as the sum of joint rotations.
void expect_valid(const ArmProblem& p, const ArmQuery& q, const ArmGridPlan& plan, bool torus) {
  ASSERT_TRUE(plan.found) << plan.why_not;
  ASSERT_GE(plan.path.size(), 2u);
  for (std::size_t i = 0; i < q.start.size(); ++i) {
    EXPECT_EQ(plan.path.front()[i], normalize_angle(q.start[i]));
    EXPECT_EQ(plan.path.back()[i], normalize_angle(q.goal[i]));
  }
  const ArmCollisionChecker checker(p);
  const double step = plan.check_degrees * two_pi / 360;
  double length = 0;
  for (std::size_t k = 0; k + 1 < plan.path.size(); ++k) {
    for (const auto& c : motion_samples(plan.path[k], plan.path[k + 1], step))
      ASSERT_TRUE(checker.is_free(c)) << "configuration between path[" << k << "] and path[" << k + 1 << "] collides";
    for (std::size_t i = 0; i < q.start.size(); ++i) {
      const double d = plan.path[k + 1][i] - plan.path[k][i];
      // On the interval a joint never turns across 0, so consecutive angles differ by at most a step.
      if (!torus) {
        EXPECT_LT(std::fabs(d), two_pi / static_cast<double>(plan.cells_per_axis) + 1e-12);
      }
      length += torus ? angular_distance(plan.path[k][i], plan.path[k + 1][i]) : std::fabs(d);
    }
  }
  EXPECT_NEAR(plan.length, length, 1e-9);
}

TEST(ArmGridPlanner, TorusKeepsTheEasyCaseShortAndTheIntervalUnwinds) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& easy = query_named(p, "easy");
  ArmGridOptions torus;
  const ArmGridPlan on_torus = plan_arm_on_grid(p, easy, torus);
  expect_valid(p, easy, on_torus, true);
  ArmGridOptions interval;
  interval.torus = false;
  const ArmGridPlan on_interval = plan_arm_on_grid(p, easy, interval);
  expect_valid(p, easy, on_interval, false);
  // θ2 from 0.12 to 6.00: 0.40 rad the short way round, 5.88 rad unwound.
  EXPECT_LT(on_torus.length, 1.0);
  EXPECT_GT(on_interval.length, 5.8);
  double lowest = two_pi, highest = 0;
  for (const auto& q : on_interval.path) lowest = std::min(lowest, q[1]), highest = std::max(highest, q[1]);
  EXPECT_GT(highest - lowest, 5.5) << "the interval path turns joint 2 through almost the whole circle";
}

TEST(ArmGridPlanner, HardCaseIsFoundOnlyOnTheTorus) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& hard = query_named(p, "hard");
  const ArmGridPlan on_torus = plan_arm_on_grid(p, hard, {});
  expect_valid(p, hard, on_torus, true);
  ArmGridOptions interval;
  interval.torus = false;
  const ArmGridPlan on_interval = plan_arm_on_grid(p, hard, interval);
  EXPECT_FALSE(on_interval.found);
  EXPECT_NE(on_interval.why_not.find("not connected"), std::string::npos) << on_interval.why_not;
}

TEST(ArmGridPlanner, LazyAndEagerFindPathsOfEqualCostAndLazyEvaluatesLess) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  for (const char* name : {"easy", "medium", "hard"}) {
    const ArmQuery& q = query_named(p, name);
    ArmGridOptions lazy, eager;
    eager.lazy = false;
    const ArmGridPlan a = plan_arm_on_grid(p, q, lazy), b = plan_arm_on_grid(p, q, eager);
    ASSERT_TRUE(a.found && b.found) << name;
    EXPECT_NEAR(a.length, b.length, 1e-12) << name;
    EXPECT_EQ(b.cells_evaluated, 72u * 72u) << name;
    EXPECT_LT(a.cells_evaluated, b.cells_evaluated) << name;
  }
}

TEST(ArmGridPlanner, MediumCaseAtOneDegreeIsValidAndNoLongerThanAtFive) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& medium = query_named(p, "medium");
  ArmGridOptions fine;
  fine.resolution_degrees = 1;
  const ArmGridPlan a = plan_arm_on_grid(p, medium, fine);
  expect_valid(p, medium, a, true);
  const ArmGridPlan b = plan_arm_on_grid(p, medium, {});
  expect_valid(p, medium, b, true);
  // The 5-degree grid is a sub-grid of the 1-degree one; only the joins to start and goal differ
  // (each at most half a cell per joint).
  EXPECT_LE(a.length, b.length + 2 * 2 * (2.5 * two_pi / 360));
}

TEST(ArmGridPlanner, ForestArmsFromSeed001Plan) {
  for (const char* file : {"three_link_forest.json", "four_link_forest.json"}) {
    const ArmProblem p = read_arm_problem(arms + file);
    ASSERT_FALSE(p.queries.empty());
    ArmGridOptions options;
    options.resolution_degrees = 10;
    const ArmGridPlan plan = plan_arm_on_grid(p, p.queries.front(), options);
    expect_valid(p, p.queries.front(), plan, true);
    EXPECT_GE(plan.length, total_angular_distance(p.queries.front().start, p.queries.front().goal) - 1e-9) << file;
  }
}

// Four unit links; a wall at x in [2.5, 2.7] with a gap |y| < 0.3: the straight arm fits through
// it only within 0.11 rad of the x axis (about two 5-degree cells). The start folds link 3 back
// (joints (1, 0), (2, 0), (1, 0), (0, 0)); the goal stretches the arm straight through the gap, so
// links 3 and 4 must unfold without sweeping into the wall and thread the gap.
ArmProblem four_links_and_a_gap() {
  ArmProblem p;
  p.source = "four_links_and_a_gap";
  p.arm.links = {1, 1, 1, 1};
  const auto box = [](const char* x0, const char* y0, const char* x1, const char* y1) {
    const Rational a = *parse_rational(x0), b = *parse_rational(y0), c = *parse_rational(x1), d = *parse_rational(y1);
    return PolygonWithHoles{{{a, b}, {c, b}, {c, d}, {a, d}}, {}};
  };
  p.obstacles = {box("2.5", "0.3", "2.7", "5"), box("2.5", "-5", "2.7", "-0.3")};
  p.obstacle_names = {"obstacles[0]", "obstacles[1]"};
  p.queries = {{"through the gap", {0, 0, M_PI, 0}, {0, 0, 0, 0}}};
  return p;
}

TEST(ArmGridPlanner, FourLinksThreadANarrowGap) {
  const ArmProblem p = four_links_and_a_gap();
  const ArmGridPlan plan = plan_arm_on_grid(p, p.queries.front(), {});
  expect_valid(p, p.queries.front(), plan, true);
  // Unfolding joint 3 alone would sweep links 3 and 4 through the wall: the path turns other
  // joints too, so it is longer than the straight motion's π.
  EXPECT_GT(plan.length, M_PI + 0.5);
  const ArmCollisionChecker checker(p);
  EXPECT_FALSE(motion_is_free(checker, p.queries.front().start, p.queries.front().goal, two_pi / 360));
  EXPECT_LT(plan.cells_evaluated, 72u * 72u * 72u * 72u / 100) << "lazy: a small part of the 72^4 grid";
}

TEST(ArmGridPlanner, SevenJointsPlanLazily) {
  ArmProblem p;
  p.source = "seven links";
  p.arm.links = std::vector<double>(7, 0.5);
  p.points = {{2.0, 0.2}, {1.0, 1.5}, {-1.5, 1.0}};
  p.queries = {{"fold", {0, 0, 0, 0, 0, 0, 0}, {M_PI / 2, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3}}};
  const ArmGridPlan plan = plan_arm_on_grid(p, p.queries.front(), {});
  expect_valid(p, p.queries.front(), plan, true);
  EXPECT_LT(plan.cells_evaluated, 1000000u);  // of 72^7 = 1.0e13
}

TEST(ArmGridPlanner, CollidingStartIsAnAnswerAndBadOptionsAreRefused) {
  ArmProblem p = four_links_and_a_gap();
  ArmQuery into_wall{"into the wall", {0.3, 0, 0, 0}, {0, 0, 0, 0}};  // link 3 crosses x = 2.5 at y = 0.77
  const ArmGridPlan plan = plan_arm_on_grid(p, into_wall, {});
  EXPECT_FALSE(plan.found);
  EXPECT_NE(plan.why_not.find("the start collides: link 3 meets obstacles[0]"), std::string::npos) << plan.why_not;
  ArmGridOptions bad;
  bad.resolution_degrees = 7;  // does not divide 360
  EXPECT_THROW(plan_arm_on_grid(p, p.queries.front(), bad), std::invalid_argument);
  bad.resolution_degrees = 5;
  bad.check_degrees = 6;  // coarser than the grid
  EXPECT_THROW(plan_arm_on_grid(p, p.queries.front(), bad), std::invalid_argument);
  bad.check_degrees = 0;
  bad.lazy = false;  // 72^4 = 2.7e7 cells eagerly
  EXPECT_THROW(plan_arm_on_grid(p, p.queries.front(), bad), std::invalid_argument);
  EXPECT_THROW(plan_arm_on_grid(p, ArmQuery{"short", {0, 0}, {0, 0}}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
