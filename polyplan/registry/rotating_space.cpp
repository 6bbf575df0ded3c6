// The front door of a polygon robot that translates and turns.
#include <polyplan/registry/detail/world_door.hpp>

#include <polyplan/registry/registry.hpp>

namespace polyplan::detail {
namespace {

class RotatingDoor final : public WorldDoor<RotatingRobot> {
 public:
  // Not a world with discs or walls: turning among them is not planned (the round robot's door, or
  // the translating one's refusal, answers those).
  bool plans(const Problem& problem) const override {
    return problem.world() && !problem.world()->robot.car && round_features(*problem.world()).empty();
  }
  const World& built_from(const Problem& problem) const override { return *problem.world(); }
  Query query(const Problem&, const QuerySpec& spec) const override { return world_query(spec); }

  std::string default_planner(const Problem&) const override { return planners<RotatingRobot>().default_planner(); }

  std::string_view steps() const override { return "motion"; }
};

}  // namespace

template <>
const SpaceDoor<RotatingRobot>& space_door<RotatingRobot>() {
  static const RotatingDoor door;
  return door;
}

}  // namespace polyplan::detail
