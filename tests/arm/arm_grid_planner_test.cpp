// arm/arm_grid_planner: the arm's C-space grid searched on the torus or the square, lazily or
// eagerly. Every returned path is re-checked here with the collision checker alone, densely along
// every motion (every 0.01 degrees of the joint that turns most), and its certificate is re-derived.
#include <polyplan/arm/arm_grid_planner.hpp>

#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_facts.hpp>
#include <polyplan/arm/arm_goal_set.hpp>
#include <polyplan/arm/arm_grid_search.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/io/arm_reader.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
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

PlanReport<JointAngles> plan_once(const ArmProblem& p, const ArmQuery& q, const ArmGridOptions& options = {}) {
  return ArmGridPlanner(p, options).plan(q);
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

// The planner's promise, checked independently: exact ends, every configuration free, every motion
// between consecutive ones free at dense samples and certified again, length as the sum of joint
// rotations.
void expect_valid(const ArmProblem& p, const ArmQuery& q, const PlanReport<JointAngles>& plan, bool torus) {
  ASSERT_TRUE(plan.found) << plan.why_not;
  ASSERT_TRUE(plan.certificate.certified);
  ASSERT_GE(plan.path.size(), 2u);
  for (std::size_t i = 0; i < q.start.size(); ++i) {
    EXPECT_EQ(plan.path.front()[i], normalize_angle(q.start[i]));
    EXPECT_EQ(plan.path.back()[i], normalize_angle(q.goal[i]));
  }
  const ArmCollisionChecker checker(p);
  const double dense = 0.01 * two_pi / 360;
  const double cell = two_pi / static_cast<double>(plan.facts.at(ArmGridFacts::grid_cells_per_axis));
  double length = 0;
  for (std::size_t k = 0; k + 1 < plan.path.size(); ++k) {
    for (const auto& c : motion_samples(plan.path[k], plan.path[k + 1], dense))
      ASSERT_TRUE(checker.is_free(c)) << "configuration between path[" << k << "] and path[" << k + 1 << "] collides";
    EXPECT_TRUE(certify_motion(checker, plan.path[k], plan.path[k + 1]).free()) << "motion " << k;
    for (std::size_t i = 0; i < q.start.size(); ++i) {
      const double d = plan.path[k + 1][i] - plan.path[k][i];
      // On the interval a joint never turns across 0, so consecutive angles differ by at most a step.
      if (!torus) {
        EXPECT_LT(std::fabs(d), cell + 1e-12);
      }
      length += torus ? angular_distance(plan.path[k][i], plan.path[k + 1][i]) : std::fabs(d);
    }
  }
  EXPECT_NEAR(plan.length, length, 1e-9);
}

std::int64_t cells_evaluated(const PlanReport<JointAngles>& plan) {
  return plan.facts.at(ArmGridFacts::cells_evaluated);
}

TEST(ArmGridPlanner, TorusKeepsTheEasyCaseShortAndTheIntervalUnwinds) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& easy = query_named(p, "easy");
  ArmGridOptions torus;
  const auto on_torus = plan_once(p, easy, torus);
  expect_valid(p, easy, on_torus, true);
  ArmGridOptions interval;
  interval.torus = false;
  const auto on_interval = plan_once(p, easy, interval);
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
  const auto on_torus = plan_once(p, hard);
  expect_valid(p, hard, on_torus, true);
  ArmGridOptions interval;
  interval.torus = false;
  const auto on_interval = plan_once(p, hard, interval);
  EXPECT_FALSE(on_interval.found);
  EXPECT_NE(on_interval.why_not.find("not connected"), std::string::npos) << on_interval.why_not;
}

// A query whose tables would outgrow its memory budget ends, not found, naming the budget and the
// option; the same query within the budget is found. Both searches: the compact one (A*) and the
// generic one (eager evaluation, about 330 bytes a cell).
TEST(ArmGridPlanner, AQueryStopsAtItsMemoryBudget) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& hard = query_named(p, "hard");
  ArmGridOptions small;
  small.memory_mb = 0.05;
  const auto stopped = plan_once(p, hard, small);
  EXPECT_FALSE(stopped.found);
  EXPECT_EQ(stopped.why_not.rfind("stopped after evaluating ", 0), 0u) << stopped.why_not;
  EXPECT_NE(
      stopped.why_not.find("the memory budget of one query is 0.05 MB (option memory-mb: raise it with --memory-mb N)"),
      std::string::npos)
      << stopped.why_not;
  EXPECT_LE(stopped.facts.at(ArmGridFacts::memory_mb), 0.05);
  small.lazy = false;  // eager evaluation meets the budget before searching
  const auto eager = plan_once(p, hard, small);
  EXPECT_FALSE(eager.found);
  EXPECT_NE(eager.why_not.find("option memory-mb"), std::string::npos) << eager.why_not;
  const auto within = plan_once(p, hard);
  EXPECT_TRUE(within.found);
  EXPECT_GT(within.facts.at(ArmGridFacts::memory_mb), 0.05);
}

