// The potential of the potential-field planner: gradients and Hessians against finite
// differences, continuity across d* and Q*, and the course's planning problem set's infinite wall — one critical point,
// a minimum at x ≈ −0.68233, whose Hessian is the seed's own formula.
#include <polyplan/reactive/potential_field.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace polyplan {
namespace {

const std::vector<Vec2> pentagon{{0, 0}, {3, -1}, {4, 2}, {1.5, 4}, {-1, 2}};

Potential total(Vec2 q, Vec2 goal, const AttractiveParameters& a, const RepulsiveParameters& r,
                const std::vector<Vec2>& ring) {
  return attractive_potential(q, goal, a) + repulsive_potential(q, nearest_on_ring(q, ring), r);
}

// Central differences of the value give the gradient, of the gradient the Hessian, at points
// around the pentagon (within Q* of it, so both terms act) for quadratic and conic attraction.
TEST(PotentialField, GradientAndHessianAreTheDerivatives) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-3, 7);
  const Vec2 goal{6, 5};
  const RepulsiveParameters r{0.8, 2.5};
  int checked = 0;
  for (const double d_star : {0.0, 3.0}) {
    const AttractiveParameters a{1.3, d_star};
    while (checked < (d_star == 0 ? 200 : 400)) {
      const Vec2 q{coordinate(random), coordinate(random)};
      const NearestPoint n = nearest_on_ring(q, pentagon);
      if (n.distance < 0.2 || n.distance > 2.4) continue;  // away from the obstacle and from Q*'s seam
      // Inside the pentagon is no place to ask: a point whose nearest edge is on the far side of it.
      const bool inside = q.x > -1 && q.x < 4 && q.y > -1 && q.y < 4 && n.distance < 1.2;
      if (inside) continue;
      const double d_goal = std::hypot(q.x - goal.x, q.y - goal.y);
      if (std::abs(d_goal - d_star) < 0.01) continue;
      ++checked;
      const double h = 1e-6;
      const Potential p = total(q, goal, a, r, pentagon);
      const Potential px = total({q.x + h, q.y}, goal, a, r, pentagon),
                      mx = total({q.x - h, q.y}, goal, a, r, pentagon);
      const Potential py = total({q.x, q.y + h}, goal, a, r, pentagon),
                      my = total({q.x, q.y - h}, goal, a, r, pentagon);
      const double scale = 1 + std::abs(p.gradient.x) + std::abs(p.gradient.y);
      EXPECT_NEAR(p.gradient.x, (px.value - mx.value) / (2 * h), 1e-5 * scale);
      EXPECT_NEAR(p.gradient.y, (py.value - my.value) / (2 * h), 1e-5 * scale);
      const double hscale = 1 + std::abs(p.hessian.xx) + std::abs(p.hessian.yy) + std::abs(p.hessian.xy);
      EXPECT_NEAR(p.hessian.xx, (px.gradient.x - mx.gradient.x) / (2 * h), 1e-4 * hscale);
      EXPECT_NEAR(p.hessian.xy, (py.gradient.x - my.gradient.x) / (2 * h), 1e-4 * hscale);
      EXPECT_NEAR(p.hessian.yy, (py.gradient.y - my.gradient.y) / (2 * h), 1e-4 * hscale);
    }
  }
}

