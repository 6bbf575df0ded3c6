#include <polyplan/car/car_path_check.hpp>

#include <polyplan/car/car_collision.hpp>
#include <polyplan/car/car_motion.hpp>

#include <string>

namespace polyplan {

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