// The compact search (A*, safe angles, bucket queue) and the generic one (search/'s breadth-first
// search on GridGraph, every move certified by certify_motion) decide the same cells and moves, and
// on a grid of equal steps both find a shortest path: their lengths agree (to rounding: paths of
// equal grid length add their rotations in different orders).
TEST(ArmGridPlanner, CompactSearchFindsTheLengthsOfTheGenericSearch) {
  struct Case {
    ArmProblem problem;
    double resolution;
  };
  std::vector<Case> cases{{read_arm_problem(arms + "two_link_points.json"), 5},
                          {read_arm_problem(arms + "two_link_points.json"), 2},
                          {read_arm_problem(arms + "three_link_forest.json"), 10},
                          {four_links_and_a_gap(), 15}};
  for (const Case& c : cases)
    for (const ArmQuery& q : c.problem.queries) {
      ArmGridOptions compact, generic;
      compact.resolution_degrees = generic.resolution_degrees = c.resolution;
      generic.search.algorithm = Search::bfs;
      const auto a = plan_once(c.problem, q, compact), b = plan_once(c.problem, q, generic);
      ASSERT_EQ(a.found, b.found) << c.problem.source << " " << q.name;
      if (!a.found) continue;
      expect_valid(c.problem, q, a, true);
      EXPECT_NEAR(a.length, b.length, 1e-12) << c.problem.source << " " << q.name << " at " << c.resolution;
      EXPECT_EQ(a.facts.at(ArmGridFacts::grid_shortest), "proved");
      EXPECT_GT(a.facts.at(ArmGridFacts::moves_by_clearance), 0) << "most moves are proved by their ends' safe angles";
    }
}

// Coarse to fine on the 3R forest at 2 degrees, the corridor forced (exact_cells 0): its path is
// valid, no shorter than the whole grid's shortest (searched with coarse 0), and the lower bound
// it reports is one; when it says "proved", it is that shortest.
TEST(ArmGridPlanner, CorridorPathsAreValidAndTheirBoundsAreBounds) {
  const ArmProblem p = read_arm_problem(arms + "three_link_forest.json");
  const ArmQuery& q = p.queries.front();
  ArmGridOptions whole;
  whole.resolution_degrees = 2;
  whole.coarse_degrees = 0;
  const auto best = plan_once(p, q, whole);
  expect_valid(p, q, best, true);
  EXPECT_EQ(best.facts.at(ArmGridFacts::grid_shortest), "proved");
  for (const int radius : {1, 2, 4}) {
    ArmGridOptions corridor = whole;
    corridor.coarse_degrees = 5;
    corridor.exact_cells = 0;
    corridor.corridor = radius;
    const auto plan = plan_once(p, q, corridor);
    ASSERT_TRUE(plan.found) << "radius " << radius << ": " << plan.why_not;
    expect_valid(p, q, plan, true);
    EXPECT_EQ(plan.facts.at(ArmGridFacts::grid_coarse_degrees), 5);
    EXPECT_GE(plan.length, best.length - 1e-12) << "radius " << radius;
    if (plan.facts.at(ArmGridFacts::grid_shortest) == "proved") {
      EXPECT_NEAR(plan.length, best.length, 1e-12) << "radius " << radius;
    } else {
      EXPECT_EQ(plan.facts.at(ArmGridFacts::grid_shortest), "corridor");
      // The bound covers the grid part (the joins are the same cells at the same resolution).
      EXPECT_LE(plan.facts.at(ArmGridFacts::grid_lower_bound), best.length) << "radius " << radius;
    }
    EXPECT_LT(plan.facts.at(ArmGridFacts::cells_evaluated), best.facts.at(ArmGridFacts::cells_evaluated) + 30000)
        << "radius " << radius;
  }
  // With a tiny exact_cells every coarse level is guided by the next coarser one too (40, 20, 10
  // and 5 degrees, each in a corridor): still a valid path, never shorter than the shortest.
  ArmGridOptions cascade = whole;
  cascade.coarse_degrees = 5;
  cascade.exact_cells = 1000;
  const auto guided = plan_once(p, q, cascade);
  expect_valid(p, q, guided, true);
  EXPECT_GE(guided.length, best.length - 1e-12);
  EXPECT_LT(guided.facts.at(ArmGridFacts::cells_evaluated), best.facts.at(ArmGridFacts::cells_evaluated));
  // A corridor wide enough holds every cell the whole search needed: the proof comes with it.
  ArmGridOptions wide = whole;
  wide.coarse_degrees = 5;
  wide.exact_cells = 0;
  wide.corridor = 36;
  const auto proved = plan_once(p, q, wide);
  EXPECT_EQ(proved.facts.at(ArmGridFacts::grid_shortest), "proved");
  EXPECT_NEAR(proved.length, best.length, 1e-12);
}

