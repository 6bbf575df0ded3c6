#include <polyplan/arm/inverse_kinematics.hpp>

#include <polyplan/geometry/rational.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

namespace polyplan {
namespace {

double wrap(double a) {
  a = std::remainder(a, 2 * M_PI);
  return a <= -M_PI ? a + 2 * M_PI : a;
}

Eigen::Vector2d hand(const Arm& arm, const JointAngles& q) { return joint_positions(arm, q).back(); }

IkSolution solution(const Arm& arm, JointAngles q, Eigen::Vector2d target) {
  for (double& a : q) a = wrap(a);
  const double error = (hand(arm, q) - target).norm();
  return {std::move(q), error};
}

bool distinct(const std::vector<IkSolution>& found, const JointAngles& q) {
  for (const IkSolution& s : found) {
    double apart = 0;
    for (std::size_t i = 0; i < q.size(); ++i) apart = std::max(apart, std::abs(wrap(q[i] - s.angles[i])));
    if (apart <= 1e-6) return false;
  }
  return true;
}

void require_links(const Arm& arm, std::size_t n, const char* what) {
  if (arm.joints() != n)
    throw std::invalid_argument(std::string(what) + ": the arm has " + std::to_string(arm.joints()) + " links");
}

}  // namespace

double end_orientation(const JointAngles& angles) {
  double sum = 0;
  for (const double a : angles) sum += a;
  return wrap(sum);
}

HandReach exact_hand_reach(const std::vector<Rational>& links, const ExactPoint& target) {
  // The sums, the squares and the comparisons are exact.
  Rational sum(0), longest(0);
  for (const Rational& l : links) {
    sum += l;
    longest = std::max(longest, l);
  }
  Rational inner = 2 * longest - sum;
  if (inner < 0) inner = 0;
  const Rational d2 = target.x * target.x + target.y * target.y, outer_margin = sum * sum - d2,
                 inner_margin = d2 - inner * inner;
  return {to_double(inner),  to_double(sum),          sgn(outer_margin),
          sgn(inner_margin), to_double(outer_margin), to_double(inner_margin)};
}

HandReach hand_reach(const std::vector<double>& links, Eigen::Vector2d target) {
  // Every double is a rational.
  return exact_hand_reach(std::vector<Rational>(links.begin(), links.end()),
                          ExactPoint{Rational(target.x()), Rational(target.y())});
}

HandReach hand_reach(const Arm& arm, Eigen::Vector2d target, const std::optional<ExactPoint>& exact_target) {
  const std::vector<Rational> links = arm.exact_links.size() == arm.links.size()
                                          ? arm.exact_links
                                          : std::vector<Rational>(arm.links.begin(), arm.links.end());
  return exact_hand_reach(links, exact_target.value_or(ExactPoint{Rational(target.x()), Rational(target.y())}));
}

IkAnswer two_link_ik(const Arm& arm, Eigen::Vector2d target, const std::optional<ExactPoint>& exact_target) {
  require_links(arm, 2, "two_link_ik");
  const HandReach reach = hand_reach(arm, target, exact_target);
  const double toward = std::atan2(target.y(), target.x());
  const bool longer_first = arm.links[0] >= arm.links[1];
  const JointAngles stretched{toward, 0}, folded{longer_first ? toward : toward + M_PI, M_PI};
  IkAnswer answer;
  if (!reach.reachable()) {
    const bool beyond = reach.outer_side < 0;
    answer.solutions.push_back(solution(arm, beyond ? stretched : folded, target));
    answer.why_not = beyond ? "the target is farther from the base than the two links reach (l1 + l2)"
                            : "the target is nearer the base than the links' difference |l1 - l2|";
    return answer;
  }
  answer.found = answer.every_solution = true;
  if (reach.outer_side == 0 || reach.inner_side == 0) {  // on the annulus's boundary: one elbow
    const bool at_base = target.x() == 0 && target.y() == 0;
    answer.solutions.push_back(
        solution(arm, reach.outer_side == 0 ? stretched : (at_base ? JointAngles{0, M_PI} : folded), target));
    return answer;
  }
  // The elbow's half-angle formula, tan²(θ2 / 2) = ((l1 + l2)² − d²) / (d² − (l1 − l2)²): stable
  // near both boundaries, where acos of the cosine rule loses half the digits.
  const double elbow = 2 * std::atan(std::sqrt(reach.outer_margin / reach.inner_margin));
  for (const double t2 : {elbow, -elbow}) {
    const double t1 = toward - std::atan2(arm.links[1] * std::sin(t2), arm.links[0] + arm.links[1] * std::cos(t2));
    answer.solutions.push_back(solution(arm, {t1, t2}, target));
  }
  return answer;
}

IkAnswer three_link_ik(const Arm& arm, Eigen::Vector2d target, double orientation) {
  require_links(arm, 3, "three_link_ik");
  const Eigen::Vector2d wrist = target - arm.links[2] * Eigen::Vector2d(std::cos(orientation), std::sin(orientation));
  Arm two = arm;
  two.links.pop_back();
  if (!two.exact_links.empty()) two.exact_links.pop_back();
  IkAnswer wrist_answer = two_link_ik(two, wrist);
  IkAnswer answer;
  answer.found = answer.every_solution = wrist_answer.found;
  answer.why_not = wrist_answer.why_not.empty() ? "" : "the wrist point: " + wrist_answer.why_not;
  for (const IkSolution& s : wrist_answer.solutions)
    answer.solutions.push_back(
        solution(arm, {s.angles[0], s.angles[1], orientation - s.angles[0] - s.angles[1]}, target));
  return answer;
}

IkSolution fabrik(const Arm& arm, Eigen::Vector2d target, const JointAngles& start, std::size_t iterations,
                  double tolerance) {
  std::vector<Eigen::Vector2d> p = joint_positions(arm, start);
  const std::size_t n = arm.joints();
  const auto place = [&](std::size_t from, std::size_t to,
                         double length) {  // p[to] at `length` from p[from], on its line
    Eigen::Vector2d d = p[to] - p[from];
    const double norm = d.norm();
    p[to] = p[from] + length * (norm > 0 ? Eigen::Vector2d(d / norm) : Eigen::Vector2d(1, 0));
  };
  double total = 0;
  for (const double l : arm.links) total += l;
  if (target.norm() >= total) {  // out of reach: stretched straight towards it
    for (std::size_t i = 0; i < n; ++i) p[i + 1] = p[i] + arm.links[i] * target.normalized();
  } else {
    for (std::size_t k = 0; k < iterations && (p[n] - target).norm() > tolerance; ++k) {
      p[n] = target;
      for (std::size_t i = n; i-- > 0;) place(i + 1, i, arm.links[i]);
      p[0] = Eigen::Vector2d::Zero();
      for (std::size_t i = 0; i < n; ++i) place(i, i + 1, arm.links[i]);
    }
  }
  JointAngles q(n);
  double previous = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double absolute = std::atan2(p[i + 1].y() - p[i].y(), p[i + 1].x() - p[i].x());
    q[i] = absolute - previous;
    previous = absolute;
  }
  return solution(arm, std::move(q), target);
}

