#pragma once
// What `polyplan ik` and Python's polyplan.ik compute alike: the joint angles that put an arm's
// hand at a target (arm/inverse_kinematics.hpp, within the arm file's joint limits), each marked
// free or not of the file's obstacles, optionally only the free ones.
#include <polyplan/arm/inverse_kinematics.hpp>
#include <polyplan/geometry/arm_problem.hpp>

#include <cmath>
#include <optional>
#include <vector>

namespace polyplan {

struct IkRequest {
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  std::optional<ExactPoint> exact_target;     // the target as written, when it was exact text
  std::optional<double> orientation_degrees;  // the last link's absolute angle, reduced already
  bool all = false;                           // every distinct solution found (32 seeds), not only the first
  bool collision_free = false;                // only the solutions free of the obstacles
  std::optional<double> orientation_radians() const {
    return orientation_degrees ? std::optional<double>(*orientation_degrees * M_PI / 180) : std::nullopt;
  }
};

struct IkStudy {
  IkAnswer answer;         // with collision_free and none free: not found, the solutions as they were
  std::vector<bool> free;  // one per solution
};

IkStudy study_ik(const ArmProblem& problem, const IkRequest& request);

}  // namespace polyplan
