// The rotation planner on the shipped rotation worlds: no path without turning, a path with it,
// every motion certified again here — each run of translations by the exact path check in a
// C-space the test builds itself for that rotation, each turn by a turn enclosure's C-space the
// test builds itself — and, independently of all exact code, by dense sampling (0.01°) in doubles.
#include <polyplan/geometry/path_check.hpp>
#include <polyplan/geometry/turn_enclosure.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/roadmaps/visibility_graph.hpp>
#include <polyplan/rotation/rotation_facts.hpp>
#include <polyplan/rotation/rotation_planner.hpp>
#include "rotation/pose_motion_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace polyplan {
namespace {

World shipped_world(const std::string& name) {
  return read_world(std::string(POLYPLAN_SOURCE_DIR) + "/data/worlds/" + name + ".json");
}

RotationOptions every(double step) {
  RotationOptions options;
  options.orientations.step = step;
  return options;
}

// Every motion of a found path certified again by the test's own exact constructions, and
// re-checked by sampling.
void expect_certified(const World& world, const Query& query, const PlanReport<Pose>& report) {
  ASSERT_TRUE(report.found) << report.why_not;
  ASSERT_FALSE(report.path.empty());
  EXPECT_TRUE(report.certificate.certified);
  EXPECT_EQ(report.path.front().position, query.start);
  EXPECT_EQ(report.path.back().position, query.goal);
  EXPECT_LE(std::abs(std::remainder(degrees_of(report.path.front().rotation) - query.start_theta.value_or(0), 360)),
            1e-8);
  EXPECT_LE(std::abs(std::remainder(degrees_of(report.path.back().rotation) - query.goal_theta.value_or(0), 360)),
            1e-8);
  if (auto why = test::check_motions_are_single(report.path)) ADD_FAILURE() << *why;
  // The printed angles follow the motion: consecutive ones differ by the turn, the short way.
  EXPECT_EQ(report.path.front().degrees, query.start_theta.value_or(0));
  for (std::size_t i = 1; i < report.path.size(); ++i)
    EXPECT_NEAR(report.path[i].degrees - report.path[i - 1].degrees,
                turn_degrees(report.path[i - 1].rotation, report.path[i].rotation), 1e-6)
        << "motion " << i;

  std::map<std::pair<Rational, Rational>, std::unique_ptr<CSpace>> cspaces;  // by (sin, cos)
  std::vector<World> worlds;
  worlds.reserve(4 * report.path.size());
  const auto cspace_at = [&](const Rotation& r) -> const CSpace& {
    auto& slot = cspaces[{r.sin, r.cos}];
    if (!slot) {
      worlds.push_back(world_with_robot(world, rotated(world.robot, r)));
      slot = std::make_unique<CSpace>(worlds.back());
    }
    return *slot;
  };
  std::vector<ExactPoint> run{report.path.front().position};
  double turned = 0;
  for (std::size_t i = 1; i <= report.path.size(); ++i) {
    const bool turning = i < report.path.size() && !(report.path[i].rotation == report.path[i - 1].rotation);
    if (i == report.path.size() || turning) {
      const PathCheck check = check_path(cspace_at(report.path[i - 1].rotation), run);
      EXPECT_TRUE(check.valid) << "translations before motion " << i << ": " << check.reason;
      run.clear();
    }
    if (i == report.path.size()) break;
    if (turning) {
      const Pose& a = report.path[i - 1];
      const Pose& b = report.path[i];
      const World sweep = world_with_robot(world, turn_enclosure(world.robot, a.rotation, b.rotation));
      EXPECT_NE(CSpace(sweep).locate(b.position).kind, Location::Kind::blocked) << "the turn at motion " << i;
      turned += std::abs(turn_degrees(a.rotation, b.rotation));
    }
    run.push_back(report.path[i].position);
  }
  EXPECT_NEAR(report.facts.at(RotationFacts::rotation), turned, 1e-9);
  if (auto overlap = test::sampled_overlap(world, report.path, 0.01)) ADD_FAILURE() << *overlap;
}

TEST(RotationPlanner, Seed004NeedsATurnAndGetsACertifiedOne) {
  const World world = shipped_world("rotation_seed004");
  const Query& q = world.queries.front();
  // Translating, the robot as drawn (0°) does not get through; the planner without turns neither.
  const CSpace cspace(world);
  EXPECT_FALSE(VisibilityGraph(cspace).plan(q).found);
  RotationOptions one_layer;
  one_layer.orientations.count = 1;
  const auto fixed = RotationPlanner(world, one_layer).plan(q);
  EXPECT_FALSE(fixed.found);
  EXPECT_FALSE(fixed.why_not.empty());

  const auto report = RotationPlanner(world, every(5)).plan(q);
  expect_certified(world, q, report);
  EXPECT_GT(report.facts.at(RotationFacts::rotation), 20);
  EXPECT_GT(report.facts.at(RotationFacts::turn_layers_used), 0);
  EXPECT_LE(report.facts.at(RotationFacts::layers_max_error_radians), rotation_tolerance_radians);
  EXPECT_EQ(report.facts.at(RotationFacts::layers_actual).find("0° is 0°"), 0u)
      << report.facts.at(RotationFacts::layers_actual);
}

TEST(RotationPlanner, ThePianoTurnsInTheCorner) {
  const World world = shipped_world("rotation_piano");
  const Query& q = world.queries.front();
  RotationOptions one_layer;
  one_layer.orientations.count = 1;
  const auto fixed = RotationPlanner(world, one_layer).plan(q);
  EXPECT_FALSE(fixed.found);
  EXPECT_NE(fixed.why_not.find("cannot turn onto the nearest layer"), std::string::npos) << fixed.why_not;

  const auto report = RotationPlanner(world, every(5)).plan(q);
  expect_certified(world, q, report);
  EXPECT_NEAR(report.facts.at(RotationFacts::rotation), 90, 1e-6);  // no more turning than the corner needs

  // Over a range past 180° (where atan2 reads 270° as -90°) the layers are still within tolerance.
  RotationOptions range = every(10);
  range.orientations.to = 270.0;
  const auto ranged = RotationPlanner(world, range).plan(q);
  EXPECT_TRUE(ranged.found);
  EXPECT_EQ(ranged.facts.at(RotationFacts::layers_count), 28);
  EXPECT_LE(ranged.facts.at(RotationFacts::layers_max_error_radians), rotation_tolerance_radians);
}

TEST(RotationPlanner, NeverTurnsInAnExactFitCorridor) {
  const World world = shipped_world("rotation_exact_fit");
  RotationPlanner planner(world, every(5));
  const auto turn = planner.plan(world.queries[0]);  // only a turn would solve it
  EXPECT_FALSE(turn.found);
  EXPECT_EQ(turn.facts.at(RotationFacts::turn_layers_used), 0);
  const auto slide = planner.plan(world.queries[1]);  // along the corridor at 0°
  expect_certified(world, world.queries[1], slide);
  EXPECT_EQ(slide.facts.at(RotationFacts::rotation), 0);
  // Not a single turn layer lets the robot turn anywhere.
  for (const TurnLayer& t : planner.layers().turns()) EXPECT_TRUE(t.corners.empty());
}

TEST(RotationPlanner, RefusesTheTurnThatSampledLayersWouldAllow) {
  // A rod (length 10) at the origin and a small square whose corner is at distance 4.9 at 22.5°:
  // the rod at 0° and at 45° misses it, but sweeping from one to the other hits it. The course
  // checks only the layers; the turn layer is blocked there.
  World world;
  world.bounds = Bounds{Rational(-6), Rational(-6), Rational(6), Rational(6)};
  const double c = 4.9 * std::cos(M_PI / 8), s = 4.9 * std::sin(M_PI / 8);
  const Rational x(static_cast<long>(std::round(c * 1000)), 1000), y(static_cast<long>(std::round(s * 1000)), 1000);
  world.obstacles.push_back(
      {{{x, y}, {x + Rational(1, 5), y}, {x + Rational(1, 5), y + Rational(1, 5)}, {x, y + Rational(1, 5)}}, {}});
  world.obstacle_names.push_back("obstacles[0]");
  world.robot.parts.push_back({{Rational(-5), Rational(-1, 20)},
                               {Rational(5), Rational(-1, 20)},
                               {Rational(5), Rational(1, 20)},
                               {Rational(-5), Rational(1, 20)}});
  RotationOptions options = every(45);
  const RotationLayers layers(world, OrientationSet(options.orientations));
  const ExactPoint origin{Rational(0), Rational(0)};
  EXPECT_NE(layers.layers()[0].cspace->locate(origin).kind, Location::Kind::blocked);
  EXPECT_NE(layers.layers()[1].cspace->locate(origin).kind, Location::Kind::blocked);
  EXPECT_EQ(layers.turns()[0].cspace->locate(origin).kind, Location::Kind::blocked);
  // And a query that would turn there turns elsewhere, certified.
  world.queries.push_back({origin, origin, "start/goal", 0.0, 45.0});
  const auto report = RotationPlanner(world, options).plan(world.queries[0]);
  if (report.found) expect_certified(world, world.queries[0], report);
}

TEST(RotationPlanner, AFinerStepNeverLosesTheShippedWorldsPaths) {
  for (const char* name : {"rotation_seed004", "rotation_piano"}) {
    const World world = shipped_world(name);
    for (double step : {10.0, 5.0, 2.0, 1.0}) {
      SCOPED_TRACE(std::string(name) + " every " + std::to_string(step) + "°");
      RotationOptions options = every(step);
      if (step < 5) {  // the turns these worlds need lie within a quarter turn of the start
        options.orientations.from = std::string(name) == "rotation_piano" ? 0 : -45;
        options.orientations.to = options.orientations.from + 90;
      }
      const auto report = RotationPlanner(world, options).plan(world.queries.front());
      EXPECT_TRUE(report.found) << report.why_not;
      if (step == 1.0) expect_certified(world, world.queries.front(), report);
    }
  }
}

TEST(RotationPlanner, StartsBetweenLayersWithACertifiedTurnOntoTheNearest) {
  World world = shipped_world("rotation_piano");
  world.queries.front().start_theta = 2.5;  // halfway between 0° and 5°: both are nearest
  world.queries.front().goal_theta = 88.0;
  const auto report = RotationPlanner(world, every(5)).plan(world.queries.front());
  expect_certified(world, world.queries.front(), report);
  EXPECT_EQ(report.path.front().degrees, 2.5);
  EXPECT_EQ(report.path.back().degrees, 88.0);
}

TEST(RotationPlanner, TurnsTheShortWayAcrossZeroAndSaysSoInItsAngles) {
  World world;
  world.bounds = Bounds{Rational(0), Rational(0), Rational(20), Rational(20)};
  world.robot.parts.push_back({{Rational(-3), Rational(-1, 2)},
                               {Rational(3), Rational(-1, 2)},
                               {Rational(3), Rational(1, 2)},
                               {Rational(-3), Rational(1, 2)}});
  world.queries.push_back({{Rational(10), Rational(10)}, {Rational(10), Rational(10)}, "start/goal", 350.0, 10.0});
  const auto report = RotationPlanner(world, every(5)).plan(world.queries.front());
  expect_certified(world, world.queries.front(), report);
  EXPECT_NEAR(report.facts.at(RotationFacts::rotation), 20, 1e-6);  // 350 → 360 → 370, not back through 180
  EXPECT_EQ(report.path.front().degrees, 350);
  EXPECT_EQ(report.path.back().degrees, 370);
}

TEST(RotationPlanner, SaysWhichObstacleAStartHitsAtWhichAngle) {
  World world = shipped_world("rotation_piano");
  world.queries.front().start_theta = 90;  // the rod upright in the horizontal corridor
  const auto report = RotationPlanner(world, every(5)).plan(world.queries.front());
  EXPECT_FALSE(report.found);
  EXPECT_NE(report.why_not.find("the start [8, 10, 90°] is not free"), std::string::npos) << report.why_not;
  EXPECT_NE(report.why_not.find("obstacles["), std::string::npos) << report.why_not;
}

TEST(RotationPlanner, TurningCostsTheWeightPerRadian) {
  const World world = shipped_world("rotation_piano");
  RotationOptions options = every(5);
  options.weight = 0;
  const auto free_turns = RotationPlanner(world, options).plan(world.queries.front());
  options.weight = 10;
  const auto dear_turns = RotationPlanner(world, options).plan(world.queries.front());
  ASSERT_TRUE(free_turns.found && dear_turns.found);
  EXPECT_NEAR(free_turns.length, free_turns.facts.at(RotationFacts::translation_length), 1e-9);
  EXPECT_NEAR(dear_turns.length,
              dear_turns.facts.at(RotationFacts::translation_length) +
                  10 * dear_turns.facts.at(RotationFacts::rotation) * M_PI / 180,
              1e-9);
  EXPECT_EQ(RotationPlanner(world, every(5)).rotation_weight(), std::hypot(5.0, 0.5));  // the rod's radius
}

TEST(OrientationSet, CountsStepsAndRanges) {
  EXPECT_EQ(OrientationSet({5, 0, 0, std::nullopt}).size(), 72u);
  EXPECT_EQ(OrientationSet({5, 0, 0, std::nullopt}).turns().size(), 72u);  // the circle closes
  EXPECT_EQ(OrientationSet({5, 0, 0, 90.0}).size(), 19u);
  EXPECT_EQ(OrientationSet({5, 0, 0, 90.0}).turns().size(), 18u);
  EXPECT_EQ(OrientationSet({5, 8, 0, std::nullopt}).step(), 45);
  EXPECT_EQ(OrientationSet({5, 1, 0, std::nullopt}).turns().size(), 0u);
  const OrientationSet circle({10, 0, -30, std::nullopt});
  EXPECT_EQ(circle.normalized(350), -10);
  EXPECT_EQ(circle.layer_at(350), 2u);
  EXPECT_EQ(circle.nearest(-25), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(circle.distance(-30, 320), 10);
  const OrientationSet range({10, 0, 0, 90.0});
  EXPECT_FALSE(range.normalized(180).has_value());
  EXPECT_EQ(range.distance(0, 90), 90);
}

TEST(OrientationSet, RefusesStepsThatDoNotMakeLayers) {
  const auto message = [](OrientationOptions o) {
    try {
      OrientationSet set(o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({0, 0, 0, std::nullopt}).find("expected a number of degrees > 0"), std::string::npos);
  EXPECT_NE(message({-5, 0, 0, std::nullopt}).find("> 0"), std::string::npos);
  EXPECT_NE(message({7, 0, 0, std::nullopt}).find("does not divide the range [0°, 360°]"), std::string::npos);
  EXPECT_NE(message({180, 0, 0, std::nullopt}).find("less than 180° apart"), std::string::npos);
  EXPECT_NE(message({5, 0, 90, 0.0}).find("reversed"), std::string::npos);
  EXPECT_NE(message({5, 0, 0, 400.0}).find("wider than 360°"), std::string::npos);
  EXPECT_NE(message({0.001, 0, 0, std::nullopt}).find("more than 3600 layers"), std::string::npos);
  EXPECT_EQ(message({0.1, 0, 0, std::nullopt}), "no error");  // 3600 steps of a decimal
}

TEST(RotationRegistry, OptionsReachThePlannerAndBadOnesAreNamed) {
  const World world = shipped_world("rotation_piano");
  const auto* entry = planners<RotatingRobot>().find("rotation");
  ASSERT_NE(entry, nullptr);
  const auto report =
      entry->make(world, {{"rotation-step", "10"}, {"rotation-weight", "0"}})->plan(world.queries.front());
  EXPECT_EQ(report.facts.at(RotationFacts::layers_count), 36);
  EXPECT_EQ(report.facts.at(RotationFacts::rotation_weight), 0);
  const auto message = [&](const OptionValues& values) {
    try {
      entry->make(world, values);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{"rotation-step", "7"}}),
            "planner rotation: rotation-step 7° does not divide the range [0°, 360°] (51.42857142857143 steps)");
  EXPECT_EQ(message({{"rotation-step", "x"}}),
            "planner rotation: option rotation-step=x: expected a number of degrees > 0");
  EXPECT_EQ(message({{"rotation-weight", "-1"}}),
            "planner rotation: option rotation-weight=-1: expected a number >= 0 or radius");
}

}  // namespace
}  // namespace polyplan
