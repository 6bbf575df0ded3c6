// NearestNeighbours against brute force under sampling_distance: on the torus (points and queries
// crowded at both sides of the 0 = 2π seam, where a tree that cuts the circle as a line prunes
// wrongly) and in the plane, built all at once or interleaved with queries as RRT does, below the
// size where the index turns from a linear scan to a KD-tree and above it.
#include <polyplan/sampling/nearest_neighbours.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

using namespace polyplan;

namespace {

using Point = std::vector<double>;

// A torus coordinate: a third of them within 0.05 above 0, a third within 0.05 below 2π.
double torus_coordinate(SamplingRandom& random) {
  const double u = uniform01(random);
  switch (random() % 3) {
    case 0: return 0.05 * u;
    case 1: return normalize_angle(-0.05 * u);
    default: return two_pi * u;
  }
}

Point random_point(SamplingMetric metric, std::size_t dimension, SamplingRandom& random) {
  Point p(dimension);
  for (double& c : p) c = metric == SamplingMetric::torus ? torus_coordinate(random) : 20 * uniform01(random) - 10;
  return p;
}

// `count` random points, every 50th a copy of an earlier one so that there are exact ties.
std::vector<Point> random_points(SamplingMetric metric, std::size_t dimension, std::size_t count,
                                 SamplingRandom& random) {
  std::vector<Point> points;
  for (std::size_t i = 0; i < count; ++i)
    points.push_back(i % 50 == 49 ? points[random() % i] : random_point(metric, dimension, random));
  return points;
}

NearestNeighbours build(SamplingMetric metric, std::size_t dimension, const std::vector<Point>& points) {
  NearestNeighbours nn(dimension, metric);
  for (const Point& p : points) nn.add(p);
  return nn;
}

std::vector<double> distances_to(SamplingMetric metric, const std::vector<Point>& points, const Point& query) {
  std::vector<double> d;
  for (const Point& p : points) d.push_back(sampling_distance(metric, p, query));
  return d;
}

// `indices` are distinct and their distances are `expected`, in order: the brute-force answer up
// to the order of exact ties.
void expect_distances(const std::vector<std::size_t>& indices, const std::vector<double>& distance,
                      const std::vector<double>& expected, const std::string& what) {
  ASSERT_EQ(indices.size(), expected.size()) << what;
  for (std::size_t j = 0; j < indices.size(); ++j) {
    ASSERT_LT(indices[j], distance.size()) << what;
    EXPECT_EQ(distance[indices[j]], expected[j]) << what << ", result " << j;
  }
  std::vector<std::size_t> sorted = indices;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << what << ": an index twice";
}

// nearest(q), nearest(q, k) for k = 1, 5, 20 and within(q, r) against brute force, r both the
// distance of a point (which must be included) and a random one. Fewer than 20 points: k is cut.
void expect_brute_force(const NearestNeighbours& nn, SamplingMetric metric, const std::vector<Point>& points,
                        const Point& query, SamplingRandom& random) {
  const std::vector<double> distance = distances_to(metric, points, query);
  std::vector<double> sorted = distance;
  std::sort(sorted.begin(), sorted.end());

  EXPECT_EQ(distance[nn.nearest(query)], sorted[0]);
  std::vector<std::size_t> out;
  for (const std::size_t k : {1, 5, 20}) {
    nn.nearest(query, k, out);
    const auto kth = sorted.begin() + static_cast<std::ptrdiff_t>(std::min(k, sorted.size()));
    expect_distances(out, distance, std::vector<double>(sorted.begin(), kth), "k = " + std::to_string(k));
  }
  const auto at_most_last = [&](std::size_t rank) { return sorted[std::min(rank, sorted.size() - 1)]; };
  for (const double radius : {at_most_last(30), at_most_last(200) * uniform01(random)}) {
    nn.within(query, radius, out);
    const auto end = std::upper_bound(sorted.begin(), sorted.end(), radius);
    expect_distances(out, distance, std::vector<double>(sorted.begin(), end), "radius " + std::to_string(radius));
  }
}

void expect_brute_force_on_random_points(SamplingMetric metric, std::size_t dimension, std::uint64_t seed) {
  SamplingRandom random(seed);
  const std::vector<Point> points = random_points(metric, dimension, 3000, random);
  const NearestNeighbours nn = build(metric, dimension, points);
  ASSERT_EQ(nn.size(), points.size());
  for (int q = 0; q < 300; ++q) {
    // Every 10th query at a stored point: a distance of 0, tied when the point has copies.
    const Point query = q % 10 == 0 ? points[random() % points.size()] : random_point(metric, dimension, random);
    SCOPED_TRACE("query " + std::to_string(q));
    expect_brute_force(nn, metric, points, query, random);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(NearestNeighbours, TorusMatchesBruteForceIn2D) {
  expect_brute_force_on_random_points(SamplingMetric::torus, 2, 1);
}
TEST(NearestNeighbours, TorusMatchesBruteForceIn4D) {
  expect_brute_force_on_random_points(SamplingMetric::torus, 4, 2);
}
TEST(NearestNeighbours, TorusMatchesBruteForceIn6D) {
  expect_brute_force_on_random_points(SamplingMetric::torus, 6, 3);
}
TEST(NearestNeighbours, EuclideanMatchesBruteForceIn2D) {
  expect_brute_force_on_random_points(SamplingMetric::euclidean, 2, 4);
}

TEST(NearestNeighbours, BothRegimesMatchBruteForce) {
  // The index scans its points until there are a few hundred to a few thousand of them, more in
  // higher dimensions (scan_threshold in nearest_neighbours.cpp), then builds a KD-tree from them
  // all and adds to it. These sizes straddle the switch in every dimension the planners use (2, 3,
  // 4, 6) and in 1, 5 and 8 (where the scan's distance is not unrolled). The torus points crowd
  // the seam.
  const std::vector<std::size_t> checkpoints{1, 2, 15, 120, 249, 250, 251, 600, 1999, 2000, 2001, 4100, 8500};
  for (const auto& [metric, dimension] : {std::pair{SamplingMetric::euclidean, 2},
                                          {SamplingMetric::euclidean, 5},
                                          {SamplingMetric::torus, 1},
                                          {SamplingMetric::torus, 2},
                                          {SamplingMetric::torus, 3},
                                          {SamplingMetric::torus, 4},
                                          {SamplingMetric::torus, 6},
                                          {SamplingMetric::torus, 8}}) {
    SamplingRandom random(8 + dimension);
    const std::vector<Point> points = random_points(metric, dimension, checkpoints.back(), random);
    NearestNeighbours nn(dimension, metric);
    std::vector<Point> added;
    for (const std::size_t size : checkpoints) {
      while (added.size() < size) {
        added.push_back(points[added.size()]);
        nn.add(added.back());
      }
      for (int q = 0; q < 20; ++q) {
        SCOPED_TRACE(std::string(metric == SamplingMetric::torus ? "torus" : "euclidean") + ", dimension " +
                     std::to_string(dimension) + ", " + std::to_string(size) + " points, query " + std::to_string(q));
        const Point query = q % 5 == 0 ? added[random() % size] : random_point(metric, dimension, random);
        expect_brute_force(nn, metric, added, query, random);
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
  }
}

TEST(NearestNeighbours, EuclideanTiesOnAGridMatchBruteForce) {
  // Integer points, each twice, queried at integers and half-integers: many exact ties.
  std::vector<Point> points;
  for (int copy = 0; copy < 2; ++copy)
    for (int x = 0; x < 25; ++x)
      for (int y = 0; y < 25; ++y) points.push_back({double(x), double(y)});
  const NearestNeighbours nn = build(SamplingMetric::euclidean, 2, points);
  SamplingRandom random(5);
  for (int q = 0; q < 200; ++q) {
    const Point query{double(random() % 50) / 2, double(random() % 50) / 2};
    SCOPED_TRACE("query " + std::to_string(q));
    expect_brute_force(nn, SamplingMetric::euclidean, points, query, random);
  }
}

TEST(NearestNeighbours, TheNearestPointMayBeAcrossTheSeam) {
  // One point 0.1 from the query the short way round, through 0 = 2π, and 1200 points in
  // [1, 2] ∪ [3.7, 4.2], at least 0.95 away: the trees split the far point from the query's side,
  // and a bound that is the distance on the line (6.18), or the short way to the split value
  // (3.45 from 0.05 to 3.7), prunes it. (1200: past the size where the index stops scanning.)
  for (const bool query_at_zero : {false, true}) {
    for (const std::size_t dimension : {1, 2}) {
      SCOPED_TRACE("dimension " + std::to_string(dimension) +
                   (query_at_zero ? ", query at 0.05" : ", query at 2π − 0.05"));
      Point across(dimension, 1.0);
      Point query(dimension, 1.0);
      across[0] = query_at_zero ? two_pi - 0.05 : 0.05;
      query[0] = query_at_zero ? 0.05 : two_pi - 0.05;
      NearestNeighbours nn(dimension, SamplingMetric::torus);
      nn.add(across);
      SamplingRandom random(6);
      for (int i = 0; i < 1200; ++i) {
        Point p(dimension, 1.0);
        p[0] = i % 2 == 0 ? 1 + uniform01(random) : 3.7 + 0.5 * uniform01(random);
        nn.add(p);
      }
      EXPECT_EQ(nn.nearest(query), 0u);
      EXPECT_NEAR(sampling_distance(SamplingMetric::torus, nn.point(0), query), 0.1, 1e-12);
      std::vector<std::size_t> out;
      nn.nearest(query, 2, out);
      ASSERT_EQ(out.size(), 2u);
      EXPECT_EQ(out[0], 0u);
      nn.within(query, 0.2, out);
      EXPECT_EQ(out, std::vector<std::size_t>{0});
    }
  }
}

TEST(NearestNeighbours, InterleavedAddsAndQueriesMatchBruteForce) {
  // As RRT grows its tree: after every add the nearest points to a fresh sample are right, through
  // the switch from scan to tree (at 500 points in 3-D).
  for (const SamplingMetric metric : {SamplingMetric::torus, SamplingMetric::euclidean}) {
    SCOPED_TRACE(metric == SamplingMetric::torus ? "torus" : "euclidean");
    SamplingRandom random(7);
    NearestNeighbours nn(3, metric);
    std::vector<Point> points;
    for (std::size_t i = 0; i < 1500; ++i) {
      points.push_back(random_point(metric, 3, random));
      ASSERT_EQ(nn.add(points.back()), i);
      const Point query = random_point(metric, 3, random);
      SCOPED_TRACE("after " + std::to_string(i + 1));
      expect_brute_force(nn, metric, points, query, random);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(NearestNeighbours, FewerPointsThanKGivesThemAllNearestFirst) {
  NearestNeighbours nn(2, SamplingMetric::torus);
  const std::vector<Point> points{{3.0, 3.0}, {0.1, 6.2}, {1.0, 0.5}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(nn.add(points[i]), i);
    EXPECT_EQ(std::vector<double>(nn.point(i).begin(), nn.point(i).end()), points[i]);
  }
  EXPECT_EQ(nn.dimension(), 2u);
  EXPECT_EQ(nn.size(), 3u);
  std::vector<std::size_t> out{42, 43};
  nn.nearest(Point{6.2, 0.0}, 10, out);
  EXPECT_EQ(out, (std::vector<std::size_t>{1, 2, 0}));  // distances 0.2 + 0.083, 1.28 + 0.5, 3.28 + 3
  nn.nearest(Point{6.2, 0.0}, 0, out);
  EXPECT_TRUE(out.empty());
}

TEST(NearestNeighbours, WithinIncludesPointsAtTheRadius) {
  NearestNeighbours plane(2, SamplingMetric::euclidean);
  for (const Point& p : std::vector<Point>{{3, 4}, {0, 0}, {0, 5.5}, {-3, -4}}) plane.add(p);
  std::vector<std::size_t> out;
  plane.within(Point{0, 0}, 5, out);  // (3, 4) and (−3, −4) at exactly 5
  EXPECT_EQ(out, (std::vector<std::size_t>{1, 0, 3}));
  plane.within(Point{0, 0}, 0, out);
  EXPECT_EQ(out, std::vector<std::size_t>{1});
  plane.within(Point{0, 0}, -1, out);
  EXPECT_TRUE(out.empty());
  plane.within(Point{0, 0}, std::numeric_limits<double>::infinity(), out);
  EXPECT_EQ(out, (std::vector<std::size_t>{1, 0, 3, 2}));

  NearestNeighbours torus(1, SamplingMetric::torus);
  for (const double a : {1.0, 0.0, 5.0}) torus.add(Point{a});
  torus.within(Point{0.0}, 1.0, out);  // 1 at exactly 1; 5 at 2π − 5 > 1
  EXPECT_EQ(out, (std::vector<std::size_t>{1, 0}));
}

TEST(NearestNeighbours, MovingKeepsThePoints) {
  NearestNeighbours nn(2, SamplingMetric::torus);
  for (int i = 0; i < 50; ++i) nn.add(Point{0.1 * i, 0.05 * i});
  NearestNeighbours moved(std::move(nn));
  EXPECT_EQ(moved.size(), 50u);
  EXPECT_EQ(moved.nearest(Point{1.01, 0.5}), 10u);
  nn = std::move(moved);
  EXPECT_EQ(nn.nearest(Point{6.2, 6.2}), 0u);  // 0.083 + 0.083 across both seams
}

TEST(NearestNeighbours, RejectsBadDimensionsAndPoints) {
  EXPECT_THROW(NearestNeighbours(0, SamplingMetric::euclidean), std::invalid_argument);
  EXPECT_THROW(NearestNeighbours(0, SamplingMetric::torus), std::invalid_argument);

  NearestNeighbours nn(2, SamplingMetric::torus);
  std::vector<std::size_t> out;
  // Empty: nearest(q) has no answer (a logic_error that is not invalid_argument).
  try {
    nn.nearest(Point{1, 1});
    ADD_FAILURE() << "nearest on an empty set did not throw";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(typeid(e), typeid(std::logic_error)) << e.what();
  }
  nn.nearest(Point{1, 1}, 3, out);
  EXPECT_TRUE(out.empty());
  nn.within(Point{1, 1}, 10, out);
  EXPECT_TRUE(out.empty());

  EXPECT_THROW(nn.add(Point{1}), std::invalid_argument);
  EXPECT_THROW(nn.add(Point{1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(nn.add(Point{1, two_pi}), std::invalid_argument);
  EXPECT_THROW(nn.add(Point{-0.1, 1}), std::invalid_argument);
  EXPECT_THROW(nn.add(Point{std::nan(""), 1}), std::invalid_argument);
  EXPECT_EQ(nn.size(), 0u);
  nn.add(Point{1, 1});
  EXPECT_THROW(nn.nearest(Point{1}), std::invalid_argument);
  EXPECT_THROW(nn.nearest(Point{1, 1, 1}, 1, out), std::invalid_argument);
  EXPECT_THROW(nn.within(Point{1, 7}, 1, out), std::invalid_argument);
  EXPECT_THROW(nn.point(1), std::out_of_range);

  NearestNeighbours plane(2, SamplingMetric::euclidean);
  EXPECT_THROW(plane.add(Point{1, std::numeric_limits<double>::infinity()}), std::invalid_argument);
  plane.add(Point{-100, 100});  // any finite coordinates
  EXPECT_EQ(plane.nearest(Point{0, 0}), 0u);
}

}  // namespace
