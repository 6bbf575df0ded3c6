// The front door of a point, disc or translating polygon robot among discs, walls and polygons
// (docs/architecture.md "The front door"): the worlds with round things and thin walls
// (World::round_features), which the translating robot's door leaves to it; their C-space is
// geometry/round_cspace.hpp's. A planner of polygon worlds alone is refused such a world, naming
// what it has (world_queries.hpp).
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/detail/space_door.hpp>
#include <polyplan/registry/detail/world_door.hpp>
#include <polyplan/registry/registry.hpp>
#include <polyplan/registry/world_queries.hpp>

namespace polyplan::detail {
namespace {

class RoundDoor final : public WorldDoor<RoundRobot> {
 public:
  bool plans(const Problem& problem) const override {
    const World* world = problem.world();
    return world && !world->robot.car && !round_features(*world).empty();
  }
  const RoundWorld& built_from(const Problem& problem) const override { return problem.round_world(); }

  Query query(const Problem&, const QuerySpec& spec) const override {
    Query q = world_query(spec);
    for (const auto& [what, theta] : {std::pair{"start", q.start_theta}, std::pair{"goal", q.goal_theta}})
      if (turned(theta))
        throw InputError(std::string(what) + ": an orientation; among discs and walls a robot translates only");
    return q;
  }

  // Every start and goal free, as the translating robot's door checks its C-space's.
  void require_plannable(const Problem& problem, std::string_view planner) const override {
    const World& world = *problem.world();
    require_planner_for_robot(world, planner);
    if (world.queries.empty()) throw InputError(world.source + ": world: no start/goal and no queries to plan");
    for (const Query& q : world.queries)
      for (const auto& [what, p] : {std::pair{".start", &q.start}, std::pair{".goal", &q.goal}})
        if (auto why = problem.round_world().config_not_free(*p))
          throw InputError(world.source + ": " + q.name + what + ": " + *why);
  }

  // A world that changes goes to the first planner that follows the changes, as a polygon world does.
  std::string default_planner(const Problem& problem) const override {
    return default_planner_for_changes(*problem.world(), planners<RoundRobot>().default_planner());
  }
  std::size_t columns(const Problem&) const override { return 2; }
};

}  // namespace

template <>
const SpaceDoor<RoundRobot>& space_door<RoundRobot>() {
  static const RoundDoor door;
  return door;
}

}  // namespace polyplan::detail
