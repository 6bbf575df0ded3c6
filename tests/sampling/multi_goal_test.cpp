// The sampling planners (prm, lazyprm, rrt, rrtstar, rrtconnect) planning to a set of goals
// (SamplingSpace::goals): a polygon world's space whose goal is a set — one goal walled in, one
// reachable far away, one reachable near — planned by every planner; the facts goal.candidates and
// goal.reached, present only where there are several goals; the goal tree of several roots.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/plan/plan_facts.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/sampling/lazy_prm_planner.hpp>
#include <polyplan/sampling/polygon_sampling_space.hpp>
#include <polyplan/sampling/prm_planner.hpp>
#include <polyplan/sampling/rrt_connect_planner.hpp>
#include <polyplan/sampling/rrt_planner.hpp>
#include <polyplan/sampling/rrt_star_planner.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

// The polygon world's sampling space with a goal set of its own in place of the query's goal.
class GoalSetSpace final : public SamplingSpace<TranslatingRobot> {
 public:
  GoalSetSpace(std::unique_ptr<SamplingSpace<TranslatingRobot>> space, std::vector<ExactPoint> goals)
      : space_(std::move(space)), goals_(std::move(goals)) {}

  std::vector<ExactPoint> goals(const Query&) override { return goals_; }

  std::size_t dimension() const override { return space_->dimension(); }
  SamplingMetric metric() const override { return space_->metric(); }
  std::size_t index_dimension() const override { return space_->index_dimension(); }
  bool distance_is_metric() const override { return space_->distance_is_metric(); }
  bool symmetric() const override { return space_->symmetric(); }
  double distance(std::span<const double> a, std::span<const double> b) const override {
    return space_->distance(a, b);
  }
  double distance_bound(std::span<const double> a, std::span<const double> b) const override {
    return space_->distance_bound(a, b);
  }
  void interpolate(std::span<const double> a, std::span<const double> b, double t,
                   std::span<double> out) const override {
    space_->interpolate(a, b, t, out);
  }
  double extent() const override { return space_->extent(); }
  double volume() const override { return space_->volume(); }
  void sample(SamplingRandom& random, std::span<double> out) const override { space_->sample(random, out); }
  void coordinates(const ExactPoint& p, std::span<double> out) const override { space_->coordinates(p, out); }
  ExactPoint configuration(std::span<const double> c) const override { return space_->configuration(c); }
  bool is_free(const ExactPoint& p) override { return space_->is_free(p); }
  bool motion_is_free(const ExactPoint& a, const ExactPoint& b) override { return space_->motion_is_free(a, b); }
  std::optional<std::string> query_not_free(const Query& q) override { return space_->query_not_free(q); }
  std::optional<std::string> no_path(const Query& q) override { return space_->no_path(q); }
  ExactPoint start(const Query& q) const override { return space_->start(q); }
  ExactPoint goal(const Query& q) const override { return space_->goal(q); }
  std::string certificate_method() const override { return space_->certificate_method(); }

 private:
  std::unique_ptr<SamplingSpace<TranslatingRobot>> space_;
  std::vector<ExactPoint> goals_;
};

using EntryOf = PlannerEntry<TranslatingRobot> (*)(SamplingSpaceFactory<TranslatingRobot>);
const std::array<std::pair<const char*, EntryOf>, 5> sampling_entries{{
    {"prm", &prm_planner_entry<TranslatingRobot>},
    {"lazyprm", &lazy_prm_planner_entry<TranslatingRobot>},
    {"rrt", &rrt_planner_entry<TranslatingRobot>},
    {"rrtstar", &rrt_star_planner_entry<TranslatingRobot>},
    {"rrtconnect", &rrt_connect_planner_entry<TranslatingRobot>},
}};

// The planner of `entry` on `cspace`, planning to `goals` whatever the query's goal.
std::unique_ptr<Planner<TranslatingRobot>> planner_to(EntryOf entry, const CSpace& cspace,
                                                      std::vector<ExactPoint> goals, const OptionValues& options) {
  return entry([goals](const CSpace& c) { return std::make_unique<GoalSetSpace>(polygon_sampling_space(c), goals); })
      .make(cspace, options);
}

// A square ring whose hole holds the walled-in goal; the open world has nothing else, so that the
// start sees both other goals (a roadmap joins all three at once, and must choose), the walled
// world a wall between the start and the far goal (a detour over it). The goals' coordinates are
// thirds, which no double holds: a path ends at one only by being given it.
const char* open_world = R"({"bounds": [0, 0, 10, 10],
    "obstacles": [{"outer": [[6, 6], [9, 6], [9, 9], [6, 9]], "holes": [[[7, 7], [7, 8], [8, 8], [8, 7]]]}],
    "start": [1, 1], "goal": ["28/3", "1/3"]})";
