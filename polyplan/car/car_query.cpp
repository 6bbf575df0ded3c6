#include <polyplan/car/car_query.hpp>

#include <polyplan/geometry/rotation.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace polyplan {

CarPose start_pose(const Query& query) {
  return {to_double(query.start.x), to_double(query.start.y), query.start_theta.value_or(0) * pi / 180};
}
CarPose goal_pose(const Query& query) {
  return {to_double(query.goal.x), to_double(query.goal.y), query.goal_theta.value_or(0) * pi / 180};
}

std::string to_string(const CarPose& pose) {
  char text[96];
  std::snprintf(text, sizeof text, "[%.10g, %.10g, ", pose.x, pose.y);
  return text + angle_text(heading_degrees(pose)) + "]";
}

std::optional<std::string> car_query_not_free(const CarCollision& car, const Query& query) {
  for (const auto& [what, pose] : {std::pair{"start", start_pose(query)}, std::pair{"goal", goal_pose(query)}})
    if (const auto hit = car.pose_blocked_by(pose))
      return std::string("the ") + what + " " + to_string(pose) + " is not free: the car's body " +
             (*hit == "the bounds" ? "leaves the bounds" : "meets " + *hit);
  return std::nullopt;
}

std::optional<std::string> car_query_unreachable(const HolonomicDistance* holonomic, const Query& query) {
  if (!holonomic || !holonomic->separated(query.start, query.goal)) return std::nullopt;
  return "start and goal lie in different components of the free space of the car's reference point, which lies in its "
         "body: "
         "no motion of the car joins them";
}

CarSamplingBox car_sampling_box(const World& world) {
  if (world.bounds)
    return {to_double(world.bounds->xmin), to_double(world.bounds->ymin), to_double(world.bounds->xmax),
            to_double(world.bounds->ymax)};
  CarSamplingBox b{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  const auto add = [&](const ExactPoint& p) {
    b = {std::min(b.xmin, to_double(p.x)), std::min(b.ymin, to_double(p.y)), std::max(b.xmax, to_double(p.x)),
         std::max(b.ymax, to_double(p.y))};
  };
  for (const auto& o : world.obstacles)
    for (const ExactPoint& p : o.outer) add(p);
  for (const ExactPoint& p : query_points(world)) add(p);
  const double grow = 0.1 * std::hypot(b.xmax - b.xmin, b.ymax - b.ymin) + 1;
  return {b.xmin - grow, b.ymin - grow, b.xmax + grow, b.ymax + grow};
}

}  // namespace polyplan