TEST(PotentialField, ValueAndGradientAreContinuousAcrossDStarAndQStar) {
  const Vec2 goal{0, 0};
  const AttractiveParameters a{2, 1.5};
  for (const double side : {-1e-9, 1e-9}) {
    const Potential p = attractive_potential({1.5 + side, 0}, goal, a);
    EXPECT_NEAR(p.value, 0.5 * 2 * 1.5 * 1.5, 1e-8);
    EXPECT_NEAR(p.gradient.x, 2 * 1.5, 1e-8);
  }
  // At Q* the repulsion fades to nothing, value and gradient alike.
  const RepulsiveParameters r{3, 2};
  const Potential inside = repulsive_potential({0, 2 - 1e-9}, NearestPoint{2 - 1e-9, {0, 0}, true}, r);
  const Potential outside = repulsive_potential({0, 2 + 1e-9}, NearestPoint{2 + 1e-9, {0, 0}, true}, r);
  EXPECT_NEAR(inside.value, 0, 1e-15);
  EXPECT_NEAR(inside.gradient.y, 0, 1e-8);
  EXPECT_EQ(outside.value, 0);
  EXPECT_EQ(outside.gradient.y, 0);
  // The conic potential has no gradient at its point, and pulls with ζ everywhere else.
  EXPECT_EQ(attractive_potential(goal, goal, {1, 0}).gradient.x, 0);
  EXPECT_NEAR(std::hypot(attractive_potential({3, 4}, goal, {1.5, 0}).gradient.x,
                         attractive_potential({3, 4}, goal, {1.5, 0}).gradient.y),
              1.5, 1e-12);
}

// The course's planning problem set, problem 1: a point robot left of a wall at x = 0 (here a rectangle whose far ends
// lie far beyond Q*), the goal at (2, 0), conic attraction ζ = 1, repulsion η = 1, Q* = 1.
TEST(PotentialField, SeedTwosInfiniteWallHasOneMinimumAtMinus068233) {
  const std::vector<Vec2> wall{{0, -1000}, {1, -1000}, {1, 1000}, {0, 1000}};
  const Vec2 goal{2, 0};
  const AttractiveParameters a{1, 0};
  const RepulsiveParameters r{1, 1};
  const auto at = [&](double x) { return total({x, 0}, goal, a, r, wall); };
  // The gradient along the axis left of the wall changes sign once.
  int changes = 0;
  double previous = at(-3).gradient.x;
  for (double x = -3; x < -1e-3; x += 1e-3) {
    const double g = at(x).gradient.x;
    changes += (g > 0) != (previous > 0);
    previous = g;
    EXPECT_EQ(at(x).gradient.y, 0);  // symmetric about the axis
  }
  EXPECT_EQ(changes, 1);
  double x = -0.7;
  for (int i = 0; i < 50; ++i) x -= at(x).gradient.x / at(x).hessian.xx;  // Newton on the axis
  EXPECT_NEAR(x, -0.68233, 1e-5);
  EXPECT_NEAR(at(x).gradient.x, 0, 1e-12);
  // The seed's second derivative along x: 1/x⁴ − 2(−1/x − 1)/x³.
  EXPECT_NEAR(at(x).hessian.xx, 1 / std::pow(x, 4) - 2 * (-1 / x - 1) / std::pow(x, 3), 1e-9);
  EXPECT_STREQ(critical_point_kind(at(x).hessian), "minimum");
}

TEST(PotentialField, HessiansAreClassifiedByTheirEigenvalues) {
  EXPECT_STREQ(critical_point_kind({2, 0, 1}), "minimum");
  EXPECT_STREQ(critical_point_kind({-2, 0, -1}), "maximum");
  EXPECT_STREQ(critical_point_kind({1, 2, 1}), "saddle");  // eigenvalues 3 and −1
  EXPECT_STREQ(critical_point_kind({1, 1, 1}), "degenerate");
  const Eigenvalues e = eigenvalues({1, 2, 1});
  EXPECT_DOUBLE_EQ(e.smaller, -1);
  EXPECT_DOUBLE_EQ(e.larger, 3);
}

TEST(PotentialField, TheNearestPointOfARingIsACornerOrInsideAnEdge) {
  const NearestPoint edge = nearest_on_ring({2, -3}, std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  EXPECT_DOUBLE_EQ(edge.distance, 3);
  EXPECT_FALSE(edge.at_corner);
  const NearestPoint corner = nearest_on_ring({7, 8}, std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  EXPECT_DOUBLE_EQ(corner.distance, 5);
  EXPECT_TRUE(corner.at_corner);
  EXPECT_THROW(nearest_on_ring({0, 0}, std::vector<Vec2>{}), std::invalid_argument);
}

}  // namespace
}  // namespace polyplan
