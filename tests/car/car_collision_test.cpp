// The car's certified segments: exact at contact (touching is refused, a hair's clearance is
// proved), arcs whose middle sweeps into an obstacle refused though both ends are free, loose
// enclosures split until they prove a near miss, the bounds holding the whole sweep, and on random segments among
// random obstacles every segment certified free passes the independent sampling oracle.
#include "car/car_fixtures.hpp"
#include "car/car_path_check.hpp"

#include <polyplan/car/car_collision.hpp>
#include <polyplan/geometry/rotation.hpp>

#include <gtest/gtest.h>

#include <random>

namespace polyplan {
namespace {

// A 2×2 square car centred on its reference point, radius 2, and a wall from x = 5.
World walled(const std::string& wall_x) {
  return test::car_world(R"({"obstacles": [[[)" + wall_x + R"(, -10], [9, -10], [9, 10], [)" + wall_x + R"(, 10]]],
    "robot": {"parts": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]], "car": {"turning_radius": 2, "reverse": true}},
    "start": [0, 0, 0], "goal": [1, 0, 0]})");
}

TEST(CarCollision, AStraightToTheWallIsRefusedAndOneAHairShortIsProved) {
  const CarCollision collision(walled("5"));
  const CarPose start{0, 0, 0};
  EXPECT_TRUE(collision.segment_is_free(start, {Steer::straight, 1, 3.9}));
  EXPECT_TRUE(collision.segment_is_free(start, {Steer::straight, 1, 4 - 1e-6}));    // no epsilon of 1e-6 decides
  EXPECT_FALSE(collision.segment_is_free(start, {Steer::straight, 1, 4}));          // touching: refused
  EXPECT_FALSE(collision.segment_is_free(start, {Steer::straight, 1, 4 - 1e-14}));  // within the margin: refused
  EXPECT_FALSE(collision.segment_is_free(start, {Steer::straight, 1, 4.5}));
  EXPECT_TRUE(collision.segment_is_free(start, {Steer::straight, -1, 40}));  // backward, away from the wall
  EXPECT_EQ(collision.pose_blocked_by({4.5, 0, 0}), std::optional<std::string>("obstacles[0]"));
  EXPECT_EQ(collision.pose_blocked_by({0, 0, 0}), std::nullopt);
  EXPECT_TRUE(collision.body_holds_reference_point());
}

// A 0.2 square car on a half turn left about (0, 2): its outermost corner passes x = 2.1024 at
// mid-turn (distance √(0.1² + 2.1²) from the centre), where both ends are far from x > 2.
World post(const std::string& x) {
  return test::car_world(R"({"obstacles": [[[)" + x + R"(, 1.5], [3, 1.5], [3, 2.5], [)" + x +
                         R"(, 2.5]]],
    "robot": {"parts": [[[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]]], "car": {"turning_radius": 2, )"
                         R"("reverse": false}},
    "start": [0, 0, 0], "goal": [0, 4, 180]})");
}

TEST(CarCollision, AnArcThatSweepsIntoAnObstacleMidwayIsRefused) {
  const SteeringSegment half_turn{Steer::left, 1, 2 * pi};
  const CarCollision blocked(post("2.1"));
  EXPECT_TRUE(blocked.pose_is_free({0, 0, 0}));
  EXPECT_TRUE(blocked.pose_is_free({0, 4, pi}));
  EXPECT_FALSE(blocked.segment_is_free({0, 0, 0}, half_turn));
}

TEST(CarCollision, ALooseEnclosureIsSplitUntilItProvesANearMiss) {
  // 0.0076 to spare: a 45° piece's apexes stand 0.17 beyond the circle, so the arc is halved.
  const CarCollision near(post("2.11"));
  const std::size_t before = near.enclosures_tested();
  EXPECT_TRUE(near.segment_is_free({0, 0, 0}, {Steer::left, 1, 2 * pi}));
  EXPECT_GT(near.enclosures_tested() - before, 4u) << "four 45° pieces alone cannot prove it";
  const CarCollision far(post("2.5"));
  EXPECT_TRUE(far.segment_is_free({0, 0, 0}, {Steer::left, 1, 2 * pi}));
}

TEST(CarCollision, TheBoundsHoldTheWholeSweep) {
  const CarCollision collision(test::car_world(R"({"bounds": [0, 0, 10, 10], "obstacles": [],
    "robot": {"parts": [[[-0.01, -0.01], [0.01, -0.01], [0.01, 0.01], [-0.01, 0.01]]], "car": {"turning_radius": 1}},
    "start": [5, 5, 0], "goal": [6, 5, 0]})"));
  EXPECT_TRUE(collision.body_holds_reference_point());
  EXPECT_TRUE(collision.segment_is_free({5, 5, 0}, {Steer::left, 1, 2 * pi}));      // a full circle of radius 1
  EXPECT_FALSE(collision.segment_is_free({5, 5, 0}, {Steer::straight, 1, 4.995}));  // the body reaches x = 10.005
  EXPECT_TRUE(collision.segment_is_free({5, 5, 0}, {Steer::straight, 1, 4.98}));
  EXPECT_FALSE(collision.segment_is_free({5, 8.5, 0}, {Steer::left, 1, pi}));  // the circle reaches y = 10.5
  EXPECT_EQ(collision.pose_blocked_by({10, 5, 0}), std::optional<std::string>("the bounds"));
}

TEST(CarCollision, EverySegmentCertifiedFreeAmongRandomObstaclesPassesTheSamplingOracle) {
  std::mt19937_64 random(2026);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  std::string obstacles;
  for (int i = 0; i < 25; ++i) {
    const double x = uniform(0, 28), y = uniform(0, 28), w = uniform(0.3, 2.5), h = uniform(0.3, 2.5);
    obstacles += std::string(i ? ", " : "") + "[[" + std::to_string(x) + ", " + std::to_string(y) + "], [" +
                 std::to_string(x + w) + ", " + std::to_string(y) + "], [" + std::to_string(x + w) + ", " +
                 std::to_string(y + h) + "], [" + std::to_string(x) + ", " + std::to_string(y + h) + "]]";
  }
  const World world = test::car_world(R"({"bounds": [0, 0, 30, 30], "obstacles": [)" + obstacles +
                                      R"(],
    "robot": {"parts": [[[-0.5, -0.4], [1.5, -0.4], [1.8, 0], [1.5, 0.4], [-0.5, 0.4]]], )"
                                      R"("car": {"turning_radius": 1.5, "reverse": true}},
    "start": [1, 1, 0], "goal": [2, 1, 0]})");
  const CarCollision collision(world);
  std::size_t free = 0, refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const CarPose start{uniform(1, 29), uniform(1, 29), uniform(-pi, pi)};
    const SteeringSegment segment{static_cast<Steer>("LSR"[trial % 3]), trial % 2 ? 1 : -1, uniform(0, 6)};
    if (!collision.segment_is_free(start, segment)) {
      ++refused;
      continue;
    }
    ++free;
    const CarState path[] = {{start, {}}, {drive(start, segment, 1.5, segment.length), segment}};
    if (auto hit = test::sampled_car_overlap(world, {path[0], path[1]})) ADD_FAILURE() << "certified, yet " << *hit;
  }
  EXPECT_GT(free, 300u);
  EXPECT_GT(refused, 300u);
}

}  // namespace
}  // namespace polyplan
