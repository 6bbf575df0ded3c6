#include <polyplan/arm/arm_motion.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace polyplan {

std::size_t motion_step_count(const JointAngles& from, const JointAngles& to, double resolution) {
  if (!(resolution > 0) || !std::isfinite(resolution))
    throw std::invalid_argument("motion: the resolution must be a positive finite angle");
  detail::require_same_size(from, to, "motion");
  double widest = 0;
  for (std::size_t i = 0; i < from.size(); ++i) widest = std::max(widest, angular_distance(from[i], to[i]));
  const double steps = std::ceil(widest / resolution);
  // A billion samples is a resolution error, not a motion anyone means to check.
  if (steps > 1e9) throw std::invalid_argument("motion: the resolution is too fine (over 10^9 samples)");
  return std::max<std::size_t>(1, static_cast<std::size_t>(steps));
}

std::vector<JointAngles> motion_samples(const JointAngles& from, const JointAngles& to, double resolution) {
  const std::size_t k = motion_step_count(from, to, resolution);
  std::vector<JointAngles> samples;
  samples.reserve(k + 1);
  samples.push_back(from);
  for (std::size_t j = 1; j < k; ++j)
    samples.push_back(interpolate_angles(from, to, static_cast<double>(j) / static_cast<double>(k)));
  samples.push_back(to);
  return samples;
}

bool motion_is_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to, double resolution) {
  const std::size_t k = motion_step_count(from, to, resolution);
  if (!checker.is_free(from)) return false;
  JointAngles sample;
  for (std::size_t j = 1; j < k; ++j) {
    interpolate_angles_into(from, to, static_cast<double>(j) / static_cast<double>(k), sample);
    if (!checker.is_free(sample)) return false;
  }
  return checker.is_free(to);
}

}  // namespace polyplan
