#pragma once
// Worlds the benchmarks share.
#include <polyplan/geometry/world.hpp>

#include <cmath>
#include <random>

namespace polyplan::bench {

// vertices/4 random convex quadrilaterals on a jittered grid (they never overlap) in a box, with
// coordinates in thousandths: the random worlds of the roadmap benchmarks.
inline World quadrilaterals(int vertices) {
  const int count = vertices / 4, side = static_cast<int>(std::ceil(std::sqrt(count)));
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> jitter(0, 300);  // thousandths of a cell
  World world;
  world.source = "bench";
  world.bounds = Bounds{0, 0, side, side};
  for (int i = 0; i < count; ++i) {
    const int cx = i % side, cy = i / side;
    auto at = [&](int dx, int dy) {
      return ExactPoint{Rational(cx * 1000 + dx + jitter(rng)) / 1000, Rational(cy * 1000 + dy + jitter(rng)) / 1000};
    };
    world.obstacles.push_back({{at(100, 100), at(550, 100), at(550, 550), at(100, 550)}, {}});
    world.obstacle_names.push_back("quad");
  }
  return world;
}

}  // namespace polyplan::bench
