// Certified motions (conservative advancement, certify_motion) against the sampled check at 1°
// they replace (the peer), on the same motions in the same run. For each shipped arm
// (data/arms/*.json) a fixed, seeded set of the motions the grid planner checks: moves of one
// 5° grid step on one joint between free grid configurations, and longer joins (every joint up to
// ±0.5 rad) between free configurations.
//
// Counters, per motion: seconds, checks (configurations the checker evaluated: exact tests and
// clearance computations) and, for certify_motion, steps (clearance computations) and its verdicts.
// `disagree` counts the motions that 1° sampling calls free and certify_motion does not, split
// into `missed` (certify_motion found a colliding configuration that the samples skipped) and
// `refused` (uncertified: no bound proved them free); `unsound` counts motions certified free that
// a 1° sample sees collide, and must be 0.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/geometry/angles.hpp>
#include <polyplan/io/arm_reader.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace polyplan;

constexpr double degree = two_pi / 360;
constexpr std::array<const char*, 3> arm_files{"two_link_points.json", "three_link_forest.json",
                                               "four_link_forest.json"};
constexpr std::size_t grid_moves = 400, long_joins = 100;

// The peer: the sampled check at 1° as polyplan had it (motion_is_free with a resolution), written
// out here so that the comparison outlives that overload: `from`, the k − 1 interpolated samples
// and `to`, each tested exactly, stopping at the first that collides.
bool sampled_is_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to,
                     double resolution) {
  const std::size_t k = motion_step_count(from, to, resolution);
  if (!checker.is_free(from)) return false;
  JointAngles sample;
  for (std::size_t j = 1; j < k; ++j) {
    interpolate_angles_into(from, to, static_cast<double>(j) / static_cast<double>(k), sample);
    if (!checker.is_free(sample)) return false;
  }
  return checker.is_free(to);
}

struct Motion {
  JointAngles from, to;
  bool sampled_free = false;  // the peer's answer, for counting disagreements
};

struct MotionSet {
  ArmProblem problem;
  std::vector<Motion> grid_moves, long_joins;
};

MotionSet build(std::size_t arm) {
  MotionSet set;
  set.problem = read_arm_problem(std::string(POLYPLAN_DATA_DIR) + "/arms/" + arm_files[arm]);
  const ArmCollisionChecker checker(set.problem);
  const std::size_t joints = set.problem.arm.joints();
  std::mt19937 rng(static_cast<std::mt19937::result_type>(1000 + arm));
  const double step = 5 * degree;
  std::uniform_int_distribution<int> cell(0, 71), joint(0, static_cast<int>(joints) - 1), side(0, 1);
  while (set.grid_moves.size() < grid_moves) {
    JointAngles from(joints);
    for (double& a : from) a = cell(rng) * step;
    if (!checker.is_free(from)) continue;
    JointAngles to = from;
    const auto j = static_cast<std::size_t>(joint(rng));
    to[j] = normalize_angle(to[j] + (side(rng) == 0 ? -step : step));
    if (checker.is_free(to)) set.grid_moves.push_back({from, to});
  }
  std::uniform_real_distribution<double> angle(0, two_pi), turn(-0.5, 0.5);
  while (set.long_joins.size() < long_joins) {
    JointAngles from(joints);
    for (double& a : from) a = angle(rng);
    JointAngles to = from;
    for (double& a : to) a = normalize_angle(a + turn(rng));
    if (checker.is_free(from) && checker.is_free(to)) set.long_joins.push_back({from, to});
  }
  for (auto* motions : {&set.grid_moves, &set.long_joins})
    for (Motion& m : *motions) m.sampled_free = sampled_is_free(checker, m.from, m.to, degree);
  return set;
}

const MotionSet& motion_set(std::size_t arm) {
  static std::array<MotionSet, 3> sets{build(0), build(1), build(2)};
  return sets.at(arm);
}

const std::vector<Motion>& motions_of(const benchmark::State& state) {
  const MotionSet& set = motion_set(static_cast<std::size_t>(state.range(0)));
  return state.range(1) == 0 ? set.grid_moves : set.long_joins;
}

void label(benchmark::State& state) {
  state.SetLabel(std::string(arm_files[static_cast<std::size_t>(state.range(0))]) +
                 (state.range(1) == 0 ? " 5-degree grid moves" : " joins up to 0.5 rad"));
}

// Per-motion counters: `total` over one pass of `motions` motions.
void per_motion(benchmark::State& state, const char* name, double total, std::size_t motions) {
  state.counters[name] = total / static_cast<double>(motions);
}

void BM_Certified(benchmark::State& state) {
  const std::vector<Motion>& motions = motions_of(state);
  const ArmCollisionChecker checker(motion_set(static_cast<std::size_t>(state.range(0))).problem);
  std::size_t checks = 0, steps = 0, free = 0, collides = 0, uncertified = 0, missed = 0, refused = 0, unsound = 0;
  for (auto _ : state) {
    const std::size_t checks_before = checker.checks();
    steps = free = collides = uncertified = missed = refused = unsound = 0;
    for (const Motion& m : motions) {
      const MotionCertificate c = certify_motion(checker, m.from, m.to);
      steps += c.steps;
      free += c.free();
      collides += c.verdict == MotionCertificate::Verdict::collides;
      uncertified += c.verdict == MotionCertificate::Verdict::uncertified;
      missed += m.sampled_free && c.verdict == MotionCertificate::Verdict::collides;
      refused += m.sampled_free && c.verdict == MotionCertificate::Verdict::uncertified;
      unsound += !m.sampled_free && c.free();
    }
    checks = checker.checks() - checks_before;
  }
  label(state);
  state.counters["motions"] = static_cast<double>(motions.size());
  state.counters["per_motion"] = benchmark::Counter(
      static_cast<double>(motions.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  per_motion(state, "checks", static_cast<double>(checks), motions.size());
  per_motion(state, "steps", static_cast<double>(steps), motions.size());
  state.counters["free"] = static_cast<double>(free);
  state.counters["collides"] = static_cast<double>(collides);
  state.counters["uncertified"] = static_cast<double>(uncertified);
  state.counters["disagree"] = static_cast<double>(missed + refused);
  state.counters["missed"] = static_cast<double>(missed);
  state.counters["refused"] = static_cast<double>(refused);
  state.counters["unsound"] = static_cast<double>(unsound);
}

void BM_Sampled1Degree(benchmark::State& state) {
  const std::vector<Motion>& motions = motions_of(state);
  const ArmCollisionChecker checker(motion_set(static_cast<std::size_t>(state.range(0))).problem);
  std::size_t checks = 0, free = 0;
  for (auto _ : state) {
    const std::size_t checks_before = checker.checks();
    free = 0;
    for (const Motion& m : motions) free += sampled_is_free(checker, m.from, m.to, degree);
    checks = checker.checks() - checks_before;
  }
  label(state);
  state.counters["motions"] = static_cast<double>(motions.size());
  state.counters["per_motion"] = benchmark::Counter(
      static_cast<double>(motions.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  per_motion(state, "checks", static_cast<double>(checks), motions.size());
  state.counters["free"] = static_cast<double>(free);
}

// Arms 0, 1, 2 (two_link_points, three_link_forest, four_link_forest) × grid moves, long joins.
void motion_sets(benchmark::internal::Benchmark* b) {
  for (int arm = 0; arm < 3; ++arm)
    for (int kind = 0; kind < 2; ++kind) b->Args({arm, kind});
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Certified)->Apply(motion_sets);
BENCHMARK(BM_Sampled1Degree)->Apply(motion_sets);

}  // namespace

BENCHMARK_MAIN();
