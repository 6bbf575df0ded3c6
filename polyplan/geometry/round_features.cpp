// A world's round things and thin walls: what they are called (round_features, for the planners
// that refuse them) and their validation (validate_world calls check_round_features).
#include <polyplan/geometry/world.hpp>

#include <polyplan/geometry/input_error.hpp>

namespace polyplan {
namespace {

[[noreturn]] void fail(const World& world, const std::string& object, const std::string& problem) {
  throw InputError(world.source + ": " + object + ": " + problem);
}

void check_radius(const World& world, const Rational& radius, const std::string& object) {
  if (radius <= 0) fail(world, object, to_string(radius) + ": expected a radius > 0");
}

// Repeated consecutive points carry no shape: dropped; a wall needs two distinct points.
void check_wall(const World& world, Wall& wall, const std::string& object) {
  Wall kept;
  for (const ExactPoint& p : wall)
    if (kept.empty() || !(kept.back() == p)) kept.push_back(p);
  if (kept.size() < 2) fail(world, object, "a wall needs at least two distinct points [[x, y], [x, y], ...]");
  wall = std::move(kept);
}

}  // namespace

std::vector<std::string> round_features(const World& world) {
  std::vector<std::string> features;
  if (!world.discs.empty()) features.emplace_back("discs");
  if (!world.walls.empty()) features.emplace_back("walls");
  if (world.disc_bounds) features.emplace_back("disc bounds");
  if (world.robot.disc) features.emplace_back("a disc robot");
  return features;
}

std::string round_features_text(const World& world) {
  std::string what;
  for (const std::string& feature : round_features(world)) what += (what.empty() ? "" : ", ") + feature;
  return what;
}

void refuse_round_features(const World& world, const std::string& who) {
  const std::string what = round_features_text(world);
  if (!what.empty())
    throw InputError(world.source + ": " + what + ": " + who +
                     " holds polygons and a polygon or point robot only (not discs, walls or a disc robot)");
}

void check_round_features(World& world) {
  for (std::size_t i = 0; i < world.discs.size(); ++i)
    check_radius(world, world.discs[i].radius, "discs[" + std::to_string(i) + "].radius");
  for (std::size_t i = 0; i < world.walls.size(); ++i)
    check_wall(world, world.walls[i], "walls[" + std::to_string(i) + "]");
  if (world.disc_bounds) check_radius(world, world.disc_bounds->radius, "bounds.radius");
  if (world.robot.disc) check_radius(world, *world.robot.disc, "robot.disc");
  if (world.bounds && world.disc_bounds) fail(world, "bounds", "a box or a disc, not both");
  if (world.robot.disc && (!world.robot.parts.empty() || world.robot.car))
    fail(world, "robot", "a disc robot is {\"disc\": r} alone, without parts or car");
}

}  // namespace polyplan
