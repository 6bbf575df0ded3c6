// Steering across the whole supported range (turning radii and coordinates from 1e-100 to 1e100):
// the curves of a pose pair scaled by s are the curves scaled by s, a straight stays a straight
// whatever the radius, and what lies outside the range is refused with the range.
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>
#include <polyplan/geometry/input_error.hpp>
#include "car/steering_test_poses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polyplan {
namespace {

using Shortest = SteeringPath (*)(const CarPose&, const CarPose&, double);
const struct Model {
  const char* name;
  Shortest shortest;
} kModels[] = {{"dubins", shortest_dubins_path}, {"reeds-shepp", shortest_reeds_shepp_path}};

CarPose scaled(const CarPose& p, double s) { return {p.x * s, p.y * s, p.theta}; }

TEST(SteeringRange, ACurveScaledIsTheScaledCurve) {
  for (const Model& model : kModels)
    for (double s : {1e-90, 1e-40, 1e40, 1e90})
      for (const test::PosePair& p : test::random_pose_pairs(300, 44)) {
        SCOPED_TRACE(std::string(model.name) + " " + p.name + " scaled by " + std::to_string(s));
        const SteeringPath unit = model.shortest(p.from, p.to, p.radius);
        const SteeringPath big = model.shortest(scaled(p.from, s), scaled(p.to, s), p.radius * s);
        EXPECT_NEAR(big.length() / s, unit.length(), 1e-9 * unit.length());
        EXPECT_LE(goal_miss(big, scaled(p.from, s), scaled(p.to, s), p.radius * s), 1e-9 * big.length());
      }
}

TEST(SteeringRange, AStraightAheadIsAStraightWhateverTheRadius) {
  for (const Model& model : kModels)
    for (double radius : {1e-100, 1.0, 1e12, 1e100}) {
      SCOPED_TRACE(std::string(model.name) + " radius " + std::to_string(radius));
      const SteeringPath path = model.shortest({0, 0, 0}, {28, 0, 0}, radius);
      ASSERT_EQ(path.segments.size(), 1u) << path.word;
      EXPECT_EQ(path.segments[0].steer, Steer::straight);
      EXPECT_EQ(path.length(), 28);
    }
}

TEST(SteeringRange, AHugeRadiusTurnsOnLoopsThatReachTheGoal) {
  // A quarter turn 10 ahead with a radius of 1e12: nothing near 10 long does it.
  for (const Model& model : kModels) {
    const CarPose from{0, 0, 0}, to{10, 0, M_PI / 2};
    const SteeringPath path = model.shortest(from, to, 1e12);
    EXPECT_GT(path.length(), 1e12) << model.name << " " << path.word;
    EXPECT_LE(goal_miss(path, from, to, 1e12), 1e-9 * path.length()) << model.name;
  }
}

TEST(SteeringRange, ATinyRadiusTurnsOnTheSpot) {
  for (const Model& model : kModels) {
    const CarPose from{-1e100, -1e100, 0}, to{1e100, 1e100, M_PI / 2};
    const SteeringPath path = model.shortest(from, to, 1e-100);
    EXPECT_NEAR(path.length(), std::hypot(2e100, 2e100), 1e-12 * path.length()) << model.name << " " << path.word;
  }
}

TEST(SteeringRange, ANearlyEqualHeadingIsALoopForwardOnlyAndAWiggleWithReverse) {
  const CarPose from{0, 0, 0}, to{0, 0, 1e-11};
  const SteeringPath loop = shortest_dubins_path(from, to, 1);
  EXPECT_NEAR(loop.length(), 2 * M_PI, 1e-9);
  EXPECT_LE(goal_miss(loop, from, to, 1), 1e-9 * loop.length());
  const SteeringPath wiggle = shortest_reeds_shepp_path(from, to, 1);
  EXPECT_NEAR(wiggle.length(), 1e-11, 1e-15);
  EXPECT_LE(goal_miss(wiggle, from, to, 1), 1e-9 * wiggle.length());
}

TEST(SteeringRange, OutsideTheRangeIsRefusedWithTheRange) {
  for (const Model& model : kModels) {
    for (double radius : {1e-101, 1e101, 0.0, -1.0, std::nan("")}) try {
        model.shortest({0, 0, 0}, {1, 0, 0}, radius);
        ADD_FAILURE() << model.name << " radius " << radius;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected a number in [1e-100, 1e+100]"), std::string::npos) << e.what();
      }
    try {
      model.shortest({0, 0, 0}, {1e101, 0, 0}, 1);
      ADD_FAILURE() << model.name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("at most 1e+100 in magnitude"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace polyplan
