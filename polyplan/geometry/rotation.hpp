#pragma once
// Exact rotations of the plane and the poses of a rotating robot.
//
// A rotation is a pair of rationals (sin, cos) with sin² + cos² = 1 exactly: every rotated point
// of a rational point is rational, and distances to the centre are kept exactly, so a rotated
// robot is an exact polygon and its C-space is exact. Most angles have no such pair; the one used
// is within a stated tolerance of the requested angle, from the Pythagorean triple of a rational
// approximation of tan(θ/2) (Canny, Donald and Ressler's construction, as in CGAL's
// rational_rotation_approximation, with continued fractions: rotation.cpp says why).
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/world.hpp>

#include <string>

namespace polyplan {

inline constexpr double pi = 3.14159265358979323846;

// How far an exact rotation may be from the angle asked for, in radians.
inline constexpr double rotation_tolerance_radians = 1e-10;

struct Rotation {
  Rational sin{0}, cos{1};
  friend bool operator==(const Rotation& a, const Rotation& b) { return a.sin == b.sin && a.cos == b.cos; }
};

// An exact rotation within rotation_tolerance_radians of `degrees`, counter-clockwise, with small
// numbers (denominators about 1/tolerance). Multiples of 90 degrees are exact. Throws std::invalid_argument for an
// angle that is not finite.
Rotation exact_rotation(double degrees);

// The angle of an exact rotation in degrees, in (-180, 180] (atan2 of the doubles: what it is,
// to double precision).
double degrees_of(const Rotation& rotation);

// The counter-clockwise angle from `from` to `to` in (-180, 180] degrees (the short way).
double turn_degrees(const Rotation& from, const Rotation& to);

ExactPoint rotate(const ExactPoint& p, const Rotation& rotation);

// The robot turned about its reference point (the origin of its frame).
Robot rotated(const Robot& robot, const Rotation& rotation);

// The largest distance of a robot vertex from its reference point (0 for a point robot): how far
// a turn of one radian moves any point of the robot, at most. In doubles.
double robot_radius(const Robot& robot);

// A rotating robot's configuration: its reference point's exact position and its exact rotation.
// `degrees` is the rotation's angle as the planner names it (a layer's nominal angle, or the
// query's theta); the exact rotation is within rotation_tolerance_radians of it.
struct Pose {
  ExactPoint position;
  Rotation rotation;
  double degrees = 0;
  friend bool operator==(const Pose& a, const Pose& b) {
    return a.position == b.position && a.rotation == b.rotation && a.degrees == b.degrees;
  }
};

// "5°", "-22.5°": an angle as messages name it (the shortest text that reads back the same).
std::string angle_text(double degrees);

// "[3/2, 7, 60°]": a pose as messages name it.
std::string to_string(const Pose& pose);

}  // namespace polyplan