// The 4R forest at 1 degree (1.7e10 cells): coarse to fine answers with a valid path, shorter than
// at 5 degrees, in a small part of the memory an exact search needs.
TEST(ArmGridPlanner, FourLinkForestAtOneDegreeThroughACorridor) {
  const ArmProblem p = read_arm_problem(arms + "four_link_forest.json");
  const ArmQuery& q = p.queries.front();
  ArmGridOptions fine;
  fine.resolution_degrees = 1;
  const auto plan = plan_once(p, q, fine);
  expect_valid(p, q, plan, true);
  EXPECT_EQ(plan.facts.at(ArmGridFacts::grid_shortest), "corridor");
  EXPECT_LT(plan.length, 8.0820061220085) << "the 5-degree grid's shortest";
  EXPECT_LT(plan.facts.at(ArmGridFacts::memory_mb), 400);
}

TEST(ArmGridPlanner, LazyAndEagerFindPathsOfEqualCostAndLazyEvaluatesLess) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  for (const char* name : {"easy", "medium", "hard"}) {
    const ArmQuery& q = query_named(p, name);
    ArmGridOptions lazy, eager;
    eager.lazy = false;
    const auto a = plan_once(p, q, lazy), b = plan_once(p, q, eager);
    ASSERT_TRUE(a.found && b.found) << name;
    EXPECT_NEAR(a.length, b.length, 1e-12) << name;
    EXPECT_EQ(cells_evaluated(b), 72 * 72) << name;
    EXPECT_LT(cells_evaluated(a), cells_evaluated(b)) << name;
  }
}

TEST(ArmGridPlanner, MediumCaseAtOneDegreeIsValidAndNoLongerThanAtFive) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  const ArmQuery& medium = query_named(p, "medium");
  ArmGridOptions fine;
  fine.resolution_degrees = 1;
  const auto a = plan_once(p, medium, fine);
  expect_valid(p, medium, a, true);
  const auto b = plan_once(p, medium);
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
    const auto plan = plan_once(p, p.queries.front(), options);
    expect_valid(p, p.queries.front(), plan, true);
    EXPECT_GE(plan.length, total_angular_distance(p.queries.front().start, p.queries.front().goal) - 1e-9) << file;
  }
}

TEST(ArmGridPlanner, FourLinksThreadANarrowGap) {
  const ArmProblem p = four_links_and_a_gap();
  const auto plan = plan_once(p, p.queries.front());
  expect_valid(p, p.queries.front(), plan, true);
  // Unfolding joint 3 alone would sweep links 3 and 4 through the wall: the path turns other
  // joints too, so it is longer than the straight motion's π.
  EXPECT_GT(plan.length, M_PI + 0.5);
  const ArmCollisionChecker checker(p);
  EXPECT_FALSE(motion_is_free(checker, p.queries.front().start, p.queries.front().goal));
  EXPECT_LT(cells_evaluated(plan), 72 * 72 * 72 * 72 / 100) << "lazy: a small part of the 72^4 grid";
}

