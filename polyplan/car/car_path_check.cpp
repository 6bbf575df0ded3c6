#include <polyplan/car/car_path_check.hpp>

#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/car_motion.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace polyplan {
namespace {

// The shortest segment of `radius` from `a` whose end arrives at `b`. Left forward and right in
// reverse turn the heading counter-clockwise, right forward and left in reverse clockwise.
std::optional<SteeringSegment> segment_between(const CarPose& a, const CarPose& b, double radius) {
  std::optional<SteeringSegment> best;
  const auto consider = [&](Steer steer, int gear, double length) {
    const SteeringSegment s{steer, gear, length};
    if (arrives(drive(a, s, radius, length), b, radius) && (!best || length < best->length)) best = s;
  };
  const double distance = std::hypot(b.x - a.x, b.y - a.y);
  consider(Steer::straight, 1, distance);
  consider(Steer::straight, -1, distance);
  const double counter_clockwise = std::fmod(std::fmod(b.theta - a.theta, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
  const double clockwise = counter_clockwise > 0 ? 2 * M_PI - counter_clockwise : 0;
  consider(Steer::left, 1, radius * counter_clockwise);
  consider(Steer::right, -1, radius * counter_clockwise);
  consider(Steer::right, 1, radius * clockwise);
  consider(Steer::left, -1, radius * clockwise);
  return best;
}

}  // namespace

std::vector<CarPathSegment> car_segments_through(const std::vector<CarPose>& poses, double radius) {
  if (poses.size() == 1) return {{poses.front(), {Steer::straight, 1, 0}}};  // standing still: the pose checked
  std::vector<CarPathSegment> segments;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const auto s = segment_between(poses[i], poses[i + 1], radius);
    if (!s)
      throw InputError("path[" + std::to_string(i) + "] to path[" + std::to_string(i + 1) +
                       "]: no straight and no arc of the car's turning radius " + std::to_string(radius) +
                       " joins these poses (a car's path gives a pose at the end of each segment it drives)");
    segments.push_back({poses[i], *s});
  }
  return segments;
}

PathCheck check_car_path(const World& world, const std::vector<CarPathSegment>& path) {
  const CarCollision car(world);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const CarPathSegment& s = path[i];
    const std::string name = "segment " + std::to_string(i) + " (" + segment_word(s.segment) + ")";
    if (i > 0) {
      const CarPathSegment& before = path[i - 1];
      const CarPose end = drive(before.start, before.segment, car.turning_radius(), before.segment.length);
      if (!arrives(end, s.start, car.turning_radius()))
        return {false,
                name + " does not start where the segment before it ends: a car neither jumps nor slides sideways", i};
    }
    if (s.segment.gear < 0 && !car.reverse())
      return {false, name + " drives in reverse, and the car only drives forward", i};
    if (!car.pose_is_free(s.start))
      return {false,
              name + " starts where the car's body is not free (" +
                  car.pose_blocked_by(s.start).value_or("too near to prove") + ")",
              i};
    if (!car.segment_is_free(s.start, s.segment))
      return {false,
              name +
                  " is not proved free: the body it sweeps meets an obstacle or the bounds, or comes too near to prove",
              i};
  }
  return {};
}

}  // namespace polyplan
