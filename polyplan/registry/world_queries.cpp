#include <polyplan/registry/world_queries.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>
#if POLYPLAN_WITH_CAR
#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/car_query.hpp>
#endif
#if POLYPLAN_WITH_ROTATION
#include <polyplan/rotation/rotation_layers.hpp>
#endif

#include <algorithm>
#include <stdexcept>
#include <string>

namespace polyplan {
namespace {

// A world that changes as the robot drives, for a planner that plans a world standing still:
// its answer would hold for the world of the file's first moment only.
void require_planner_for_changes(const World& world, std::string_view planner) {
  const std::vector<std::string> following = planners_following_changes();
  if (std::find(following.begin(), following.end(), planner) != following.end()) return;
  std::string names;
  for (const std::string& name : following) names += (names.empty() ? "" : ", ") + name;
  throw InputError(world.source + ": " + world.changes.front().name +
                   ": the world changes as the robot drives, and the planner " + std::string(planner) +
                   " plans a world that stands still: use one that follows the changes (" + names + ")");
}

// Discs, walls, disc bounds or a disc robot, for a planner that plans among polygons only.
void require_planner_for_round_features(const World& world, std::string_view planner) {
  const std::string what = round_features_text(world);
  const std::vector<std::string> able = planners_for_round_worlds();
  if (what.empty() || std::find(able.begin(), able.end(), planner) != able.end()) return;
  std::string names;
  for (const std::string& name : able) names += (names.empty() ? "" : ", ") + name;
  throw InputError(world.source + ": " + what + ": the planner " + std::string(planner) +
                   " plans polygon worlds only (polygon obstacles, box bounds, a polygon or point robot)" +
                   (names.empty() ? std::string(": no planner plans with these yet (polyplan check checks a path "
                                                "among them exactly)")
                                  : ": use one that plans with them (" + names + ")"));
}

}  // namespace

std::vector<std::string> planners_for_round_worlds() {
  std::vector<std::string> names;
  const auto add = [&](const auto& registry) {
    for (const auto& entry : registry.entries())
      if (entry.plans_round_worlds && std::find(names.begin(), names.end(), entry.name) == names.end())
        names.push_back(entry.name);
  };
  add(planners<RoundRobot>());
  add(planners<TranslatingRobot>());
  add(planners<RotatingRobot>());
  add(planners<SteeredCar>());
  return names;
}

std::vector<std::string> planners_following_changes() {
  std::vector<std::string> names;
  for (const PlannerEntry<TranslatingRobot>& entry : planners<TranslatingRobot>().entries())
    if (entry.follows_world_changes) names.push_back(entry.name);
  return names;
}

std::string default_planner_for_changes(const World& world, std::string still) {
  if (world.changes.empty()) return still;
  const std::vector<std::string> following = planners_following_changes();
  return following.empty() ? still : following.front();
}

void require_planner_for_robot(const World& world, std::string_view planner) {
  const bool car_planner = planners<SteeredCar>().find(planner) != nullptr;
  const bool world_planner = planners<TranslatingRobot>().find(planner) || planners<RotatingRobot>().find(planner);
  if (world.robot.car) planners<SteeredCar>().require_planners();
  if (world.robot.car && !car_planner)
    throw InputError(world.source + ": robot.car: the robot steers like a car, and the planner " +
                     std::string(planner) + " neither steers nor keeps to a turning radius: use a car planner (" +
                     planners<SteeredCar>().names() + ")");
  if (!world.robot.car && car_planner && !world_planner)
    throw InputError(
        world.source + ": robot: the planner " + std::string(planner) +
        " plans for a car, and this robot has no \"car\": {\"turning_radius\": R, \"reverse\": true|false}");
  if (!world.changes.empty()) require_planner_for_changes(world, planner);
  require_planner_for_round_features(world, planner);
}

#if POLYPLAN_WITH_CAR
// A car's starts and goals: its body inside the bounds and clear of every obstacle.
void require_free_car_poses(const World& world) {
  const CarCollision collision(world);
  for (const Query& q : world.queries)
    if (auto why = car_query_not_free(collision, q)) throw InputError(world.source + ": " + q.name + ": " + *why);
}
#endif

void require_plannable_queries(const World& world, const CSpace* cspace, std::string_view planner) {
  require_planner_for_robot(world, planner);
  if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal and no queries to plan");
#if POLYPLAN_WITH_CAR  // without it, require_planner_for_robot refused the car
  if (world.robot.car) return require_free_car_poses(world);
#endif
#if POLYPLAN_WITH_ROTATION
  // A rotating robot's planner builds the C-space of each orientation itself.
  if (planners<RotatingRobot>().find(planner)) return require_free_poses(world);
#endif
  if (turns_the_robot(world))
    throw InputError(
        world.source + ": a start or goal has an orientation other than 0 degrees ([x, y, theta]); the planner " +
        std::string(planner) +
        " only translates the robot as its file draws it: use --planner rotation (Python: planner=\"rotation\")");
  if (!cspace)
    throw std::logic_error("require_plannable_queries: a translating planner's check needs the world's C-space");
  cspace->require_free_queries();
}

}  // namespace polyplan
