#include <polyplan/rotation/pose_path_check.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/input_error.hpp>
#include <polyplan/geometry/turn_enclosure.hpp>
#include <polyplan/rotation/rotation_layers.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace polyplan {
namespace {

// The exact rotations a turn from `from` to `to` (the short way) is proved through: its ends and,
// between them, one every rotation_check_step degrees at most.
std::vector<Rotation> turn_stops(const Rotation& from, const Rotation& to) {
  const double turn = turn_degrees(from, to), start = degrees_of(from);
  const auto parts = static_cast<std::size_t>(std::ceil(std::abs(turn) / rotation_check_step));
  std::vector<Rotation> stops{from};
  for (std::size_t k = 1; k < parts; ++k) stops.push_back(exact_rotation(start + turn * double(k) / double(parts)));
  stops.push_back(to);
  return stops;
}

// Why the turn on the spot at `at` is not proved free; empty when it is.
std::string turn_blocked(const World& world, const ExactPoint& at, const Rotation& from, const Rotation& to) {
  if (std::abs(turn_degrees(from, to)) >= 180) return "a half turn on the spot has no short way: turn in two steps";
  const std::vector<Rotation> stops = turn_stops(from, to);
  for (std::size_t k = 0; k + 1 < stops.size(); ++k) {
    const CSpace enclosure(world_with_robot(world, turn_enclosure(world.robot, stops[k], stops[k + 1])));
    if (const PathCheck c = check_path(enclosure, {at}); !c.valid) return c.reason;
  }
  return {};
}

}  // namespace

PathCheck check_pose_path(const World& world, const std::vector<Pose>& path) {
  std::unique_ptr<CSpace> turned;  // the C-space at the rotation of the step before, kept while it holds
  std::optional<Rotation> turned_by;
  const std::size_t steps = std::max<std::size_t>(path.size(), 2) - 1;  // one pose: a step to itself
  for (std::size_t i = 0; i < steps; ++i) {
    const Pose& a = path[i];
    const Pose& b = path[std::min(i + 1, path.size() - 1)];
    const std::string step =
        "step " + std::to_string(i) + " (pose " + std::to_string(i) + " to " + std::to_string(i + 1) + ")";
    if (a.rotation == b.rotation) {
      if (!turned_by || !(*turned_by == a.rotation)) {
        turned = std::make_unique<CSpace>(world_with_robot(world, rotated(world.robot, a.rotation)));
        turned_by = a.rotation;
      }
      if (PathCheck c = check_path(*turned, {a.position, b.position}); !c.valid)
        return {false, step + ": " + c.reason, i};
    } else if (a.position == b.position) {
      if (const std::string why = turn_blocked(world, a.position, a.rotation, b.rotation); !why.empty())
        return {false, step + ", a turn on the spot, is not proved free: " + why, i};
    } else {
      return {false, step + " moves and turns at once: the robot translates at one rotation or turns on the spot", i};
    }
  }
  return {};
}

Pose pose_from_row(const std::vector<Rational>& row, const std::string& where) {
  if (row.size() == 3) {
    const double degrees = to_double(row[2]);
    return {{row[0], row[1]}, exact_rotation(degrees), degrees};
  }
  if (row.size() != 4)
    throw InputError(where + ": " + std::to_string(row.size()) +
                     " numbers: a pose is (x, y, degrees) or (x, y, sin, cos)");
  const Rotation r{row[2], row[3]};
  if (r.sin * r.sin + r.cos * r.cos != 1)
    throw InputError(where + ": sin and cos with sin² + cos² ≠ 1: not an exact rotation");
  return {{row[0], row[1]}, r, degrees_of(r)};
}

}  // namespace polyplan
