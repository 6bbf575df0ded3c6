#include <polyplan/geometry/car_pose.hpp>

#include <cmath>

namespace polyplan {

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

std::string segment_word(const SteeringSegment& segment) {
  return {static_cast<char>(segment.steer), segment.gear > 0 ? '+' : '-'};
}

}  // namespace polyplan
