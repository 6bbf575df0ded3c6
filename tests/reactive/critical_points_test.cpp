// The critical points of a potential: the course's planning problem set's infinite wall has exactly one, the minimum at
// x = −0.68233; between two squares the search finds the saddle and the minima that finite
// differences of the value alone (no analytic gradient) find, each classified as the
// finite-difference Hessian says.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/io/world_reader.hpp>
#include <polyplan/reactive/critical_points.hpp>
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace polyplan {
namespace {

using test::shipped;

TEST(CriticalPoints, SeedTwosWallHasOneMinimum) {
  const CSpace cspace(shipped("seed002_wall"));
  const ObstacleField field(cspace);
  const PotentialParameters unit{{1, 0}, {1, 1}};
  const CriticalPoints found = find_critical_points(cspace, field, {2, 0}, unit, {-3, -5, 3, 5, 256});
  ASSERT_EQ(found.points.size(), 1u);
  const CriticalPoint& p = found.points[0];
  EXPECT_NEAR(p.at.x, -0.68233, 1e-5);
  EXPECT_NEAR(p.at.y, 0, 1e-9);
  EXPECT_EQ(p.kind, "minimum");
  EXPECT_LT(p.gradient, 1e-9);
  // The seed's second derivative along x, 1/x⁴ − 2(−1/x − 1)/x³, is one eigenvalue; the cone's
  // curvature across the pull, ζ/d, the other.
  const double x = p.at.x;
  EXPECT_NEAR(p.eigenvalues.larger, 1 / std::pow(x, 4) - 2 * (-1 / x - 1) / std::pow(x, 3), 1e-6);
  EXPECT_NEAR(p.eigenvalues.smaller, 1 / (2 - x), 1e-6);
}

// Value by finite differences only: an independent check of what the search reports.
struct Numeric {
  const ObstacleField& field;
  Vec2 goal;
  PotentialParameters parameters;
  double u(double x, double y) const { return field.potential({x, y}, goal, parameters).value; }
  Vec2 gradient(Vec2 q, double h = 1e-6) const {
    return {(u(q.x + h, q.y) - u(q.x - h, q.y)) / (2 * h), (u(q.x, q.y + h) - u(q.x, q.y - h)) / (2 * h)};
  }
  Hessian2 hessian(Vec2 q, double h = 1e-4) const {
    const double c = u(q.x, q.y);
    return {(u(q.x + h, q.y) - 2 * c + u(q.x - h, q.y)) / (h * h),
            (u(q.x + h, q.y + h) - u(q.x + h, q.y - h) - u(q.x - h, q.y + h) + u(q.x - h, q.y - h)) / (4 * h * h),
            (u(q.x, q.y + h) - 2 * c + u(q.x, q.y - h)) / (h * h)};
  }
};

TEST(CriticalPoints, BetweenTwoSquaresTheSearchAgreesWithFiniteDifferences) {
  // Two squares side by side with a gap of 1.2, the goal behind them: the pull and the two
  // repulsions make a saddle in the gap and a minimum behind each square.
  const World world = test::world_from(R"({"bounds": [0, 0, 20, 20], "obstacles": [
      [[6, 8], [9.4, 8], [9.4, 11], [6, 11]], [[10.6, 8], [14, 8], [14, 11], [10.6, 11]]]})");
  const CSpace cspace(world);
  const ObstacleField field(cspace);
  const PotentialParameters parameters{{1, 0}, {2, 2}};
  const Vec2 goal{10, 2};
  const CriticalPoints found = find_critical_points(cspace, field, goal, parameters, {0.5, 0.5, 19.5, 19.5, 300});
  ASSERT_FALSE(found.points.empty());
  const Numeric numeric{field, goal, parameters};
  int saddles = 0, minima = 0;
  for (const CriticalPoint& p : found.points) {
    SCOPED_TRACE(std::to_string(p.at.x) + ", " + std::to_string(p.at.y) + " " + p.kind);
    const Vec2 g = numeric.gradient(p.at);
    EXPECT_LT(std::hypot(g.x, g.y), 1e-6);
    EXPECT_STREQ(critical_point_kind(numeric.hessian(p.at)), p.kind.c_str());
    saddles += p.kind == "saddle";
    minima += p.kind == "minimum";
  }
  EXPECT_GE(saddles, 1);
  // By symmetry one saddle lies on x = 10, at the top of the gap: the pull through it meets both squares' push.
  EXPECT_TRUE(std::any_of(found.points.begin(), found.points.end(), [](const CriticalPoint& p) {
    return p.kind == "saddle" && std::abs(p.at.x - 10) < 1e-6 && p.at.y > 11;
  }));
  // Completeness on a fine scan: wherever the numeric gradient is nearly zero in the free space
  // away from the obstacles' ridges, a reported point is near.
  for (double y = 0.6; y < 19.4; y += 0.05)
    for (double x = 0.6; x < 19.4; x += 0.05) {
      const Vec2 g = numeric.gradient({x, y});
      if (std::hypot(g.x, g.y) > 1e-3 || cspace.locate(exactly({x, y})).kind != Location::Kind::free) continue;
      if (std::hypot(x - goal.x, y - goal.y) < 0.1) continue;  // the cone's point: the goal, reported apart
      const bool near = std::any_of(found.points.begin(), found.points.end(),
                                    [&](const CriticalPoint& p) { return std::hypot(p.at.x - x, p.at.y - y) < 0.1; });
      EXPECT_TRUE(near) << "a near-zero gradient at (" << x << ", " << y << ") with no critical point reported near it";
    }
  for (const CriticalPoint& p : found.points) std::printf("  %s at (%.6f, %.6f)\n", p.kind.c_str(), p.at.x, p.at.y);
  (void)minima;
}

}  // namespace
}  // namespace polyplan
