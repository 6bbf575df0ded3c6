// The front door of a polygon robot that translates (docs/architecture.md "The front door").
#include <polyplan/registry/detail/world_door.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>

namespace polyplan::detail {
namespace {

class TranslatingDoor final : public WorldDoor<TranslatingRobot> {
 public:
  // A polygon world: among discs or walls the round robot's door plans (round_space.cpp).
  bool plans(const Problem& problem) const override {
    const World* world = problem.world();
    return world && !world->robot.car && round_features(*world).empty();
  }
  const CSpace& built_from(const Problem& problem) const override { return problem.cspace(); }

  Query query(const Problem&, const QuerySpec& spec) const override {
    Query q = world_query(spec);
    for (const auto& [what, theta] : {std::pair{"start", q.start_theta}, std::pair{"goal", q.goal_theta}})
      if (turned(theta))
        throw InputError(std::string(what) +
                         ": an orientation other than 0 degrees; a translating planner moves the robot as "
                         "its file draws it: use the planner \"" +
                         planners<RotatingRobot>().default_planner() + "\"");
    return q;
  }

  void require_plannable(const Problem& problem, std::string_view planner) const override {
    require_plannable_queries(*problem.world(), &problem.cspace(), planner);
  }

  // A world whose queries turn the robot goes to the rotation space; one that changes, to the
  // first planner that follows its changes.
  std::string default_planner(const Problem& problem) const override {
    const World& world = *problem.world();
    if (turns_the_robot(world)) return planners<RotatingRobot>().default_planner();
    return default_planner_for_changes(world, planners<TranslatingRobot>().default_planner());
  }

  std::size_t columns(const Problem&) const override { return 2; }
};

}  // namespace

template <>
const SpaceDoor<TranslatingRobot>& space_door<TranslatingRobot>() {
  static const TranslatingDoor door;
  return door;
}

}  // namespace polyplan::detail