IkAnswer numeric_ik(const Arm& arm, Eigen::Vector2d target, const IkOptions& o) {
  const std::size_t n = arm.joints();
  if (!o.limits.empty() && o.limits.size() != n)
    throw std::invalid_argument("numeric_ik: " + std::to_string(o.limits.size()) + " joint limits for " +
                                std::to_string(n) + " links");
  const std::size_t rows = o.orientation ? 3 : 2;
  const double aim = o.refine_to > 0 ? std::min(o.refine_to, o.tolerance) : o.tolerance;
  const auto clamp = [&](JointAngles& q) {
    for (std::size_t i = 0; i < o.limits.size(); ++i) q[i] = std::clamp(q[i], o.limits[i].first, o.limits[i].second);
  };
  // The task's error and Jacobian at q, from q's joint positions.
  const auto task_error = [&](const JointAngles& q, const std::vector<Eigen::Vector2d>& joints) {
    Eigen::VectorXd e(rows);
    e.head<2>() = target - joints[n];
    if (o.orientation) e[2] = wrap(*o.orientation - end_orientation(q));
    return e;
  };
  const auto jacobian = [&](const std::vector<Eigen::Vector2d>& joints) {
    Eigen::MatrixXd J(rows, n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d r = joints[n] - joints[i];
      J(0, i) = -r.y(), J(1, i) = r.x();
      if (o.orientation) J(2, i) = 1;
    }
    return J;
  };
  std::mt19937_64 random(o.seed);
  IkAnswer answer;
  std::optional<IkSolution> closest;
  for (std::size_t s = 0; s < o.seeds && (o.all || !answer.found); ++s) {
    JointAngles q(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double lo = o.limits.empty() ? -M_PI : o.limits[i].first, hi = o.limits.empty() ? M_PI : o.limits[i].second;
      q[i] = s == 0 && lo <= 0.3 && 0.3 <= hi
                 ? 0.3
                 : std::uniform_real_distribution<double>(lo, hi)(random);  // seed 0: a gentle curl
    }
    // Damped least squares, Levenberg–Marquardt's damping: halved after a step that helps,
    // quadrupled (and the step refused) after one that does not. Forward kinematics once per
    // step tried; the Jacobian only where q moves.
    std::vector<Eigen::Vector2d> joints = joint_positions(arm, q), tried;
    Eigen::VectorXd e = task_error(q, joints);
    Eigen::MatrixXd J = jacobian(joints);
    double damping = 1e-2 * arm.reach();
    const auto damped_step = [&](const Eigen::MatrixXd& jacobian_used) -> Eigen::VectorXd {
      const Eigen::MatrixXd JJt =
          jacobian_used * jacobian_used.transpose() + damping * damping * Eigen::MatrixXd::Identity(rows, rows);
      return jacobian_used.transpose() * JJt.ldlt().solve(e);
    };
    for (std::size_t k = 0; k < o.iterations && e.norm() > aim; ++k) {
      Eigen::VectorXd step = damped_step(J);
      // A joint held at a limit that the step pushes further takes no part in it: the others then
      // make the whole step, instead of a clamp cutting it short every time.
      if (!o.limits.empty()) {
        Eigen::MatrixXd held = J;
        bool holds = false;
        for (std::size_t i = 0; i < n; ++i)
          if ((q[i] <= o.limits[i].first && step[i] < 0) || (q[i] >= o.limits[i].second && step[i] > 0))
            held.col(i).setZero(), holds = true;
        if (holds) step = damped_step(held);
      }
      JointAngles next = q;
      for (std::size_t i = 0; i < n; ++i) next[i] += step[i];
      clamp(next);
      joint_positions_into(arm, next, tried);
      const Eigen::VectorXd e_next = task_error(next, tried);
      if (e_next.norm() < e.norm()) {
        q = std::move(next), joints.swap(tried), e = e_next, J = jacobian(joints), damping *= 0.5;
      } else {
        damping *= 4;
        // Steps this damped no longer move q (and many more would overflow it): this seed is done.
        if (damping > 1e6 * arm.reach()) break;
      }
    }
    IkSolution found = solution(arm, q, target);
    const bool reached = e.norm() <= o.tolerance;
    if (reached && distinct(answer.solutions, found.angles)) answer.solutions.push_back(found), answer.found = true;
    if (!closest || found.error < closest->error) closest = found;
  }
  if (!answer.found && !o.orientation && o.limits.empty()) {  // FABRIK: no orientation, no limits
    IkSolution pulled = fabrik(arm, target, JointAngles(n, 0.3));
    if (pulled.error <= o.tolerance) answer.found = true, answer.solutions.push_back(pulled);
    else if (!closest || pulled.error < closest->error) closest = pulled;
  }
  if (!answer.found) {
    answer.solutions.push_back(*closest);
    char why[160];
    std::snprintf(why, sizeof why, "no configuration within %g of the target from %zu seeds (the closest: %.6g away)",
                  o.tolerance, o.seeds, closest->error);
    answer.why_not = why;
  }
  return answer;
}

