// The front door of a car steering among polygons.
#include <polyplan/registry/detail/world_door.hpp>

#include <polyplan/car/car_facts.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/registry/registry.hpp>

namespace polyplan::detail {
namespace {

class CarDoor final : public WorldDoor<SteeredCar> {
 public:
  std::string_view file() const override { return "CAR_WORLD.json"; }
  std::string summary(const Facts& facts) const override {
    const auto changes = facts.find(CarFacts::gear_changes);
    return changes ? ", " + std::to_string(*changes) + " gear change(s)" : "";
  }
  bool plans(const Problem& problem) const override { return problem.world() && problem.world()->robot.car; }
  const World& built_from(const Problem& problem) const override { return *problem.world(); }

  Query query(const Problem&, const QuerySpec& spec) const override {
    Query q = world_query(spec);
    if (!q.start_theta || !q.goal_theta)
      throw InputError(std::string(q.start_theta ? "goal" : "start") +
                       ": a car's pose is (x, y, theta), theta in degrees");
    return q;
  }

  std::string default_planner(const Problem&) const override { return planners<SteeredCar>().default_planner(); }
};

}  // namespace

template <>
const SpaceDoor<SteeredCar>& space_door<SteeredCar>() {
  static const CarDoor door;
  return door;
}

}  // namespace polyplan::detail
