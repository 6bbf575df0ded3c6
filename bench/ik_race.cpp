// The inverse-kinematics race (issue 29): for arms of 3 to 10 links, 10,000 seeded random reachable
// targets (the hand of a random configuration), solved by polyplan's numeric_ik (damped least
// squares from several seeds, then FABRIK) and, in the same run, by a plain Jacobian-transpose
// baseline (Buss's step size, the same seeds, 1000 iterations each): the share solved to 1e-9 and
// the mean time per solve. A plain program, not Google Benchmark: it times whole solves.
//
//   build/bench/ik_race [--targets 10000] [--seed 1]
#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/inverse_kinematics.hpp>

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

namespace {

using namespace polyplan;

// Jacobian transpose: Δθ = α Jᵀe with α = (e · JJᵀe) / |JJᵀe|² (Buss 2004), from `seeds` random starts.
bool transpose_ik(const Arm& arm, Eigen::Vector2d target, std::size_t seeds, std::mt19937_64& random) {
  const std::size_t n = arm.joints();
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (std::size_t s = 0; s < seeds; ++s) {
    JointAngles q(n);
    for (double& a : q) a = s == 0 ? 0.3 : angle(random);
    for (int k = 0; k < 1000; ++k) {
      const std::vector<Eigen::Vector2d> joints = joint_positions(arm, q);
      const Eigen::Vector2d e = target - joints[n];
      if (e.norm() <= 1e-9) return true;
      Eigen::MatrixXd J(2, n);
      for (std::size_t i = 0; i < n; ++i) J(0, i) = -(joints[n] - joints[i]).y(), J(1, i) = (joints[n] - joints[i]).x();
      const Eigen::VectorXd g = J.transpose() * e;
      const Eigen::Vector2d jg = J * g;
      const double alpha = e.dot(jg) / std::max(jg.squaredNorm(), 1e-300);
      for (std::size_t i = 0; i < n; ++i) q[i] += alpha * g[i];
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t targets = 10000;
  std::uint64_t seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--targets")) targets = std::strtoull(argv[i + 1], nullptr, 10);
    else if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 10);
    else return std::fprintf(stderr, "usage: ik_race [--targets N] [--seed S]\n"), 2;
  }
  std::printf(
      "| links | numeric_ik solved | µs per solve | Jacobian transpose solved | µs per solve |\n| --- | --- | --- | "
      "--- | --- |\n");
  for (std::size_t n = 3; n <= 10; ++n) {
    std::mt19937_64 random(seed * 100 + n);
    std::uniform_real_distribution<double> length(0.5, 1.5), angle(-M_PI, M_PI);
    Arm arm;
    for (std::size_t i = 0; i < n; ++i) arm.links.push_back(length(random));
    std::vector<Eigen::Vector2d> goals;
    for (std::size_t t = 0; t < targets; ++t) {
      JointAngles q(n);
      for (double& a : q) a = angle(random);
      goals.push_back(joint_positions(arm, q).back());
    }
    using Clock = std::chrono::steady_clock;
    std::size_t ours = 0, theirs = 0;
    const auto t0 = Clock::now();
    IkOptions options;
    for (std::size_t t = 0; t < targets; ++t) {
      options.seed = seed + t;
      const IkAnswer answer = numeric_ik(arm, goals[t], options);
      ours += answer.found && answer.solutions.front().error <= 1e-9;
    }
    const auto t1 = Clock::now();
    std::mt19937_64 baseline(seed);
    for (std::size_t t = 0; t < targets; ++t) theirs += transpose_ik(arm, goals[t], options.seeds, baseline);
    const auto t2 = Clock::now();
    const auto micro = [&](auto a, auto b) {
      return std::chrono::duration<double, std::micro>(b - a).count() / static_cast<double>(targets);
    };
    std::printf("| %zu | %.2f %% | %.1f | %.2f %% | %.1f |\n", n,
                100.0 * static_cast<double>(ours) / static_cast<double>(targets), micro(t0, t1),
                100.0 * static_cast<double>(theirs) / static_cast<double>(targets), micro(t1, t2));
    std::fflush(stdout);
  }
  return 0;
}