TEST(ArmGridPlanner, SevenJointsPlanLazily) {
  // Seven segment links (width 0) curl from straight along +x up to the y axis. The obstacle points
  // lie beside the region the arm sweeps: a segment link that crosses a point touches it, which
  // sampling the motion never sees but certification does, so points inside the sweep would force
  // a long detour through 72^7 cells.
  ArmProblem p;
  p.source = "seven links";
  p.arm.links = std::vector<double>(7, 0.5);
  p.points = {{2.0, -0.5}, {-1.5, 1.0}, {0.5, -1.5}};
  p.queries = {{"fold", {0, 0, 0, 0, 0, 0, 0}, {M_PI / 2, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3}}};
  const auto plan = plan_once(p, p.queries.front());
  expect_valid(p, p.queries.front(), plan, true);
  EXPECT_LT(cells_evaluated(plan), 1000000);  // of 72^7 = 1.0e13
}

TEST(ArmGridPlanner, ASegmentLinkNeverSweepsAcrossAnObstaclePoint) {
  // One unit segment link turning from 0 to π/2 past a point at (0.5, 0.5·tan 20°): any sampled
  // check misses the instant the segment crosses it; the planner must go round the other way.
  ArmProblem p;
  p.source = "one link and a point";
  p.arm.links = {1};
  p.points = {{0.5 * std::cos(0.349), 0.5 * std::sin(0.349)}};
  p.queries = {{"quarter turn", {0}, {M_PI / 2}}};
  const auto plan = plan_once(p, p.queries.front());
  expect_valid(p, p.queries.front(), plan, true);
  EXPECT_GT(plan.length, 1.5 * M_PI - 1e-9) << "the short way sweeps across the point";
}

TEST(ArmGridPlanner, CollidingStartIsAnAnswerAndBadOptionsAreRefused) {
  ArmProblem p = four_links_and_a_gap();
  ArmQuery into_wall{"into the wall", {0.3, 0, 0, 0}, {0, 0, 0, 0}};  // link 3 crosses x = 2.5 at y = 0.77
  const auto plan = plan_once(p, into_wall);
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.path.empty());
  EXPECT_EQ(plan.why_not, "the start collides: link 3 meets obstacles[0]");
  const auto short_query = plan_once(p, ArmQuery{"short", {0, 0}, {0, 0}});
  EXPECT_FALSE(short_query.found);
  EXPECT_EQ(short_query.why_not, "the query short has 2 start and 2 goal angles for an arm of 4 joints");
  ArmGridOptions bad;
  bad.resolution_degrees = 7;  // does not divide 360
  EXPECT_THROW(ArmGridPlanner(p, bad), std::invalid_argument);
  bad.resolution_degrees = 5;
  bad.lazy = false;  // 72^4 = 2.7e7 cells eagerly
  EXPECT_THROW(ArmGridPlanner(p, bad), std::invalid_argument);
}

// A stored safe angle never exceeds the angle measured: units · unit ≤ safe as real numbers
// (fma's one rounding keeps the sign of units · unit − safe). Rounding safe / unit to nearest
// first, then down to a whole unit, would break that where the quotient rounds up onto a whole
// number: such cases are found here, and must lose their unit.
TEST(ArmGridSearch, SafeAnglesAreStoredRoundedDown) {
  std::mt19937_64 random(255);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int quotient_rounded_up = 0;
  for (int i = 0; i < 200000; ++i) {
    const double step = two_pi / std::ldexp(1.0 + uniform(random), 6 + static_cast<int>(uniform(random) * 6));
    const double unit = std::nextafter(step / 255, 1.0);
    // Angles at and near whole numbers of units, where rounding decides.
    const double whole = std::floor(uniform(random) * 300);
    const double safe = i % 2 ? whole * unit : uniform(random) * 300 * unit;
    const std::uint8_t units = safe_angle_units(safe, unit);
    ASSERT_LE(std::fma(static_cast<double>(units), unit, -safe), 0.0)
        << safe << " / " << unit << " stored as " << int(units);
    const double naive = std::floor(safe / unit);
    if (naive < 255 && std::fma(naive, unit, -safe) > 0) {
      ++quotient_rounded_up;
      EXPECT_EQ(units, naive - 1);
    }
    if (safe >= 255 * unit) {
      EXPECT_GE(units, 254) << "at most one unit is lost";
    }
  }
  EXPECT_GT(quotient_rounded_up, 100) << "the test must meet the case it guards against";
  EXPECT_EQ(safe_angle_units(0, 1e-3), 0);
  EXPECT_EQ(safe_angle_units(std::numeric_limits<double>::infinity(), 1e-3), 255);
}

