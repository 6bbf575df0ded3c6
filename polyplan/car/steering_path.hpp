#pragma once
// A steered car's path between two poses: arcs at full lock and straights, each driven forward or
// in reverse — the curves of Dubins (forward only) and of Reeds and Shepp (either gear), and the
// poses along them. The reference point is the rear-axle centre; the car turns about a centre
// `radius` to its left or right.
#include <polyplan/geometry/car_pose.hpp>

#include <string>
#include <vector>

namespace polyplan {

struct SteeringPath {
  // The segments' letters: "LSR" for a Dubins path; "L+R-L+" for a Reeds–Shepp path (each
  // letter with its gear). A segment of no length is left out: straight ahead is "S".
  std::string word;
  std::vector<SteeringSegment> segments;
  double length() const;
};

// Appends a segment driving `length` (its letter to the word, with the gear's sign when `gears`),
// unless it is shorter than 1e-14 turning radii: the rounding of a segment that is 0 exactly.
void append_segment(SteeringPath& path, Steer steer, int gear, double length, double radius, bool gears);

// The pose reached after driving the first `s` of `path` (clamped to [0, length]) from `start`,
// turning with `radius`.
CarPose pose_along(const SteeringPath& path, const CarPose& start, double radius, double s);
CarPose end_pose(const SteeringPath& path, const CarPose& start, double radius);

// How far the path's end misses `to`: the larger of the distance between the reference points and
// the heading error (wrapped to [0, pi]) times `radius`, so both are lengths.
double goal_miss(const SteeringPath& path, const CarPose& from, const CarPose& to, double radius);

// `radius` and both poses finite, radius > 0; InputError naming `what` otherwise.
void require_steerable(const CarPose& from, const CarPose& to, double radius, const char* what);

}  // namespace polyplan