bool within_joint_limits(const JointAngles& angles, const std::vector<std::pair<double, double>>& limits) {
  constexpr double slack = 1e-12;
  for (std::size_t i = 0; i < limits.size() && i < angles.size(); ++i) {
    const auto [lo, hi] = limits[i];
    if (hi - lo >= 2 * M_PI) continue;
    // The first of a + 2πk at or above lo; beyond hi it is outside, and so is every other.
    const double shifted = angles[i] + 2 * M_PI * std::ceil((lo - slack - angles[i]) / (2 * M_PI));
    if (shifted > hi + slack) return false;
  }
  return true;
}

IkAnswer inverse_kinematics(const Arm& arm, Eigen::Vector2d target, const IkOptions& options) {
  const bool oriented = options.orientation.has_value();
  IkAnswer answer = arm.joints() == 2 && !oriented  ? two_link_ik(arm, target, options.exact_target)
                    : arm.joints() == 3 && oriented ? three_link_ik(arm, target, *options.orientation)
                                                    : numeric_ik(arm, target, options);
  if (!answer.found || options.limits.empty()) return answer;
  std::vector<IkSolution> within;
  for (IkSolution& s : answer.solutions)
    if (within_joint_limits(s.angles, options.limits)) within.push_back(std::move(s));
    else ++answer.outside_limits;
  if (within.empty()) {  // the closest stay, as when nothing is found
    answer.found = false;
    answer.why_not = "every solution (" + std::to_string(answer.outside_limits) + ") lies outside the joint limits";
    return answer;
  }
  answer.solutions = std::move(within);
  return answer;
}

}  // namespace polyplan
