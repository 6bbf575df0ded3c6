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
//   inverse_kinematics  any arm: the closed form where one applies, numeric_ik otherwise, and the
//                   joint limits kept by every solution
//   hand_reach      whether a point lies in the annulus an n-link arm's hand reaches, decided exactly
//                   (on the lengths and the point as a file or the command line wrote them, when known)
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
  std::size_t outside_limits = 0;  // solutions inverse_kinematics dropped for the joint limits
  bool every_solution = false;     // a closed form's: the solutions are all there are
};

// Where a target lies against the annulus an arm's hand reaches about its base,
// r_min ≤ |target| ≤ r_max with r_max = Σ l and r_min = max(0, 2·max l − Σ l) (the longest link
// folded back over all the others): decided exactly on the rational values of the lengths and the
// target (a double is a rational: no epsilon). The squared margins are exact, then rounded once.
struct HandReach {
  double inner = 0, outer = 0;  // r_min and r_max, rounded to nearest
  int outer_side = 0;           // sign of r_max² − d²: 1 strictly within the outer circle, 0 on it, −1 beyond
  int inner_side = 0;           // sign of d² − r_min²: 1 strictly beyond the inner circle, 0 on it, −1 within
  double outer_margin = 0, inner_margin = 0;  // r_max² − d² and d² − r_min²
  bool reachable() const { return outer_side >= 0 && inner_side >= 0; }
};
HandReach exact_hand_reach(const std::vector<Rational>& links, const ExactPoint& target);
// On the doubles' values.
HandReach hand_reach(const std::vector<double>& links, Eigen::Vector2d target);
// On the values as written where they are known: arm.exact_links, and exact_target (the target as
// written; its double is `target`), each falling back to the doubles.
HandReach hand_reach(const Arm& arm, Eigen::Vector2d target, const std::optional<ExactPoint>& exact_target);

// exact_target: the target as written (a decimal 0.3 is 3/10), whose double is `target`; with the
// arm's exact_links it decides the annulus's boundary on the values the user wrote.
IkAnswer two_link_ik(const Arm& arm, Eigen::Vector2d target,
                     const std::optional<ExactPoint>& exact_target = std::nullopt);
IkAnswer three_link_ik(const Arm& arm, Eigen::Vector2d target, double orientation);

struct IkOptions {
  std::optional<double> orientation;              // radians; none: the hand's position only
  std::vector<std::pair<double, double>> limits;  // per joint [lo, hi] radians; empty: none
  std::size_t seeds = 8;                          // starting configurations tried
  std::size_t iterations = 100;                   // per seed, damped least squares
  double tolerance = 1e-9;                        // end-effector error accepted
  double refine_to = 0;  // above 0: iterate on towards this smaller error while the steps still reduce it
  bool all = false;      // every distinct solution the seeds find, not only the first
  std::optional<ExactPoint> exact_target;  // the target as written (two_link_ik's boundary)
  std::uint64_t seed = 1;
};

IkAnswer numeric_ik(const Arm& arm, Eigen::Vector2d target, const IkOptions& options = {});

// Any arm: two_link_ik for two links without an orientation, three_link_ik for three with one (every
// solution of the closed forms, whatever options.all says), numeric_ik otherwise; then only the
// solutions within options.limits are kept (within_joint_limits), the others counted in
// outside_limits — found is false, and why_not says so, when none is left.
IkAnswer inverse_kinematics(const Arm& arm, Eigen::Vector2d target, const IkOptions& options = {});

// Whether every angle lies within its joint's [lo, hi] read round the circle (some a + 2πk in it),
// to 1e-12 rad: the rounding of a whole-turn shift. No limits (empty) holds every configuration.
bool within_joint_limits(const JointAngles& angles, const std::vector<std::pair<double, double>>& limits);

// FABRIK (Aristidou & Lasenby) from `start`: the joints' positions pulled to the target and back
// to the base until the hand is within the tolerance; link lengths kept to 1e-12. An unreachable
// target gives the arm stretched straight towards it.
IkSolution fabrik(const Arm& arm, Eigen::Vector2d target, const JointAngles& start, std::size_t iterations = 200,
                  double tolerance = 1e-9);

// The absolute angle of the last link: θ1 + … + θn, in (−π, π].
double end_orientation(const JointAngles& angles);

}  // namespace polyplan
