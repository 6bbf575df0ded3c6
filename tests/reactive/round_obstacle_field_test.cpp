// What repels a disc robot among discs, walls, polygons and bounds: each distance is the one its
// rim keeps from the obstacle (hand-computed below), the nearest point lies on the grown obstacle,
// and a disc's and disc bounds' curvature makes the Hessian the gradient's derivative.
#include "world_fixtures.hpp"

#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/reactive/round_obstacle_field.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace polyplan {
namespace {

// A robot of radius 1/2 in the box [-10, 10]²: a disc of radius 1 at the origin, a wall bent at
// (5, 1), a square of side 2 at (−7, −7).
const char* const round_box = R"({"bounds": [-10, -10, 10, 10],
  "discs": [{"center": [0, 0], "radius": 1}],
  "walls": [[[5, -1], [5, 1], [7, 2]]],
  "obstacles": [[[-8, -8], [-6, -8], [-6, -6], [-8, -6]]],
  "robot": {"disc": 0.5}})";

TEST(RoundObstacleField, EachDistanceIsTheOneTheRobotsRimKeeps) {
  const World world = test::world_from(round_box);
  const RoundWorld round(world);
  const RoundObstacleField field(round);
  // Discs, walls, polygons, then the box's left, right, bottom and top.
  const std::vector<NearestPoint> at_3_4 = field.nearest_points({3, 4});
  ASSERT_EQ(at_3_4.size(), 7u);
  EXPECT_DOUBLE_EQ(at_3_4[0].distance, 3.5);  // |(3, 4)| − 1 − 0.5
  EXPECT_NEAR(at_3_4[0].at.x, 0.9, 1e-12);    // 1.5 along (0.6, 0.8)
  EXPECT_NEAR(at_3_4[0].at.y, 1.2, 1e-12);
  EXPECT_TRUE(at_3_4[0].at_corner);
  EXPECT_DOUBLE_EQ(at_3_4[0].curve_offset, 1.5);
  EXPECT_NEAR(at_3_4[1].distance, std::sqrt(13.0) - 0.5, 1e-12);          // the wall's bend (5, 1)
  EXPECT_NEAR(at_3_4[2].distance, std::sqrt(81.0 + 100.0) - 0.5, 1e-12);  // the square's corner (−6, −6)
  EXPECT_DOUBLE_EQ(at_3_4[3].distance, 12.5);                             // x = −9.5: the box shrunk by 0.5
  EXPECT_DOUBLE_EQ(at_3_4[4].distance, 6.5);
  EXPECT_DOUBLE_EQ(at_3_4[5].distance, 13.5);
  EXPECT_DOUBLE_EQ(at_3_4[6].distance, 5.5);
  EXPECT_DOUBLE_EQ(field.clearance({3, 4}), 3.1055512754639891);  // the wall: √13 − 0.5
  // Inside an edge: the wall's first piece x = 5 seen from (4, 0), the square's side x = −6 from
  // (−5, −7); both half a unit nearer for the robot's rim.
  const std::vector<NearestPoint> at_4_0 = field.nearest_points({4, 0});
  EXPECT_DOUBLE_EQ(at_4_0[1].distance, 0.5);
  EXPECT_FALSE(at_4_0[1].at_corner);
  EXPECT_DOUBLE_EQ(at_4_0[1].at.x, 4.5);
  EXPECT_DOUBLE_EQ(field.nearest_points({-5, -7})[2].distance, 0.5);
}

TEST(RoundObstacleField, DiscBoundsRepelFromInsideAndAPointRobotKeepsTheWholeDistance) {
  const World world = test::world_from(R"({"bounds": {"center": [0, 0], "radius": 10},
    "discs": [{"center": [0, 0], "radius": 1}]})");
  const RoundWorld round(world);
  const std::vector<NearestPoint> n = RoundObstacleField(round).nearest_points({3, 4});
  ASSERT_EQ(n.size(), 2u);
  EXPECT_DOUBLE_EQ(n[0].distance, 4);  // |(3, 4)| − 1, no rim
  EXPECT_DOUBLE_EQ(n[1].distance, 5);  // 10 − |(3, 4)|
  EXPECT_NEAR(n[1].at.x, 6, 1e-12);
  EXPECT_NEAR(n[1].at.y, 8, 1e-12);
  EXPECT_DOUBLE_EQ(n[1].curve_offset, -10);
}

// The Hessian of each term against central differences of its gradient: a disc grown by the
// robot curves about its centre, disc bounds the other way.
TEST(RoundObstacleField, TheRepulsionsHessianIsItsGradientsDerivative) {
  const World world = test::world_from(R"({"bounds": {"center": [0, 0], "radius": 4},
    "discs": [{"center": [1, 0], "radius": 1}], "robot": {"disc": 0.5}})");
  const RoundWorld round(world);
  const RoundObstacleField field(round);
  const RepulsiveParameters repulsion{1, 2};
  const auto gradient = [&](Vec2 q, std::size_t term) {
    return repulsive_potential(q, field.nearest_points(q)[term], repulsion).gradient;
  };
  const Vec2 q{-1.2, 1.1};  // within Q* of both
  const double h = 1e-6;
  for (std::size_t term : {0u, 1u}) {
    SCOPED_TRACE(term);
    const Hessian2 hessian = repulsive_potential(q, field.nearest_points(q)[term], repulsion).hessian;
    const Vec2 xp = gradient({q.x + h, q.y}, term), xm = gradient({q.x - h, q.y}, term);
    const Vec2 yp = gradient({q.x, q.y + h}, term), ym = gradient({q.x, q.y - h}, term);
    EXPECT_NEAR(hessian.xx, (xp.x - xm.x) / (2 * h), 1e-4);
    EXPECT_NEAR(hessian.xy, (yp.x - ym.x) / (2 * h), 1e-4);
    EXPECT_NEAR(hessian.yy, (yp.y - ym.y) / (2 * h), 1e-4);
  }
}

}  // namespace
}  // namespace polyplan
