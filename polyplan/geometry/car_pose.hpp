#pragma once
// A steered car's configurations and the one motion it makes: poses (the rear-axle centre and the
// heading) and segments (an arc at full lock or a straight, forward or in reverse). Plain doubles:
// a car's poses along an arc are transcendental, so no exact representation would survive one
// turn; car/car_collision.hpp says how a segment from a double pose is still proved free.
#include <string>

namespace polyplan {

// A car's pose: the reference point and the heading, radians counter-clockwise from +x.
struct CarPose {
  double x = 0, y = 0, theta = 0;
  friend bool operator==(const CarPose&, const CarPose&) = default;
};

// The heading in degrees, as files and answers give it: one conversion for the program, its JSON
// and Python, so that they print the same numbers.
inline double heading_degrees(const CarPose& pose) { return pose.theta * 57.295779513082320876798; }

enum class Steer : char { left = 'L', straight = 'S', right = 'R' };

struct SteeringSegment {
  Steer steer = Steer::straight;
  int gear = 1;       // +1 forward, -1 reverse
  double length = 0;  // distance driven, >= 0; an arc turns length / radius radians
  friend bool operator==(const SteeringSegment&, const SteeringSegment&) = default;
};

// The pose after driving the first `distance` of `segment` from `pose`, turning with `radius`: a
// straight moves along the heading, an arc turns about the centre `radius` to the car's left (L)
// or right (R).
CarPose drive(const CarPose& pose, const SteeringSegment& segment, double radius, double distance);

// A car's configuration as its planners' paths and trees hold it: the pose, and the one segment
// that drove the car here from the configuration before it (in a path, the previous entry; in a
// tree or a search graph, the edge's first vertex). The path's first entry arrives by a segment of
// no length.
struct CarState {
  CarPose pose;
  SteeringSegment arrival;
  friend bool operator==(const CarState&, const CarState&) = default;
};

// One segment of a car's path as a file gives it: driven from `start` (plan --json's "segments").
struct CarPathSegment {
  CarPose start;
  SteeringSegment segment;
};

// "L+", "S-": a segment's letter and gear.
std::string segment_word(const SteeringSegment& segment);

}  // namespace polyplan
