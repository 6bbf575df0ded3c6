// The front door: one call reads any problem file, make_planner settles the space once and
// refuses a planner for another kind of problem with the reason, default_planner is the
// registry's, and every report reads alike whatever the space.
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/plan/plan_json.hpp>
#include <polyplan/registry/any_planner.hpp>
#include <polyplan/registry/registry.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace polyplan {
namespace {

std::string data(const std::string& path) { return std::string(POLYPLAN_SOURCE_DIR) + "/data/" + path; }

Problem read(const std::string& path) {
  std::vector<std::string> warnings;
  return Problem::read(data(path), &warnings);
}

std::string refusal(std::string_view planner, const Problem& problem) {
  try {
    make_planner(planner, problem);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(built)";
}

std::vector<Rational> numbers(std::initializer_list<int> values) { return {values.begin(), values.end()}; }

// Whether the listed planner plans `problem` in the listing's space.
bool planner_for_or_null(const PlannerListing& listing, const Problem& problem) {
  try {
    return planner_for(listing.name, problem).space == listing.space;
  } catch (const InputError&) {
    return false;
  }
}

TEST(Problem, OneCallReadsAWorldOrAnArmByWhatTheFileHolds) {
  const Problem world = read("worlds/seed004.json"), arm = read("arms/two_link_points.json");
  ASSERT_NE(world.world(), nullptr);
  EXPECT_EQ(world.arm(), nullptr);
  ASSERT_NE(arm.arm(), nullptr);
  EXPECT_EQ(arm.world(), nullptr);
  EXPECT_EQ(world.query_names().front(), "start/goal");
  EXPECT_EQ(arm.query_names(), (std::vector<std::string>{"easy", "medium", "hard"}));
  EXPECT_THROW(arm.cspace(), std::logic_error);
  EXPECT_THROW(Problem::read(data("worlds/nowhere.json")), InputError);
  EXPECT_THROW(Problem::parse(R"({"links": []})", "bad.json"), InputError);  // an arm file's own error
}

TEST(Problem, EachProblemGetsItsSpacesDefault) {
  EXPECT_EQ(default_planner(read("worlds/seed004.json")), planners<TranslatingRobot>().default_planner());
  EXPECT_EQ(default_planner(read("worlds/rotation_piano.json")), planners<RotatingRobot>().default_planner());
  EXPECT_EQ(default_planner(read("worlds/car_park.json")), planners<SteeredCar>().default_planner());
  EXPECT_EQ(default_planner(read("arms/two_link_points.json")), planners<PlanarArm>().default_planner());
}

TEST(MakePlanner, ANameRegisteredForSeveralSpacesPlansTheProblemsSpace) {
  EXPECT_EQ(make_planner("rrt", read("worlds/car_park.json"))->listing().space, SteeredCar::description);
  EXPECT_EQ(make_planner("rrt", read("worlds/seed004.json"))->listing().space, TranslatingRobot::description);
  EXPECT_EQ(make_planner("rrt", read("arms/two_link_points.json"))->listing().space, PlanarArm::description);
  EXPECT_EQ(make_planner("rotation", read("worlds/seed004.json"))->listing().space, RotatingRobot::description);
}

TEST(MakePlanner, APlannerOfAnotherKindOfProblemIsRefusedWithTheReason) {
  const std::string arm_planner = refusal("grid", read("worlds/seed004.json"));
  EXPECT_NE(arm_planner.find("planner grid plans in an Arm (a planar n-link arm), not in a World"), std::string::npos)
      << arm_planner;
  EXPECT_NE(arm_planner.find("its planners: visibility, visibility-full"), std::string::npos) << arm_planner;
  const std::string world_planner = refusal("visibility", read("arms/two_link_points.json"));
  EXPECT_NE(world_planner.find("plans in a World"), std::string::npos) << world_planner;
  EXPECT_NE(world_planner.find("its planners: grid, prm"), std::string::npos) << world_planner;
  EXPECT_NE(refusal("visibility", read("worlds/car_park.json")).find("steers like a car"), std::string::npos);
  EXPECT_EQ(refusal("teleport", read("worlds/seed004.json")).rfind("unknown planner \"teleport\" (visibility, ", 0),
            0u);
}

TEST(MakePlanner, ABadOptionIsRefusedBeforeAnythingIsBuilt) {
  EXPECT_THROW(make_planner("raster", read("worlds/seed004.json"), {{"resolution", "forty"}}), InputError);
  EXPECT_THROW(make_planner("raster", read("worlds/seed004.json"), {{"colour", "red"}}), InputError);
}

TEST(Report, ReadsAsThePlannersOwnReportWhateverTheSpace) {
  const Problem world = read("worlds/seed004.json");
  const auto planner = make_planner("visibility", world);
  planner->require_plannable();
  const Report report = planner->plan(0);
  ASSERT_TRUE(report.found());
  EXPECT_EQ(report.status(), PlanStatus::solved);
  EXPECT_EQ(report.query(), "start/goal");
  EXPECT_EQ(report.planner(), "visibility");
  EXPECT_EQ(report.path_columns(), 2u);
  const auto& typed = std::get<PlanReport<ExactPoint>>(report.typed());
  EXPECT_EQ(report.to_json(), plan_json(typed, "start/goal"));
  ASSERT_EQ(report.path().size(), typed.path.size());
  EXPECT_EQ(report.path().back(),
            (std::vector<double>{to_double(typed.path.back().x), to_double(typed.path.back().y)}));
  ASSERT_TRUE(report.exact_path());
  EXPECT_EQ(report.exact_path()->front(), (std::vector<Rational>{typed.path.front().x, typed.path.front().y}));
  EXPECT_EQ(report.summary().rfind("start/goal: length ", 0), 0u) << report.summary();
}

TEST(Report, ACallersQueryIsCheckedAsTheFilesQueriesAre) {
  const Problem world = read("worlds/seed004.json");
  const auto planner = make_planner("visibility", world);
  QuerySpec turned{"mine", numbers({2, 3, 30}), numbers({95, 80}), {}, std::nullopt};
  try {
    planner->plan(turned);
    ADD_FAILURE() << "a turned start was planned by a translating planner";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("use the planner \"rotation\""), std::string::npos) << e.what();
  }
  QuerySpec four{"mine", numbers({1, 2, 3, 4}), numbers({95, 80}), {}, std::nullopt};
  EXPECT_THROW(planner->plan(four), InputError);
  const Report mine = planner->plan(QuerySpec{"mine", numbers({2, 3}), numbers({95, 80}), {}, std::nullopt});
  EXPECT_EQ(mine.query(), "mine");

  const Problem arm = read("arms/two_link_points.json");
  const auto grid = make_planner("grid", arm);
  EXPECT_THROW(grid->plan(QuerySpec{"three", numbers({0, 0, 0}), numbers({1, 1}), {}, std::nullopt}), InputError);
  EXPECT_THROW(grid->plan(QuerySpec{"both", numbers({0, 0}), numbers({1, 1}), numbers({1, 1}), std::nullopt}),
               InputError);
}

// A value just outside an option's range, as text: below its least value, or above its greatest.
std::optional<std::string> outside(const OptionRange& range) {
  if (std::isfinite(range.min)) return detail::show_number(range.min_open ? range.min : range.min - 1);
  if (std::isfinite(range.max)) return detail::show_number(range.max_open ? range.max : range.max + 1);
  return std::nullopt;
}

TEST(Catalog, EveryNumberOrChoiceOptionIsDeclaredWithItsRangeAndRefusedOutsideItBeforeAnythingIsBuilt) {
  const Problem problems[] = {read("worlds/seed004.json"), read("worlds/car_park.json"),
                              read("arms/two_link_points.json"), read("worlds/sphere_world.json")};
  std::size_t refused = 0;
  for (const PlannerListing& planner : planner_catalog()) {
    const Problem* problem = nullptr;
    for (const Problem& p : problems)
      if (!problem && planner_for_or_null(planner, p)) problem = &p;
    ASSERT_NE(problem, nullptr) << planner.name << " plans none of the test's problems";
    for (const OptionInfo& option : planner.options) {
      SCOPED_TRACE(planner.name + " " + option.name);
      const bool number = option.kind.find("number") != std::string::npos;
      EXPECT_TRUE(!number || option.range) << option.kind;
      EXPECT_TRUE(option.kind.find('|') == std::string::npos || !option.choices.empty()) << option.kind;
      if (!option.range) continue;
      const auto value = outside(*option.range);
      if (!value) continue;
      const std::string assignment = "option " + option.name + "=" + *value + ": ";
      try {
        make_planner(planner.name, *problem, {{option.name, *value}});
        ADD_FAILURE() << "accepted " << assignment;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(assignment), std::string::npos) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 50u);
}

TEST(Catalog, ListsEverySpacesPlannersOnceEachInTheRegistriesOrder) {
  const auto& catalog = planner_catalog();
  std::size_t expected = planners<TranslatingRobot>().entries().size() + planners<RotatingRobot>().entries().size() +
                         planners<SteeredCar>().entries().size() + planners<PlanarArm>().entries().size() +
                         planners<RoundRobot>().entries().size();
  ASSERT_EQ(catalog.size(), expected);
  EXPECT_EQ(catalog.front().name, "visibility");
  EXPECT_EQ(catalog.front().kind, "World");
  const PlannerListing& last_arm = catalog[expected - planners<RoundRobot>().entries().size() - 1];
  EXPECT_EQ(last_arm.kind, "Arm");
  EXPECT_EQ(last_arm.file, "ARM.json");
  EXPECT_EQ(catalog.back().name, "tangent-bug");  // the round robot's, listed last
  EXPECT_EQ(catalog.back().space, RoundRobot::description);
  EXPECT_TRUE(catalog.back().plans_round_worlds);
}

}  // namespace
}  // namespace polyplan