// Coarse to fine must not turn a miss into a claim. Among these points the 5-degree guide finds a
// path, but the 1-degree cells within its corridor (0 coarse cells wide, and a corridor asked for
// on any grid: exact_cells 1) hold none: the earlier release answered "not connected". The whole
// grid has a path, found after the corridor's; at a memory budget too small for the whole grid
// the answer is status limit, never no_path or not_found.
TEST(ArmGridPlanner, ACorridorWithoutAPathGivesWayToTheWholeGrid) {
  const ArmProblem p = parse_arm_problem(R"({"links": [1, 1], "link_width": 0.05,
    "points": [[-1.65, 0.983], [-1.894, -0.139], [0.238, 0.498], [0.251, -0.637], [0.366, 0.164],
               [0.415, -0.974], [0.378, 0.556], [-0.511, -1.742], [-0.939, 0.133]],
    "start": [4.599, 5.839], "goal": [3.843, 2.965]})",
                                         "corridor_miss");
  ArmGridOptions options;
  options.resolution_degrees = 1;
  options.exact_cells = 1;
  options.corridor = 0;
  const auto whole = plan_once(p, p.queries[0], options);
  expect_valid(p, p.queries[0], whole, true);
  EXPECT_TRUE(whole.facts.at(ArmGridFacts::grid_whole_grid));
  EXPECT_EQ(whole.facts.at(ArmGridFacts::grid_rounds), 2);
  EXPECT_EQ(whole.facts.at(ArmGridFacts::grid_shortest), "proved");
  options.coarse_degrees = 0;  // the whole grid from the start: the same shortest length
  EXPECT_NEAR(plan_once(p, p.queries[0], options).length, whole.length, 1e-12);

  options.coarse_degrees = 5;
  options.memory_mb = 0.08;  // the corridor's search fits, the whole grid's does not
  const auto stopped = plan_once(p, p.queries[0], options);
  EXPECT_FALSE(stopped.found);
  EXPECT_EQ(stopped.status, PlanStatus::limit);
  EXPECT_NE(stopped.why_not.find("no path within 0 coarse cells of the 5-degree path"), std::string::npos)
      << stopped.why_not;
  EXPECT_EQ(stopped.facts.at(QueryFacts::stopped_by), "memory limit");
}

// A narrow passage that the 5-degree guide misses and the 1-degree grid has: among these points
// the 5-degree grid holds no path (searched whole), the 2-degree one does. The planner then tries
// a 2.5-degree guide and plans the 1-degree grid in its corridor (the whole 1-degree grid finds
// the same length, 10.1175 rad, evaluating 21 M cells instead of 2 M).
TEST(ArmGridPlanner, AGuideThatMissesAPassageGivesWayToAFinerGuide) {
  const ArmProblem p = parse_arm_problem(R"({"links": [1, 1, 1], "link_width": 0.1,
    "points": [[-1.27, 0.812], [1.509, 2.25], [0.479, -0.178], [2.603, -0.215], [1.467, -0.475], [0.476, 2.684],
               [1.186, -1.958], [-2.076, -0.249], [-0.646, 1.004], [0.952, 0.434]],
    "start": [3.697, 1.802, 5.088], "goal": [0.283, 5.675, 4.356]})",
                                         "passage");
  ArmGridOptions coarse;
  coarse.coarse_degrees = 0;
  const auto missed = plan_once(p, p.queries[0], coarse);
  EXPECT_FALSE(missed.found);
  EXPECT_EQ(missed.status, PlanStatus::not_found) << "a grid without a path is not a proof about the arm";

  ArmGridOptions fine;
  fine.resolution_degrees = 1;
  const auto found = plan_once(p, p.queries[0], fine);
  expect_valid(p, p.queries[0], found, true);
  EXPECT_EQ(found.facts.at(ArmGridFacts::grid_coarse_degrees), 2.5);
  EXPECT_NEAR(found.length, 10.117523757709614, 1e-9);
}

// How many of a path's motions are grid moves (both ends on cells of n per joint): the steps the
// search counted, the joins of start and goal left out.
std::size_t grid_moves(const std::vector<JointAngles>& path, std::int64_t n) {
  const double step = two_pi / static_cast<double>(n);
  const auto on_grid = [&](const JointAngles& q) {
    return std::all_of(q.begin(), q.end(),
                       [&](double a) { return static_cast<double>(std::llround(a / step)) * step == a; });
  };
  std::size_t moves = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) moves += on_grid(path[k]) && on_grid(path[k + 1]);
  return moves;
}

