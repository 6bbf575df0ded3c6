#pragma once
// Motions between two configurations: every joint turns the short way round at a constant rate
// (seed 001's interpolation), and the motion is valid when every configuration along it is free,
// checked at a stated angular resolution.
//
// The samples of the motion from → to are `from` itself, then k−1 interpolated configurations,
// then `to` itself (bit for bit: the path a planner returns begins and ends at the exact values it
// was given), k+1 in all, with k = max(1, ceil(max_i angular_distance(from_i, to_i) / resolution)),
// so consecutive samples differ by at most `resolution` radians in every joint (up to rounding).
// A joint exactly a half turn from its goal turns counter-clockwise (signed_angle_difference's +π),
// so such a motion and its reverse sweep different half circles.
#include <polyplan/arm/angles.hpp>
#include <polyplan/arm/arm_collision.hpp>

#include <cstddef>
#include <vector>

namespace polyplan {

// k above (the number of steps). Throws std::invalid_argument when the sizes differ, an angle is
// not finite, the resolution is not positive and finite, or k would exceed 10^9.
std::size_t motion_step_count(const JointAngles& from, const JointAngles& to, double resolution);

// The k+1 samples above.
std::vector<JointAngles> motion_samples(const JointAngles& from, const JointAngles& to, double resolution);

// Whether every sample is free, checked in order from `from` to `to`, stopping at the first one
// that is not (each counts in checker.checks()). No allocation per sample.
bool motion_is_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to, double resolution);

}  // namespace polyplan
