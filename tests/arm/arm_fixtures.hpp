#pragma once
// Small helpers shared by the arm/ tests (and the arm reader's): arms, obstacles and data files
// described inline.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/geometry/arm_problem.hpp>
#include <polyplan/geometry/rational.hpp>
#include <polyplan/geometry/world.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace polyplan::test {

inline constexpr double kPi = two_pi / 2;

// The next double above / below x: "one ulp beside".
inline double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
inline double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

inline Ring ring(const std::vector<std::pair<double, double>>& points) {
  Ring r;
  for (auto [x, y] : points) r.push_back({Rational(x), Rational(y)});
  return r;
}

// The axis-aligned square of half-side `half` centred at (cx, cy).
inline PolygonWithHoles square(double half, double cx = 0, double cy = 0) {
  return {ring({{cx - half, cy - half}, {cx + half, cy - half}, {cx + half, cy + half}, {cx - half, cy + half}}), {}};
}

inline Arm arm_of(std::vector<double> links, double width = 0, bool self_collision = false) {
  Arm arm;
  arm.links = std::move(links);
  arm.link_width = width;
  arm.self_collision = self_collision;
  return arm;
}

// Whether every configuration at samples `resolution` radians apart (arm/arm_motion.hpp's
// motion_samples) is free: the sampled check certification replaced, kept here to show what it
// misses and to check certificates independently with dense samples.
inline bool samples_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to, double resolution) {
  for (const JointAngles& q : motion_samples(from, to, resolution))
    if (!checker.is_free(q)) return false;
  return true;
}

// A shipped arm file: data/arms/<name>.
inline std::string arm_data_file(const std::string& name) { return std::string(POLYPLAN_SOURCE_DIR) + "/data/arms/" + name; }

// A returned arm path checked independently of its planner: it begins at the query's start and
// ends at its goal (normalised), and every motion is free at samples 0.01° apart (of the joint
// that turns most) and certified again. Returns the sum of the joints' short-way turns.
inline double expect_arm_path_free(const ArmCollisionChecker& checker, const ArmQuery& q, const std::vector<JointAngles>& path) {
  if (path.size() < 2) {
    ADD_FAILURE() << "a path of " << path.size() << " configurations";
    return 0;
  }
  for (std::size_t j = 0; j < q.start.size(); ++j) {
    EXPECT_EQ(path.front()[j], normalize_angle(q.start[j]));
    EXPECT_EQ(path.back()[j], normalize_angle(q.goal[j]));
  }
  const double dense = 0.01 * two_pi / 360;
  double length = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    for (const JointAngles& c : motion_samples(path[k], path[k + 1], dense))
      if (!checker.is_free(c)) {
        ADD_FAILURE() << "a configuration between path[" << k << "] and path[" << k + 1 << "] collides";
        break;
      }
    EXPECT_TRUE(certify_motion(checker, path[k], path[k + 1]).free()) << "motion " << k;
    length += total_angular_distance(path[k], path[k + 1]);
  }
  return length;
}

}  // namespace polyplan::test
