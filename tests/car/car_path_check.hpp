#pragma once
// An independent re-check of a car's path, by dense sampling in doubles: each segment is driven
// again from its start pose with kinematics written here (not the library's drive()), every
// hundredth of a turning radius, and the body placed there must stay in the bounds and share no
// more area with an obstacle than rounding (rotation/pose_motion_check.hpp's clipping oracle: no
// CGAL, no enclosure). Sampling can miss an overlap thinner than a step: a test oracle, never a
// certificate — the check the hidden program makes.
#include "rotation/pose_motion_check.hpp"

#include <polyplan/geometry/car_pose.hpp>
#include <polyplan/geometry/world.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::test {

// The pose after `s` of a segment from `p` (the reference point on a circle about the turning
// centre, or along the heading), for radius `r`.
inline CarPose driven_by_hand(const CarPose& p, const SteeringSegment& segment, double r, double s) {
  const double signed_s = segment.gear * s;
  if (segment.steer == Steer::straight)
    return {p.x + signed_s * std::cos(p.theta), p.y + signed_s * std::sin(p.theta), p.theta};
  const double side = segment.steer == Steer::left ? 1 : -1;
  const double cx = p.x - side * r * std::sin(p.theta), cy = p.y + side * r * std::cos(p.theta);
  const double turn = side * signed_s / r;
  const double dx = p.x - cx, dy = p.y - cy;
  return {cx + std::cos(turn) * dx - std::sin(turn) * dy, cy + std::sin(turn) * dx + std::cos(turn) * dy,
          p.theta + turn};
}

// The first sampled pose along `path` where the body overlaps an obstacle or leaves the bounds,
// described; nullopt when every sample is free. Also checks that each segment, driven by hand,
// arrives where the next entry says (within 1e-9 relative).
inline std::optional<std::string> sampled_car_overlap(const World& world, const std::vector<CarState>& path) {
  using namespace pose_check_detail;
  const double r = world.robot.car->turning_radius;
  std::vector<Pose> corners;
  for (const CarState& s : path) corners.push_back(Pose{{Rational(s.pose.x), Rational(s.pose.y)}, {}, 0});
  const SampledWorld sampled(world, corners);
  const auto at = [&](const CarPose& p) { return overlap_at(sampled, Sample{p.x, p.y, p.theta * 180 / pi}); };
  if (!path.empty())
    if (auto hit = at(path[0].pose)) return "the start: " + *hit;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const SteeringSegment& seg = path[i].arrival;
    const int n = std::max(1, static_cast<int>(std::ceil(seg.length / (0.01 * r))));
    for (int k = 1; k <= n; ++k) {
      const CarPose p = driven_by_hand(path[i - 1].pose, seg, r, seg.length * k / n);
      if (auto hit = at(p))
        return "segment " + std::to_string(i) + " at " + std::to_string(seg.length * k / n) + " of it: " + *hit;
    }
    const CarPose end = driven_by_hand(path[i - 1].pose, seg, r, seg.length);
    const double scale = 1e-9 * (1 + std::abs(end.x) + std::abs(end.y) + r);
    if (std::hypot(end.x - path[i].pose.x, end.y - path[i].pose.y) > scale ||
        r * std::abs(std::remainder(end.theta - path[i].pose.theta, 2 * pi)) > scale)
      return "segment " + std::to_string(i) + " does not arrive at the pose the path gives next";
  }
  return std::nullopt;
}

}  // namespace polyplan::test