// A goal in the workspace is a set of goal configurations: the grid reaches the nearest in grid
// moves, which is the fewest moves of the grid planned to each goal alone; every way of searching
// agrees (the compact A* and Dijkstra, the generic graph's A* eagerly and breadth first). The path
// ends exactly at the goal the facts name, with the hand at the point.
TEST(ArmGridPlanner, AGoalPointEndsAtTheNearestGoalOfItsSet) {
  struct Case {
    std::string file, query;
    double resolution;
    bool eager;
  };
  for (const Case& c :
       {Case{"two_link_reach.json", "two_elbows", 10, true}, Case{"four_link_reach.json", "near_the_base", 10, false},
        Case{"four_link_reach.json", "oriented", 10, false}}) {
    SCOPED_TRACE(c.file + " " + c.query);
    const ArmProblem p = read_arm_problem(arms + c.file);
    const ArmQuery& q = query_named(p, c.query);
    const ArmCollisionChecker checker(p);
    const ArmGoalSet set = arm_goal_set(checker, q);
    ASSERT_GE(set.goals.size(), 2u);
    ArmGridOptions options;
    options.resolution_degrees = c.resolution;
    const std::int64_t n = 360 / static_cast<std::int64_t>(c.resolution);
    std::size_t fewest = SIZE_MAX;
    std::vector<std::size_t> moves_to;
    for (const ArmGoal& goal : set.goals) {
      const auto alone = plan_once(p, {"alone", q.start, goal.angles}, options);
      moves_to.push_back(alone.found ? grid_moves(alone.path, n) : SIZE_MAX);
      fewest = std::min(fewest, moves_to.back());
    }
    ASSERT_NE(fewest, SIZE_MAX);
    std::vector<ArmGridOptions> searches(4, options);
    searches[1].search.algorithm = Search::dijkstra;
    searches[2].lazy = !c.eager;
    searches[3].search.algorithm = Search::bfs;
    for (const ArmGridOptions& o : searches) {
      SCOPED_TRACE(std::string(to_string(o.search.algorithm)) + (o.lazy ? " lazy" : " eager"));
      const auto plan = plan_once(p, q, o);
      ASSERT_TRUE(plan.found) << plan.why_not;
      test::expect_arm_path_free(checker, q, plan.path);
      const std::size_t reached = test::expect_goal_facts(plan, set);
      EXPECT_EQ(grid_moves(plan.path, n), fewest);
      EXPECT_EQ(moves_to[reached], fewest);
      EXPECT_EQ(plan.facts.at(ArmGridFacts::grid_shortest),
                o.search.algorithm == Search::bfs ? "not claimed" : "proved");
    }
  }
}

// Coarse to fine with goals: every level joins them, and the corridor's path ends at one.
TEST(ArmGridPlanner, AGoalPointPlansCoarseToFine) {
  const ArmProblem p = read_arm_problem(arms + "four_link_reach.json");
  const ArmQuery& q = query_named(p, "near_the_base");
  ArmGridOptions options;
  options.resolution_degrees = 2.5;
  options.exact_cells = 0;  // always the corridor
  const auto plan = plan_once(p, q, options);
  ASSERT_TRUE(plan.found) << plan.why_not;
  EXPECT_EQ(plan.facts.at(ArmGridFacts::grid_rounds), 1);
  const ArmCollisionChecker checker(p);
  test::expect_arm_path_free(checker, q, plan.path);
  test::expect_goal_facts(plan, arm_goal_set(checker, q));
}

// With one goal the grid's answer is what it was before goal sets: no goal facts at all.
TEST(ArmGridPlanner, OneGoalInJointAnglesHasNoGoalFacts) {
  const ArmProblem p = read_arm_problem(arms + "two_link_points.json");
  for (const ArmQuery& q : p.queries) {
    const PlanReport<JointAngles> plan = plan_once(p, q);
    ASSERT_TRUE(plan.found);
    for (const auto& [name, value] : plan.facts.entries()) EXPECT_NE(name.rfind("goal.", 0), 0u) << name;
  }
}

}  // namespace
}  // namespace polyplan
