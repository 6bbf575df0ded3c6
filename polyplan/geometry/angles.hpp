#pragma once
// Joint angles on the circle: normalisation, the short way between two angles, and interpolation
// along it (the course's arm and car planning report's angular_distance / total_angular_distance / interpolation).
//
// Every function that takes angles takes any finite value (7 is the same joint angle as
// 7 − 2π) and throws std::invalid_argument for NaN or infinity: a non-finite angle is a bug
// upstream, and silently mapping it somewhere on the circle would hide it.
#include <polyplan/geometry/arm_problem.hpp>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace polyplan {

// 2π as a double (the one nearest 2π).
inline constexpr double two_pi = 6.283185307179586476925286766559;

namespace detail {
// Exactly half of two_pi, so that the half-turn tests below agree with the normalisation.
inline constexpr double half_turn = two_pi / 2;

inline void require_finite(double a, const char* function) {
  if (!std::isfinite(a)) throw std::invalid_argument(std::string(function) + ": angle is not finite");
}
inline void require_same_size(const JointAngles& a, const JointAngles& b, const char* function) {
  if (a.size() != b.size())
    throw std::invalid_argument(std::string(function) + ": " + std::to_string(a.size()) + " angles against " +
                                std::to_string(b.size()));
}
}  // namespace detail

// Into [0, 2π). fmod is exact; only the shift of a negative remainder rounds, and a remainder so
// small that −r + 2π rounds to 2π is mapped to 0 (the interval is half-open).
inline double normalize_angle(double a) {
  detail::require_finite(a, "normalize_angle");
  double r = std::fmod(a, two_pi);
  if (r < 0) r += two_pi;
  if (r >= two_pi || r == 0) r = 0.0;  // also turns −0.0 into +0.0
  return r;
}

// Every angle into [0, 2π): a configuration as the arm planners give it in their paths.
inline JointAngles normalize_angles(JointAngles angles) {
  for (double& a : angles) a = normalize_angle(a);
  return angles;
}

// The short way from → to, in (−π, π]; a half turn counts as +π. Computed from the normalised
// angles so that huge inputs cannot overflow; both shifts by 2π are exact (Sterbenz).
inline double signed_angle_difference(double from, double to) {
  double d = normalize_angle(to) - normalize_angle(from);  // in (−2π, 2π)
  if (d > detail::half_turn) d -= two_pi;
  else if (d <= -detail::half_turn) d += two_pi;
  return d;
}

// In [0, π]: angular_distance(1, 5) = 2π − 4 = 2.2831853071795862.
inline double angular_distance(double a, double b) { return std::fabs(signed_angle_difference(a, b)); }

// Sum over joints of angular_distance (the course's arm and car planning report's total_angular_distance, the arm
// planners' cost).
inline double total_angular_distance(const JointAngles& a, const JointAngles& b) {
  detail::require_same_size(a, b, "total_angular_distance");
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += angular_distance(a[i], b[i]);
  return sum;
}

// a_i + t·signed_angle_difference(a_i, b_i), normalised, into `out` (resized; no allocation once
// it has the size). Each joint goes its own short way round, as the course's arm and car planning report's
// interpolation does.
inline void interpolate_angles_into(const JointAngles& a, const JointAngles& b, double t, JointAngles& out) {
  detail::require_same_size(a, b, "interpolate_angles");
  if (!std::isfinite(t)) throw std::invalid_argument("interpolate_angles: t is not finite");
  out.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = normalize_angle(a[i] + t * signed_angle_difference(a[i], b[i]));
}

// t = 0 gives normalize(a), t = 1 gives normalize(b) up to rounding.
inline JointAngles interpolate_angles(const JointAngles& a, const JointAngles& b, double t) {
  JointAngles out;
  interpolate_angles_into(a, b, t, out);
  return out;
}

}  // namespace polyplan
