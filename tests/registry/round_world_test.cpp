// Worlds with discs, walls, disc bounds or a disc robot (data/worlds: sphere_world, ...):
// through the front door every planner either plans them — the tangent visibility graph, the
// sampling planners, the grids and the reactive planners, each query answered with a path that an
// independent check accepts (exact for polylines; in doubles, piece by piece, for tangents and
// arcs) — or refuses, naming the file and
// what it does not plan with: never a plan straight through a disc or a wall.
#include "piece_path_check.hpp"
#include "registry_fixtures.hpp"

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/problem.hpp>
#include <polyplan/registry/robot_path_check.hpp>
#include <polyplan/registry/world_queries.hpp>

#include <gtest/gtest.h>

namespace polyplan {
namespace {

std::string path_of(const std::string& world) {
  return std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + world + ".json";
}

class EveryPlannerOnEveryRoundWorld : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryPlannerOnEveryRoundWorld, PlansOrRefusesNamingWhatItHas) {
  const Problem problem = Problem::read(path_of(GetParam()));
  const std::vector<std::string> features = round_features(*problem.world());
  ASSERT_FALSE(features.empty());
  const std::vector<std::string> able = planners_for_round_worlds();
  for (const PlannerListing& listing : planner_catalog()) {
    if (listing.kind != "World") continue;
    SCOPED_TRACE(listing.name);
    const bool plans = std::find(able.begin(), able.end(), listing.name) != able.end();
    try {
      // A sampling planner (one with a seed) seeded; an anytime one (rrtstar) stops after 500
      // iterations rather than at its time limit. The others with their defaults.
      OptionValues options;
      const bool samples = std::any_of(listing.options.begin(), listing.options.end(),
                                       [](const OptionInfo& o) { return o.name == "seed"; });
      if (plans && samples)
        options = {{"seed", "3"}, {"time", "5"}, {"iterations", listing.anytime ? "500" : "100000"}};
      const auto planner = make_planner(listing.name, problem, options);
      EXPECT_TRUE(plans) << "built for a world it does not plan with";
      for (std::size_t q = 0; q < problem.world()->queries.size(); ++q) {
        const Report report = planner->plan(q);
        SCOPED_TRACE(report.query());
        // A path, or an answer that says why not (rrtstar stopped by its 500 iterations round
        // walls_bug's 200-long wall; the navigation function where the world is no sphere world;
        // the potential field at a local minimum, its walk checked as a path is; the raster where its
        // cells close a passage); rrtconnect and visibility, the default, find every one.
        const auto& typed = std::get<PlanReport<ExactPoint>>(report.typed());
        if (!report.found()) {
          EXPECT_NE(listing.name, "rrtconnect") << report.why_not();
          EXPECT_NE(listing.name, "visibility") << report.why_not();
          EXPECT_FALSE(report.why_not().empty());
          if (typed.path.empty()) continue;
        }
        if (!typed.pieces.empty()) {  // a path of tangents and arcs (visibility): its points are irrational
          test::expect_valid_pieces(*problem.world(), typed,
                                    [&](const auto& p) { return check_translating_path(problem, p); });
          continue;
        }
        const PathCheck check = check_translating_path(problem, typed.path);  // the checker, asked afresh
        EXPECT_TRUE(check.valid) << check.reason;
      }
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(GetParam() + ".json"), std::string::npos) << message;
      if (plans) {  // a planner may need what a world lacks (a raster needs bounds) or not follow what
                    // it has (the Bugs follow no arcs); it says which
        const bool lacks_bounds = !problem.world()->bounds && !problem.world()->disc_bounds;
        const bool names_one = std::any_of(features.begin(), features.end(),
                                           [&](const std::string& f) { return message.find(f) != std::string::npos; });
        EXPECT_TRUE(lacks_bounds || names_one) << message;
        continue;
      }
      EXPECT_NE(message.find(listing.name), std::string::npos) << message;
      const bool names_all = std::all_of(features.begin(), features.end(),
                                         [&](const std::string& f) { return message.find(f) != std::string::npos; });
      EXPECT_TRUE(names_all || message.find("car") != std::string::npos) << message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryPlannerOnEveryRoundWorld, ::testing::ValuesIn(test::shipped_worlds(true)),
                         [](const auto& info) { return test::test_name("all", info.param); });

TEST(RoundWorlds, TheirPathsAreCheckedExactlyAndTheirCSpaceRefused) {
  const Problem floor = Problem::read(path_of("disc_robot_floor_plan"));
  // Through both doorways, 1 wide, the robot 0.6 across; then into the wall between them.
  const PathCheck doorways =
      check_translating_path(floor, {{1, 1}, {3.5, 3.5}, {5, 3.5}, {7, 4.5}, {10.5, 4.5}, {11, 7}});
  EXPECT_TRUE(doorways.valid) << doorways.reason;
  const PathCheck through = check_translating_path(floor, {{1, 1}, {11, 7}});
  EXPECT_FALSE(through.valid);
  EXPECT_NE(through.reason.find("walls["), std::string::npos) << through.reason;
  try {
    floor.cspace();
    ADD_FAILURE() << "a polygon C-space of a disc robot among walls";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("discs, walls, a disc robot: the polygon C-space holds"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace polyplan
