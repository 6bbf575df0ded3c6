#pragma once
// Inverse kinematics of a planar n-link arm (arm.hpp's conventions): joint angles that put the end
// effector — the end of the last link — at a target point, and for a given end orientation (the
// absolute angle of the last link, θ1 + … + θn) where asked.
//
//   two_link_ik     closed form, both elbows: 2, 1 or 0 solutions for a target strictly inside,
//                   on, or outside the reachable annulus |l1 − l2| ≤ d ≤ l1 + l2, the boundary
//                   decided exactly on the rational values of the lengths and the target (a
//                   double is a rational: no epsilon)
//   three_link_ik   closed form with an end orientation: the wrist by two_link_ik
//   numeric_ik      n links, damped least squares from several seeds, then FABRIK where that
//                   fails; joint limits when given; distinct solutions (angles apart by > 1e-6)
//
// Every solution carries its end-effector error |f(θ) − target|, measured by forward kinematics.
#include <polyplan/arm/arm.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {

struct IkSolution {
  JointAngles angles;  // each in (−π, π]
  double error = 0;    // |end effector − target|
};

struct IkAnswer {
  bool found = false;
  std::vector<IkSolution> solutions;  // when not found: the closest the arm gets (stretched towards the target)
  std::string why_not;
};

IkAnswer two_link_ik(const Arm& arm, Eigen::Vector2d target);
IkAnswer three_link_ik(const Arm& arm, Eigen::Vector2d target, double orientation);

struct IkOptions {
  std::optional<double> orientation;                      // radians; none: the hand's position only
  std::vector<std::pair<double, double>> limits;          // per joint [lo, hi] radians; empty: none
  std::size_t seeds = 8;                                  // starting configurations tried
  std::size_t iterations = 100;                           // per seed, damped least squares
  double tolerance = 1e-9;                                // end-effector error accepted
  bool all = false;                                       // every distinct solution the seeds find, not only the first
  std::uint64_t seed = 1;
};

IkAnswer numeric_ik(const Arm& arm, Eigen::Vector2d target, const IkOptions& options = {});

// FABRIK (Aristidou & Lasenby) from `start`: the joints' positions pulled to the target and back
// to the base until the hand is within the tolerance; link lengths kept to 1e-12. An unreachable
// target gives the arm stretched straight towards it.
IkSolution fabrik(const Arm& arm, Eigen::Vector2d target, const JointAngles& start, std::size_t iterations = 200, double tolerance = 1e-9);

// The absolute angle of the last link: θ1 + … + θn, in (−π, π].
double end_orientation(const JointAngles& angles);

}  // namespace polyplan
