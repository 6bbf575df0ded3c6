#pragma once
// Pose pairs the steering tests share: seeded random pairs and the degenerate ones users report
// bugs on (start = goal, goals on a turning circle, headings 0, ±90°, 180°, poses 1e-9 and 1e6
// apart).
#include <polyplan/car/steering_path.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace polyplan::test {

struct PosePair {
  std::string name;
  CarPose from, to;
  double radius;
};

inline std::vector<PosePair> random_pose_pairs(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(-10, 10), heading(-M_PI, M_PI);
  const double radii[] = {1, 0.5, 2, 3.7};
  std::vector<PosePair> pairs;
  for (std::size_t i = 0; i < count; ++i) {
    PosePair p{"random " + std::to_string(i), {}, {}, 0};
    p.from = {coordinate(random), coordinate(random), heading(random)};
    p.to = {coordinate(random), coordinate(random), heading(random)};
    p.radius = radii[random() % 4];
    pairs.push_back(p);
  }
  return pairs;
}

inline std::vector<PosePair> degenerate_pose_pairs() {
  std::vector<PosePair> pairs;
  const double headings[] = {0, M_PI / 2, -M_PI / 2, M_PI, 0.3};
  for (double h : headings) pairs.push_back({"start = goal, heading " + std::to_string(h), {1, 2, h}, {1, 2, h}, 1});
  for (double radius : {1.0, 0.25, 7.5})
    for (double arc : {M_PI / 2, M_PI, 3 * M_PI / 2, 0.1}) {
      // The pose after an exact left (right) arc from (0, 0, 0): on the start's turning circle.
      pairs.push_back({"left circle, arc " + std::to_string(arc),
                       {0, 0, 0},
                       {radius * std::sin(arc), radius * (1 - std::cos(arc)), arc},
                       radius});
      pairs.push_back({"right circle, arc " + std::to_string(arc),
                       {0, 0, 0},
                       {radius * std::sin(arc), -radius * (1 - std::cos(arc)), -arc},
                       radius});
    }
  const double exact_headings[] = {0, M_PI / 2, -M_PI / 2, M_PI};
  for (double a : exact_headings)
    for (double b : exact_headings) {
      pairs.push_back({"ahead", {0, 0, a}, {3, 0, b}, 1});
      pairs.push_back({"behind", {0, 0, a}, {-3, 0, b}, 1});
      pairs.push_back({"beside", {0, 0, a}, {0, 3, b}, 1});
    }
  for (double b : {0.0, M_PI})
    for (auto [dx, dy] : {std::pair{1e-9, 0.0}, std::pair{0.0, 1e-9}, std::pair{-1e-9, 0.0}}) {
      pairs.push_back({"1e-9 apart", {5, 5, 0}, {5 + dx, 5 + dy, b}, 1});
    }
  pairs.push_back({"1e6 apart", {0, 0, 0}, {1e6, 0, 0}, 1});
  pairs.push_back({"1e6 apart, turned", {0, 0, 0.5}, {-1e6, 3e5, -2}, 1});
  pairs.push_back({"1e6 apart, beside", {0, 0, M_PI / 2}, {0, -1e6, M_PI / 2}, 2});
  return pairs;
}

inline std::vector<PosePair> every_test_pair() {
  std::vector<PosePair> pairs = degenerate_pose_pairs();
  for (const PosePair& p : random_pose_pairs(2000, 2026)) pairs.push_back(p);
  return pairs;
}

// How far a path may miss its goal: 1e-9 of the problem's size.
inline double miss_allowed(const PosePair& p) {
  return 1e-9 * std::max({1.0, p.radius, std::hypot(p.to.x - p.from.x, p.to.y - p.from.y)});
}

}  // namespace polyplan::test
