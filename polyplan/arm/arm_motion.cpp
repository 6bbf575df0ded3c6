#include <polyplan/arm/arm_motion.hpp>

#include <polyplan/arm/detail/outward_rounding.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace polyplan {

namespace {

using detail::above;
using detail::below;

// The speeds of arm_motion.hpp's motion bound for joint rotations of at most |turn[j]| (upper
// bounds of the real turns): link_speed[k] bounds how fast any point of links[k] moves,
// pair_speed[k * n + m] (k + 2 ≤ m, self-collision only) how fast any point of links[m] moves
// relative to links[k]. Sums and products of non-negative numbers, each rounded and then moved
// up to the next double: upper bounds.
void motion_speeds(const Arm& arm, const JointAngles& turn, std::vector<double>& link_speed,
                   std::vector<double>& pair_speed) {
  const std::size_t n = arm.joints();
  // R_{j,k} = links[j] + … + links[k] + w/2: no point of links[k] is farther from joint j.
  const auto radius = [&](std::size_t j, std::size_t k) {
    double sum = arm.link_width / 2;
    for (std::size_t i = j; i <= k; ++i) sum = above(sum + arm.links[i]);
    return sum;
  };
  const auto add = [](double& speed, double r, double t) { speed = above(speed + above(r * std::fabs(t))); };
  link_speed.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j <= k; ++j)
      if (turn[j] != 0) add(link_speed[k], radius(j, k), turn[j]);
  pair_speed.assign(arm.self_collision ? n * n : 0, 0.0);
  if (arm.self_collision)
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t m = k + 2; m < n; ++m)
        for (std::size_t j = k + 1; j <= m; ++j)
          if (turn[j] != 0) add(pair_speed[k * n + m], radius(j, m), turn[j]);
}

void require_arm_size(const ArmCollisionChecker& checker, const JointAngles& q, const char* which) {
  if (q.size() != checker.arm().joints())
    throw std::invalid_argument(std::string("certify_motion: ") + which + " has " + std::to_string(q.size()) +
                                " angles for an arm of " + std::to_string(checker.arm().joints()) + " links");
}

// The motion's turns as reals: joint j turns D_j = to_j − from_j + k_j·2π between the normalised
// ends, k_j ∈ {−1, 0, 1} as signed_angle_difference chose it (the double `turn[j]`, which differs
// from to_j − from_j in doubles exactly when it shifted that by two_pi). Enclosed in [lo, hi]: 2π
// between the doubles around two_pi, each sum rounded and moved outward to the next double.
using Range = std::array<double, 2>;
void real_turns(const JointAngles& from, const JointAngles& to, const JointAngles& turn, std::vector<Range>& out) {
  out.resize(from.size());
  for (std::size_t j = 0; j < from.size(); ++j) {
    const double between = to[j] - from[j];  // rounded to nearest, as signed_angle_difference computed it
    Range d{below(between), above(between)};
    if (turn[j] < between) d = {below(d[0] - above(two_pi)), above(d[1] - below(two_pi))};
    else if (turn[j] > between) d = {below(d[0] + below(two_pi)), above(d[1] + above(two_pi))};
    out[j] = d;
  }
}

// The largest distance from q to the true angle from + t·D, D in `turn` and t ≥ 0 (a double),
// rounded up.
double spread_of(double q, double from, double t, const Range& turn) {
  const double lo = below(from + below(t * turn[0])), hi = above(from + above(t * turn[1]));
  return std::max(above(std::fabs(q - lo)), above(std::fabs(q - hi)));
}

// How long a configuration's clearances keep a motion with these speeds free, from that end:
// safe_step's minimum, without measuring anything (lasts_below rounds down in any rounding mode).
double lasts_at(const ArmClearances& clearances, const std::vector<double>& link_speed,
                const std::vector<double>& pair_speed) {
  double h = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < link_speed.size(); ++k)
    h = std::min(h, detail::lasts_below(clearances.links[k], link_speed[k]));
  for (std::size_t i = 0; i < pair_speed.size(); ++i)
    h = std::min(h, detail::lasts_below(clearances.pairs[i], pair_speed[i]));
  return h;
}

}  // namespace

void measure_end_clearances(const ArmCollisionChecker& checker, const JointAngles& q, ArmClearances& out) {
  checker.clearances(q, out, std::numeric_limits<double>::infinity(), ClearanceUse::stepping);
}

