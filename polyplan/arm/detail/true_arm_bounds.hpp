#pragma once
// How far the arm computed in doubles (joint_positions_into, link_outline_into) may lie from the
// true arm: the same link lengths and width (doubles, exact as reals), placed with the real cos
// and sin of the real sums of the angles. An arm certificate is a statement about the true arm
// (docs/certification.md), so every clearance the collision checker reports is the distance it
// measures on the computed arm, bounded from below, minus the radius this gives.
//
// The enclosure is interval arithmetic rounded outward (detail/outward_rounding.hpp), joint by
// joint from the base (exactly at the origin):
//  - heading H_k = [q_0 ± s_0] + … + [q_k ± s_k], every configuration within spread s of q;
//  - the computed heading h_k lies at most d_k from every point of H_k, so cos over H_k lies within
//    d_k + trig_error of the computed cos(h_k) (cos is 1-Lipschitz), and likewise sin;
//  - true joint k+1 ∈ joint k + l_k·(cos, sin): boxes X_k, Y_k; the computed joint's radius is
//    its largest distance to a point of its box, rounded up;
//  - true corners of a w-wide link: true joint ± (w/2)(−sin, cos), boxes too.
// Private to arm/.
#include <polyplan/geometry/arm_problem.hpp>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace polyplan::detail {

// What the certificates assume of libm: |cos(x) − cos x| and |sin(x) − sin x| at most this for
// every double x. glibc documents at most 1 ulp for double cos and sin on x86_64 and aarch64 (its
// manual, "Known Maximum Errors in Math Functions"), which is at most 2^-52 for results in
// [−1, 1]; this is four times that. tests/arm/true_arm_bounds_test.cpp checks it against MPFR.
inline constexpr double trig_error = 0x1p-50;

class TrueArmBounds {
 public:
  explicit TrueArmBounds(const Arm& arm) : arm_(&arm) {}

  // Both functions compute with the processor rounding upward: the caller holds a
  // detail::RoundingUpward (outward_rounding.hpp) around them, once for a whole placement.

  // Encloses the true arm at every configuration within spread[j] radians of q in each joint j
  // (spread empty: q alone), given what joint_positions_into computed for q. Angles and spreads
  // must be finite (spreads not negative).
  void enclose(const JointAngles& q, std::span<const double> spread, const std::vector<double>& headings,
               const std::vector<Eigen::Vector2d>& directions, const std::vector<Eigen::Vector2d>& joints);

  // An upper bound of the distance from any point of the true links[k] to the computed shape:
  // the segment between the computed joints k and k+1 (2 corners given) or link_outline_into's
  // rectangle (4 corners, strictly convex as computed). For a link of width w checked as its
  // segment, w/2 is included.
  double link_radius(std::size_t k, std::span<const Eigen::Vector2d> corners) const;

 private:
  using Range = std::array<double, 2>;  // [lo, hi]
  const Arm* arm_;
  std::vector<Range> x_, y_;                // [k]: true joint k
  std::vector<double> radius_;              // [k]: computed joint k to any point of its box
  std::vector<Range> normal_x_, normal_y_;  // [k]: (w/2)(−sin, cos) of link k's true heading
};

}  // namespace polyplan::detail
