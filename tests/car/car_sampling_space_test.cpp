// The car's sampling space (car/car_sampling_space.hpp): its bound never exceeds the curves'
// length, so the nearest-neighbour answers refined from the positions' index are the true nearest
// by the steering distance — both ways, for a Dubins car (not symmetric) and a Reeds–Shepp car —
// as brute force finds them; a pose part way along a motion lies on it.
#include "car/car_fixtures.hpp"

#include <polyplan/car/car_sampling_space.hpp>
#include <polyplan/sampling/sampling_planner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

namespace polyplan {
namespace {

World open_car_world(bool reverse) {
  World world = test::car_world(R"({"bounds": [0, 0, 30, 20], "obstacles": [[[14, 8], [16, 8], [16, 12], [14, 12]]],
    "robot": {"parts": [[[-0.5, -0.5], [1.5, -0.5], [1.5, 0.5], [-0.5, 0.5]]], "car": {"turning_radius": 2.5, )"
                                R"("reverse": true}},
    "start": [2, 2, 0], "goal": [28, 18, 90]})");
  world.robot.car->reverse = reverse;
  return world;
}

using Coordinates = std::vector<double>;

// The ids of `points` ordered by the space's distance to (or from) `at`.
std::vector<std::size_t> brute_force(const SamplingSpace<SteeredCar>& space, const std::vector<Coordinates>& points,
                                     const Coordinates& at, Toward toward) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < points.size(); ++i)
    ranked.emplace_back(toward == Toward::asked ? space.distance(points[i], at) : space.distance(at, points[i]), i);
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::size_t> ids;
  for (const auto& [d, i] : ranked) ids.push_back(i);
  return ids;
}

class CarSamplingSpaceTest : public ::testing::TestWithParam<bool> {};

TEST_P(CarSamplingSpaceTest, TheBoundNeverExceedsTheCurveAndAPoseAlongAMotionLiesOnIt) {
  const World world = open_car_world(GetParam());
  const auto space = car_sampling_space(world);
  SamplingRandom random(11);
  Coordinates a(3), b(3), mid(3);
  for (int i = 0; i < 3000; ++i) {
    space->sample(random, a);
    space->sample(random, b);
    const double d = space->distance(a, b);
    EXPECT_LE(space->distance_bound(a, b), d * (1 + 1e-12) + 1e-12);
    const double t = uniform01(random);
    space->interpolate(a, b, t, mid);
    // The rest of a shortest curve is a shortest curve: the two parts add up to the whole.
    EXPECT_NEAR(space->distance(a, mid) + space->distance(mid, b), d, 1e-7 * (1 + d)) << i;
  }
}

TEST_P(CarSamplingSpaceTest, NearestNeighboursAreTheTrueNearestByTheCurvesBothWays) {
  const World world = open_car_world(GetParam());
  const auto space = car_sampling_space(world);
  SampledConfigurations<SteeredCar> nodes(*space);
  SamplingRandom random(5);
  std::vector<Coordinates> points;
  for (int i = 0; i < 1500; ++i) {
    Coordinates c(3);
    space->sample(random, c);
    nodes.add(space->configuration(c), c);
    points.push_back(c);
  }
  std::vector<std::size_t> got;
  Coordinates at(3);
  for (int q = 0; q < 150; ++q) {
    space->sample(random, at);
    for (const Toward toward : {Toward::asked, Toward::placed}) {
      const auto expected = brute_force(*space, points, at, toward);
      const auto d = [&](std::size_t i) { return nodes.distance(i, at, toward); };
      EXPECT_EQ(d(nodes.nearest(at, toward)), d(expected[0])) << q;
      nodes.nearest(at, 12, got, toward);
      ASSERT_EQ(got.size(), 12u);
      for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(d(got[i]), d(expected[i])) << q << " " << i;
      const double radius = d(expected[20]);
      nodes.within(at, radius, got, toward);
      EXPECT_EQ(got.size(), 21u) << q;
      for (std::size_t id : got) EXPECT_LE(d(id), radius);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Car, CarSamplingSpaceTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "ReedsShepp" : "Dubins"; });

}  // namespace
}  // namespace polyplan