MotionCertificate certify_motion(const ArmCollisionChecker& checker, const JointAngles& from_given,
                                 const JointAngles& to_given) {
  return certify_motion(checker, from_given, to_given, nullptr, nullptr);
}

MotionCertificate certify_motion(const ArmCollisionChecker& checker, const JointAngles& from_given,
                                 const JointAngles& to_given, const ArmClearances* from_clearances,
                                 const ArmClearances* to_clearances) {
  require_arm_size(checker, from_given, "from");
  require_arm_size(checker, to_given, "to");
  const std::size_t n = from_given.size();
  JointAngles from(n), to(n), turn(n);
  for (std::size_t j = 0; j < n; ++j) {
    from[j] = normalize_angle(from_given[j]);  // throws for non-finite angles
    to[j] = normalize_angle(to_given[j]);
    turn[j] = signed_angle_difference(from[j], to[j]);
  }
  // Clearances are about the configuration measured; the motion's ends are the normalised angles.
  if (from != from_given) from_clearances = nullptr;
  if (to != to_given) to_clearances = nullptr;

  MotionCertificate certificate;
  const auto collides = [&](double at, const ArmContact& contact) {
    certificate.verdict = MotionCertificate::Verdict::collides;
    certificate.at = at;
    certificate.contact = contact;
    return certificate;
  };
  // The goal first, bit for bit: the path a planner returns ends at exactly this value, and a
  // motion into a collision needs no clearance measured.
  if (to_clearances) {
    if (to_clearances->contact) return collides(1, *to_clearances->contact);
  } else if (const auto contact = checker.first_contact(to_given)) {
    return collides(1, *contact);
  }
  if (from_clearances && from_clearances->contact) return collides(0, *from_clearances->contact);

  if (std::all_of(turn.begin(), turn.end(), [](double d) { return d == 0; })) {
    // Nothing turns: every configuration of the motion is the normalised `from` (= `to`).
    if (const auto contact = checker.first_contact(from_given)) return collides(0, *contact);
    if (from != from_given && from != to_given)
      if (const auto contact = checker.first_contact(from)) return collides(0.5, *contact);
    certificate.verdict = MotionCertificate::Verdict::free;
    return certificate;
  }

  std::vector<Range> real;
  real_turns(from, to, turn, real);
  JointAngles largest_turn(n);
  for (std::size_t j = 0; j < n; ++j) largest_turn[j] = std::max(-real[j][0], real[j][1]);
  std::vector<double> link_speed, pair_speed;
  motion_speeds(checker.arm(), largest_turn, link_speed, pair_speed);
  // The known ends: [0, t) is free by `from`'s clearances, (1 − tail, 1] by `to`'s. What is left
  // to cover is [t, end] — up to the tail, or to 1 without one — with end above 1 − tail by at
  // least an ulp (so reaching end covers the tail's open boundary), and end = 1 without a tail
  // (reaching beyond 1 is asked, as before).
  double t = from_clearances ? lasts_at(*from_clearances, link_speed, pair_speed) : 0;
  const double tail = to_clearances ? lasts_at(*to_clearances, link_speed, pair_speed) : 0;
  const double end = tail > 0 ? above(1 - tail) : 1.0;
  const auto covered = [&](double reached) { return tail > 0 ? reached >= end : reached > 1; };
  if (covered(t)) {
    certificate.verdict = MotionCertificate::Verdict::free;
    return certificate;
  }
  // The configuration measured at t: from + t·turn in doubles (not normalised: cos and sin do not
  // mind), within spread[j] of the true motion's from_j + t·D_j in each joint.
  JointAngles q = from;
  std::vector<double> spread(n, 0.0);  // t = 0 is `from` itself
  const auto move_to = [&](double at) {
    t = at;
    for (std::size_t j = 0; j < n; ++j) {
      q[j] = from[j] + t * turn[j];
      spread[j] = spread_of(q[j], from[j], t, real[j]);
    }
  };
  if (t > 0) move_to(t);
  while (certificate.steps < motion_max_steps) {
    // A step of at least `horizon` (above end − t) reaches past what is left.
    const double horizon = above(end - t);
    const ArmSafeStep step = checker.safe_step(q, link_speed, pair_speed, horizon, spread);
    ++certificate.steps;
    if (step.contact) return collides(t, *step.contact);
    if (step.step >= horizon) {
      certificate.verdict = MotionCertificate::Verdict::free;
      return certificate;
    }
    if (step.step < motion_min_step) break;  // near contact: the steps would not end
    // Every configuration before t + step is free; the next one measured is at or before it.
    const double next = below(t + step.step);
    if (next >= end) {  // then t + step > end (≥ 1 without a tail): all is covered
      certificate.verdict = MotionCertificate::Verdict::free;
      return certificate;
    }
    move_to(next);
  }
  // Advancement approaches a first contact from below and never lands on it: every step ends where
  // the bound allows the arm to touch, and the true motion is slower than the bound. So at a stall,
  // probe the exact configurations beyond t at doubling distances: one that collides proves that
  // the motion collides. When none does (a touch without crossing, or a slide at tiny clearance),
  // nothing is proved either way.
  JointAngles probe;
  for (double ahead = 2 * motion_min_step; t + ahead < 1; ahead *= 2) {
    interpolate_angles_into(from, to, t + ahead, probe);
    if (const auto contact = checker.first_contact(probe)) return collides(t + ahead, *contact);
  }
  certificate.verdict = MotionCertificate::Verdict::uncertified;
  certificate.at = t;
  return certificate;
}

