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

namespace {

// One segment's first `distance` driven from `pose`: a straight moves along the heading; an arc
// turns about the centre `radius` to the left (or right) of the car.
CarPose drive(const CarPose& pose, const SteeringSegment& segment, double radius, double distance) {
  const double signed_distance = segment.gear * distance;
  CarPose next = pose;
  switch (segment.steer) {
    case Steer::straight:
      next.x += signed_distance * std::cos(pose.theta);
      next.y += signed_distance * std::sin(pose.theta);
      break;
    case Steer::left: {
      const double turn = signed_distance / radius;
      next.x += radius * (std::sin(pose.theta + turn) - std::sin(pose.theta));
      next.y += radius * (std::cos(pose.theta) - std::cos(pose.theta + turn));
      next.theta += turn;
      break;
    }
    case Steer::right: {
      const double turn = signed_distance / radius;
      next.x += radius * (std::sin(pose.theta) - std::sin(pose.theta - turn));
      next.y += radius * (std::cos(pose.theta - turn) - std::cos(pose.theta));
      next.theta -= turn;
      break;
    }
  }
  return next;
}

}  // namespace

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
  if (!(std::isfinite(radius) && radius > 0))
  {
    char text[32];
    std::snprintf(text, sizeof text, "%g", radius);
    throw InputError(std::string(what) + ": turning radius " + text + ": expected a positive finite number");
  }
  for (const auto& [name, pose] : {std::pair{"from", &from}, std::pair{"to", &to}})
    if (!std::isfinite(pose->x) || !std::isfinite(pose->y) || !std::isfinite(pose->theta))
      throw InputError(std::string(what) + ": the pose '" + name + "' is not finite");
}

}  // namespace polyplan