const char* walled_world = R"({"bounds": [0, 0, 10, 10],
    "obstacles": [[[4, 0], [5, 0], [5, 6], [4, 6]],
                  {"outer": [[6, 6], [9, 6], [9, 9], [6, 9]], "holes": [[[7, 7], [7, 8], [8, 8], [8, 7]]]}],
    "start": [1, 1], "goal": ["28/3", "1/3"]})";
const ExactPoint start = test::pt("1", "1");
const ExactPoint walled_in = test::pt("22/3", "23/3"), far = test::pt("28/3", "1/3"), near = test::pt("7/3", "10/3");

// Limits that find a path in these worlds at once, and give RRT* (which runs to its limit) time to
// reach the near goal without taking long.
OptionValues quick(const std::string& planner) {
  return {{"seed", "1"}, {"time", "30"}, {"iterations", planner == "rrtstar" ? "3000" : "100000"}};
}

// Each planner in both worlds, with the goals in two orders: found, from the start to a reachable
// goal exactly, which goal.reached names, every motion certified again by a space of its own and
// the path checked exactly; prm, lazyprm and rrtstar (which search for the cheapest) at the near
// goal, even where the far one comes first.
class MultiGoalInWorld : public ::testing::TestWithParam<std::string> {};

TEST_P(MultiGoalInWorld, EveryPlannerEndsAtAReachableGoalAndNamesIt) {
  const World world = test::world_from(GetParam() == "open" ? open_world : walled_world);
  const CSpace cspace(world);
  const auto checker = polygon_sampling_space(cspace);
  for (const std::vector<ExactPoint>& goals : {std::vector{walled_in, far, near}, std::vector{near, walled_in, far}}) {
    for (const auto& [name, entry] : sampling_entries) {
      SCOPED_TRACE(std::string(name) + ", near goal at index " + std::to_string(goals[0] == near ? 0 : 2));
      const auto report = planner_to(entry, cspace, goals, quick(name))->plan(world.queries[0]);
      ASSERT_TRUE(report.found) << report.why_not;
      EXPECT_EQ(report.path.front(), start);
      const auto reached = std::find(goals.begin(), goals.end(), report.path.back());
      ASSERT_NE(reached, goals.end()) << to_string(report.path.back());
      EXPECT_NE(*reached, walled_in);
      EXPECT_EQ(report.facts.at(GoalFacts::reached), reached - goals.begin());
      EXPECT_EQ(report.facts.at(GoalFacts::candidates), 3);
      for (std::size_t i = 0; i + 1 < report.path.size(); ++i)
        EXPECT_TRUE(checker->motion_is_free(report.path[i], report.path[i + 1])) << "motion " << i;
      const PathCheck check = check_path(cspace, report.path);
      EXPECT_TRUE(check.valid) << check.reason;
      if (std::string(name) == "prm" || std::string(name) == "lazyprm" || std::string(name) == "rrtstar") {
        EXPECT_EQ(report.path.back(), near);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(MultiGoal, MultiGoalInWorld, ::testing::Values("open", "walled"),
                         [](const auto& info) { return info.param; });

// RRT's goal bias draws one goal of the set uniformly: with the bias 1 and E1 in a world where both
// goals outside the ring are in sight of the start, the first extension that is free ends at
// whichever goal was drawn — across seeds, at each of them, and never at the walled-in one.
TEST(MultiGoalRrt, TheGoalBiasDrawsEachGoalOfTheSet) {
  const World open = test::world_from(open_world);
  const CSpace open_cspace(open);
  const std::vector<ExactPoint> goals{walled_in, far, near};
  std::set<std::int64_t> reached;
  for (int seed = 1; seed <= 20; ++seed) {
    const auto report = planner_to(&rrt_planner_entry<TranslatingRobot>, open_cspace, goals,
                                   {{"seed", std::to_string(seed)}, {"goal-bias", "1"}, {"extend", "e1"}})
                            ->plan(open.queries[0]);
    ASSERT_TRUE(report.found) << "seed " << seed << ": " << report.why_not;
    EXPECT_EQ(report.path, (std::vector{start, goals[static_cast<std::size_t>(report.facts.at(GoalFacts::reached))]}));
    reached.insert(report.facts.at(GoalFacts::reached));
  }
  EXPECT_EQ(reached, (std::set<std::int64_t>{1, 2}));
}

// The tests below plan in the walled world.
class MultiGoal : public ::testing::Test {
 protected:
  const World world = test::world_from(walled_world);
  const CSpace cspace{world};
};

// With one goal (every space's default goals()) the answer is what it was before goal sets:
// neither fact, found or not.
TEST_F(MultiGoal, ASingleGoalReportsNeitherFact) {
  for (const auto& [name, entry] : sampling_entries) {
    SCOPED_TRACE(name);
    const auto found = planners<TranslatingRobot>().find(name)->make(cspace, quick(name))->plan(world.queries[0]);
    ASSERT_TRUE(found.found) << found.why_not;
    EXPECT_EQ(found.path.back(), far);
    const auto not_found = planner_to(entry, cspace, {walled_in}, {{"iterations", "300"}})->plan(world.queries[0]);
    ASSERT_FALSE(not_found.found);
    for (const auto& report : {found, not_found}) {
      EXPECT_FALSE(report.facts.contains(GoalFacts::candidates));
      EXPECT_FALSE(report.facts.contains(GoalFacts::reached));
    }
  }
}

// Several goals, none reachable: the limit's answer, the candidates counted, none reached.
TEST_F(MultiGoal, AGoalSetOutOfReachEndsAtTheLimitCountingItsCandidates) {
  for (const auto& [name, entry] : sampling_entries) {
    SCOPED_TRACE(name);
    const auto report = planner_to(entry, cspace, {walled_in, test::pt("29/4", "31/4")}, {{"iterations", "300"}})
                            ->plan(world.queries[0]);
    EXPECT_FALSE(report.found);
    EXPECT_EQ(report.facts.at(QueryFacts::stopped_by), "iteration limit");
    EXPECT_EQ(report.facts.at(GoalFacts::candidates), 2);
    EXPECT_FALSE(report.facts.contains(GoalFacts::reached));
  }
}

// A start that is one of the goals is reached at once: a path of length 0 to that goal.
TEST_F(MultiGoal, AStartAmongTheGoalsIsReachedAtOnce) {
  for (const auto& [name, entry] : sampling_entries) {
    SCOPED_TRACE(name);
    const auto report = planner_to(entry, cspace, {far, start, near}, {})->plan(world.queries[0]);
    ASSERT_TRUE(report.found) << report.why_not;
    EXPECT_EQ(report.path, (std::vector{start, start}));
    EXPECT_EQ(report.length, 0);
    EXPECT_EQ(report.facts.at(GoalFacts::reached), 1);
  }
}

TEST_F(MultiGoal, AnEmptyGoalSetIsTheSpacesError) {
  for (const auto& [name, entry] : sampling_entries) {
    SCOPED_TRACE(name);
    EXPECT_THROW(planner_to(entry, cspace, {}, {})->plan(world.queries[0]), std::logic_error);
  }
}

// RRT-Connect's goal tree: a forest whose roots are their own parents, each path running from the
// root of its own tree, and a picture with an edge per motion and none at a root.
TEST_F(MultiGoal, ATreeOfSeveralRootsRunsEachPathFromItsOwnRoot) {
  const auto space = polygon_sampling_space(cspace);
  SamplingTree<TranslatingRobot> forest(*space, std::vector{start, far}, Toward::placed);
  ASSERT_EQ(forest.size(), 2u);
  EXPECT_TRUE(forest.is_root(SamplingTree<TranslatingRobot>::root));
  EXPECT_TRUE(forest.is_root(1));
  const std::array<double, 2> child_at{8, 2}, grandchild_at{7, 3};
  const std::size_t child = forest.add(space->configuration(child_at), child_at, 1);
  const std::size_t grandchild = forest.add(space->configuration(grandchild_at), grandchild_at, child);
  EXPECT_FALSE(forest.is_root(child));
  EXPECT_EQ(forest.path_from_root(grandchild), (std::vector{far, test::pt("8", "2"), test::pt("7", "3")}));
  EXPECT_EQ(forest.path_from_root(1), std::vector{far});
  EXPECT_EQ(forest.path_from_root(0), std::vector{start});
  const std::array<double, 2> by_the_start{1.5, 1.5};
  EXPECT_EQ(forest.nodes().nearest(by_the_start, Toward::placed), 0u);
  const auto picture = SamplingTree<TranslatingRobot>::picture({&forest});
  EXPECT_EQ(picture->vertices.size(), 4u);
  EXPECT_EQ(picture->edges, (std::vector<std::pair<std::size_t, std::size_t>>{{child, 1}, {grandchild, child}}));
}

}  // namespace
}  // namespace polyplan
