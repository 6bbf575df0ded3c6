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

void append_segment(SteeringPath& path, Steer steer, int gear, double length, double radius, bool gears, bool snap) {
  if (!(length > 0) || (snap && length < 1e-14 * radius)) return;
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

namespace {
std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}
}  // namespace

void require_steerable(const CarPose& from, const CarPose& to, double radius, const char* what) {
  constexpr double least_radius = 1e-100, greatest = 1e100;
  if (!(radius >= least_radius && radius <= greatest))
    throw InputError(std::string(what) + ": turning radius " + shown(radius) +
                     ": expected a number in [1e-100, 1e+100] (the supported range)");
  for (const auto& [name, pose] : {std::pair{"from", &from}, std::pair{"to", &to}}) {
    if (!std::isfinite(pose->theta))
      throw InputError(std::string(what) + ": the pose '" + name + "' has a heading that is not finite");
    if (!(std::abs(pose->x) <= greatest && std::abs(pose->y) <= greatest))
      throw InputError(std::string(what) + ": the pose '" + name + "' (" + shown(pose->x) + ", " + shown(pose->y) +
                       "): expected coordinates of at most 1e+100 in magnitude (the supported range)");
  }
}

bool reaches(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius) {
  const double coordinates = std::max({std::abs(from.x), std::abs(from.y), std::abs(to.x), std::abs(to.y)});
  return goal_miss(path, from, to, radius) <= 1e-9 * path.length() + 1e-13 * coordinates;
}

void throw_unreachable(const CarPose& from, const CarPose& to, double radius, const char* what) {
  throw InputError(std::string(what) + ": no curve of turning radius " + shown(radius) + " from (" + shown(from.x) +
                   ", " + shown(from.y) + ") to (" + shown(to.x) + ", " + shown(to.y) +
                   ") ends on the goal in double precision: the radius is too large against the distance "
                   "between the poses");
}

}  // namespace polyplan
