// Dubins and Reeds–Shepp distance queries per second, polyplan's against OMPL's in the same run:
// the 10,000 random pose pairs of the frozen reference (bench/steering_reference.cpp, whose rule
// random_pairs repeats: std::mt19937_64 seeded 2026), one query an iteration, cycling through them.
// Both answer distance() (polyplan: dubins_distance, reeds_shepp_distance), what a planner's
// nearest-neighbour search calls; the *Path rows make polyplan's whole shortest path as well.
//
//   build/bench/steering_bench
//
// OMPL is a benchmark-only dependency (Debian: apt-get install libompl-dev); bench/CMakeLists.txt
// builds this program only when find_package(ompl) finds it.
#include <polyplan/car/dubins.hpp>
#include <polyplan/car/reeds_shepp.hpp>

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace {

namespace ob = ompl::base;
using polyplan::CarPose;

constexpr std::array<double, 4> radii{1, 0.5, 2, 3.7};

struct PosePair {
  CarPose from, to;
  std::size_t radius_index = 0;
  double radius() const { return radii[radius_index]; }
};

// The rule of bench/steering_reference.cpp's random_pairs, draw for draw: x0, y0, theta0, x1, y1,
// theta1, then the radius's index.
std::vector<PosePair> random_pairs() {
  constexpr double pi = std::numbers::pi;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> coordinate(-10, 10), heading(-pi, pi);
  std::uniform_int_distribution<std::size_t> radius_index(0, radii.size() - 1);
  std::vector<PosePair> pairs(10000);
  for (PosePair& p : pairs) {
    p.from.x = coordinate(rng), p.from.y = coordinate(rng), p.from.theta = heading(rng);
    p.to.x = coordinate(rng), p.to.y = coordinate(rng), p.to.theta = heading(rng);
    p.radius_index = radius_index(rng);
  }
  return pairs;
}

const std::vector<PosePair>& pairs() {
  static const std::vector<PosePair> p = random_pairs();
  return p;
}

// The pairs as OMPL states, made once: the benchmarks time the queries, not the copying.
struct OmplPairs {
  std::shared_ptr<ob::SE2StateSpace> se2 = std::make_shared<ob::SE2StateSpace>();
  std::vector<ob::State*> from, to;

  OmplPairs() {
    for (const PosePair& p : pairs()) {
      from.push_back(state(p.from));
      to.push_back(state(p.to));
    }
  }
  ~OmplPairs() {
    for (auto* states : {&from, &to})
      for (ob::State* s : *states) se2->freeState(s);
  }
  OmplPairs(const OmplPairs&) = delete;
  OmplPairs& operator=(const OmplPairs&) = delete;

  ob::State* state(const CarPose& pose) const {
    ob::State* s = se2->allocState();
    auto* se2_state = s->as<ob::SE2StateSpace::StateType>();
    se2_state->setX(pose.x);
    se2_state->setY(pose.y);
    se2_state->setYaw(pose.theta);
    return s;
  }
};

const OmplPairs& ompl_pairs() {
  static const OmplPairs p;
  return p;
}

// One OMPL space per radius (its radius is fixed at construction), used as OMPL's planners use it.
template <class Space>
void ompl_distance(benchmark::State& state) {
  const std::vector<PosePair>& p = pairs();
  const OmplPairs& states = ompl_pairs();
  std::array<std::shared_ptr<Space>, radii.size()> spaces;
  for (std::size_t k = 0; k < radii.size(); ++k) spaces[k] = std::make_shared<Space>(radii[k]);
  std::size_t i = 0;
  for (auto _ : state) {
    double length = spaces[p[i].radius_index]->distance(states.from[i], states.to[i]);
    benchmark::DoNotOptimize(length);
    if (++i == p.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class Distance>
void polyplan_distance(benchmark::State& state, Distance distance) {
  const std::vector<PosePair>& p = pairs();
  std::size_t i = 0;
  for (auto _ : state) {
    double length = distance(p[i].from, p[i].to, p[i].radius());
    benchmark::DoNotOptimize(length);
    if (++i == p.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_OmplDubins(benchmark::State& state) { ompl_distance<ob::DubinsStateSpace>(state); }
void BM_PolyplanDubins(benchmark::State& state) { polyplan_distance(state, polyplan::dubins_distance); }
void BM_PolyplanDubinsPath(benchmark::State& state) {
  polyplan_distance(
      state, [](const auto& a, const auto& b, double r) { return polyplan::shortest_dubins_path(a, b, r).length(); });
}
void BM_OmplReedsShepp(benchmark::State& state) { ompl_distance<ob::ReedsSheppStateSpace>(state); }
void BM_PolyplanReedsShepp(benchmark::State& state) { polyplan_distance(state, polyplan::reeds_shepp_distance); }
void BM_PolyplanReedsSheppPath(benchmark::State& state) {
  polyplan_distance(state, [](const auto& a, const auto& b, double r) {
    return polyplan::shortest_reeds_shepp_path(a, b, r).length();
  });
}

BENCHMARK(BM_OmplDubins);
BENCHMARK(BM_PolyplanDubins);
BENCHMARK(BM_PolyplanDubinsPath);
BENCHMARK(BM_OmplReedsShepp);
BENCHMARK(BM_PolyplanReedsShepp);
BENCHMARK(BM_PolyplanReedsSheppPath);

}  // namespace

BENCHMARK_MAIN();