JointSafeAngles::JointSafeAngles(const ArmCollisionChecker& checker) : checker_(&checker) {
  const std::size_t n = checker.arm().joints();
  JointAngles unit(n, 0.0);
  std::vector<double> links, pairs;
  for (std::size_t j = 0; j < n; ++j) {
    unit.assign(n, 0.0);
    unit[j] = 1;
    motion_speeds(checker.arm(), unit, links, pairs);
    link_speed_.insert(link_speed_.end(), links.begin(), links.end());
    pair_speed_.insert(pair_speed_.end(), pairs.begin(), pairs.end());
  }
  // The largest speed of a unit turn (that of the farthest link under joint 0): measuring
  // clearances up to enough · fastest_ is enough for every joint.
  for (const double v : link_speed_) fastest_ = std::max(fastest_, v);
  for (const double v : pair_speed_) fastest_ = std::max(fastest_, v);
}

bool JointSafeAngles::measure(const JointAngles& q, double enough, std::span<double> out) const {
  const std::size_t n = q.size();
  checker_->clearances(q, clearances_, detail::covered_above(fastest_, enough));
  if (clearances_.contact) return false;
  // As safe_step: a clearance c lasts c / v rounded down, forever when nothing moves, and not at
  // all when c = 0.
  const std::size_t pairs = clearances_.pairs.size();
  for (std::size_t j = 0; j < n; ++j) {
    double step = enough;
    for (std::size_t k = 0; k < n; ++k)
      step = std::min(step, detail::lasts_below(clearances_.links[k], link_speed_[j * n + k]));
    for (std::size_t p = 0; p < pairs; ++p)
      step = std::min(step, detail::lasts_below(clearances_.pairs[p], pair_speed_[j * pairs + p]));
    out[j] = step;
  }
  return true;
}

bool motion_is_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to) {
  return certify_motion(checker, from, to).free();
}

std::size_t motion_step_count(const JointAngles& from, const JointAngles& to, double resolution) {
  if (!(resolution > 0) || !std::isfinite(resolution))
    throw std::invalid_argument("motion: the resolution must be a positive finite angle");
  detail::require_same_size(from, to, "motion");
  double widest = 0;
  for (std::size_t i = 0; i < from.size(); ++i) widest = std::max(widest, angular_distance(from[i], to[i]));
  const double steps = std::ceil(widest / resolution);
  // A billion samples is a resolution error, not a motion anyone means to check.
  if (steps > 1e9) throw std::invalid_argument("motion: the resolution is too fine (over 10^9 samples)");
  return std::max<std::size_t>(1, static_cast<std::size_t>(steps));
}

std::vector<JointAngles> motion_samples(const JointAngles& from, const JointAngles& to, double resolution) {
  const std::size_t k = motion_step_count(from, to, resolution);
  std::vector<JointAngles> samples;
  samples.reserve(k + 1);
  samples.push_back(from);
  for (std::size_t j = 1; j < k; ++j)
    samples.push_back(interpolate_angles(from, to, static_cast<double>(j) / static_cast<double>(k)));
  samples.push_back(to);
  return samples;
}

}  // namespace polyplan
