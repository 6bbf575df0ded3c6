#include <polyplan/car/steering_path.hpp>

#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace polyplan {

double SteeringPath::length() const {
  double sum = 0;
  for (const SteeringSegment& s : segments) sum += s.length;
  return sum;
}

void append_segment(SteeringPath& path, Steer steer, int gear, double length, double radius, bool gears) {
  if (length < 1e-14 * radius) return;
  path.word += static_cast<char>(steer);
  if (gears) path.word += gear > 0 ? '+' : '-';
  path.segments.push_back({steer, gear, length});
}

CarPose pose_along(const SteeringPath& path, const CarPose& start, double radius, double s) {
  CarPose pose = start;
  double left = std::max(0.0, s);
  for (const SteeringSegment& segment : path.segments) {
    const double part = std::min(left, segment.length);
    pose = drive(pose, segment, radius, part);
    left -= part;
    if (left <= 0) break;
  }
  return pose;
}

CarPose end_pose(const SteeringPath& path, const CarPose& start, double radius) {
  CarPose pose = start;
  for (const SteeringSegment& segment : path.segments) pose = drive(pose, segment, radius, segment.length);
  return pose;
}

double goal_miss(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius) {
  const CarPose end = end_pose(path, from, radius);
  const double heading = std::abs(std::remainder(end.theta - to.theta, 2 * M_PI));
  return std::max(std::hypot(end.x - to.x, end.y - to.y), radius * heading);
}

void require_steerable(const CarPose& from, const CarPose& to, double radius, const char* what) {
  if (!(std::isfinite(radius) && radius > 0)) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", radius);
    throw InputError(std::string(what) + ": turning radius " + text + ": expected a positive finite number");
  }
  for (const auto& [name, pose] : {std::pair{"from", &from}, std::pair{"to", &to}})
    if (!std::isfinite(pose->x) || !std::isfinite(pose->y) || !std::isfinite(pose->theta))
      throw InputError(std::string(what) + ": the pose '" + name + "' is not finite");
}

}  // namespace polyplan
