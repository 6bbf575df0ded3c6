#include <polyplan/registry/world_queries.hpp>

#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/rotation/rotation_layers.hpp>

#include <stdexcept>
#include <string>

namespace polyplan {

void require_planner_for_robot(const World& world, std::string_view planner) {
  if (world.robot.car)
    throw InputError(world.source + ": robot.car: the robot steers like a car, and the planner " + std::string(planner) +
                     " neither steers nor keeps to a turning radius; this build has no car planner yet");
}

void require_plannable_queries(const World& world, const CSpace* cspace, std::string_view planner) {
  require_planner_for_robot(world, planner);
  if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal and no queries to plan");
  // A rotating robot's planner builds the C-space of each orientation itself.
  if (planners<RotatingRobot>().find(planner)) return require_free_poses(world);
  if (turns_the_robot(world))
    throw InputError(world.source + ": a start or goal has an orientation other than 0 degrees ([x, y, theta]); the planner " +
                     std::string(planner) +
                     " only translates the robot as its file draws it: use --planner rotation (Python: planner=\"rotation\")");
  if (!cspace) throw std::logic_error("require_plannable_queries: a translating planner's check needs the world's C-space");
  cspace->require_free_queries();
}

}  // namespace polyplan
