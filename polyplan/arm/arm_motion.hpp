#pragma once
// Motions between two configurations: every joint turns the short way round at a constant rate
// (the course's arm and car planning report's interpolation): θ_j(t) = from_j + t·Δ_j, Δ_j =
// signed_angle_difference(from_j, to_j), t ∈ [0, 1] (interpolate_angles_into). A joint exactly a half turn from its
// goal turns counter-clockwise (signed_angle_difference's +π), so such a motion and its reverse sweep different half
// circles.
//
// certify_motion proves a motion free for every t, not only at samples (docs/design.md: motions are
// certified, never sampled), by conservative advancement. The motion proved is the true one: the
// true arm (arm_collision.hpp) along θ_j(t) = from_j + t·D_j between the normalised ends, D_j the
// real turn (to_j − from_j, shifted by 2π where signed_angle_difference shifts it):
//  - Motion bound. Over [t, t + h] every point of links[k] moves at most h · speed_k,
//    speed_k = Σ_{j ≤ k} R_{j,k} |D_j|, where R_{j,k} = (links[j] + … + links[k]) + w/2 bounds the
//    distance from joint j to any point of links[k] in every configuration (a point's velocity is
//    Σ_j θ_j' · (p − J_j) turned by 90°). For self-collision, links[m] moves relative to links[k]
//    (k < m) only through joints k+1 … m (joints 0 … k turn both rigidly, which keeps their
//    distance), so at most h · Σ_{k < j ≤ m} R_{j,m} |D_j|. Sums and products rounded up, |D_j|
//    from an interval enclosing it.
//  - Clearance. ArmCollisionChecker::safe_step measures lower bounds c of the true arm's distances
//    at every configuration within `spread` of the computed q(t) = from + t·Δ (doubles, Δ the
//    double turn), the spread enclosing the true θ(t) in interval arithmetic, and returns
//    h = the smallest c / speed rounded down: every configuration in [t, t + h) is free.
//  - Advancement. The goal `to` itself (bit for bit) is tested exactly first. Then from t = 0
//    (the normalised `from`) the motion advances to t ← t + h rounded down; it is free once h
//    exceeds 1 − t, and collides when q(t) collides (exactly). Near contact the steps become tiny:
//    when h falls below motion_min_step or after motion_max_steps clearance computations,
//    advancement stops.
//  - Probing. Advancement approaches a first contact from below and never lands on it, so after a
//    stop the configurations at t + 2·motion_min_step, t + 4·motion_min_step, … (doubling, up to
//    the end) are tested exactly: one that collides proves the motion collides. Otherwise the
//    motion is refused, "uncertified", never "free": a motion that touches something without
//    crossing into it (a zero-width link sweeping over a point crosses it in a single instant), or
//    slides along something at a small clearance for long, cannot be decided this way.
//
// Angles are normalised before interpolating (geometry/angles.hpp), with the double two_pi: an
// angle a far from [0, 2π) and normalize_angle(a) are different real angles (by a multiple of
// 2π − two_pi ≈ 2.4e-16), and the certificate is about the normalised ones. Planners return
// normalised configurations.
//
// motion_samples gives `from`, k−1 interpolated configurations and `to` itself, with
// k = max(1, ceil(max_i angular_distance(from_i, to_i) / resolution)), so consecutive samples differ
// by at most `resolution` radians in every joint (up to rounding): frames for pictures, and what
// tests sample densely to check a certificate independently. Checking samples is not a certificate.
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/geometry/angles.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace polyplan {

// certify_motion's limits: at most this many clearance computations per motion, and no step
// (as a fraction of the motion) below this. Either limit reached: the motion is uncertified.
inline constexpr std::size_t motion_max_steps = 10000;
inline constexpr double motion_min_step = 1e-12;

struct MotionCertificate {
  enum class Verdict { free, collides, uncertified };
  Verdict verdict = Verdict::uncertified;
  std::size_t steps = 0;  // configurations whose clearance was computed
  // collides/uncertified: the fraction t of the motion where it stopped (collides: a configuration
  // q(at) that collides, exactly; uncertified: the first configuration not proved free).
  double at = 0;
  std::optional<ArmContact> contact;  // collides: what the arm meets there
  bool free() const { return verdict == Verdict::free; }
};

// The motion from → to by conservative advancement (above). `at` is 1 when the goal collides, 0
// when `from` does. A zero-length motion (every Δ_j = 0) is free when `from`, `to` and the
// normalised `from` are. checker.checks() grows by `steps` plus the exact tests of the goal, of a
// zero-length motion and of the probes.
// Throws std::invalid_argument for sizes that differ from the arm or non-finite angles.
MotionCertificate certify_motion(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to);

// certify_motion(checker, from, to).free(): false for colliding and for uncertified motions.
bool motion_is_free(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to);

// Reused clearances (issue 31; docs/certification.md, "Reused clearances"). A configuration's
// clearances, measured once (measure_end_clearances), prove every motion that leaves it free for a
// while: over [0, h) with h = min_k c_k / speed_k and likewise for the link pairs — the first step
// of conservative advancement, for any motion, since the speeds are the motion's own. By symmetry
// a motion that arrives at a configuration is free over its last h of time: the true motion run
// backwards leaves it with the same speeds. So the motion from → to is free when h_from + h_to > 1
// (the two ends' free stretches cover it, nothing measured), and otherwise only the stretch
// between them is advanced over. A planner keeps each node's clearances and passes them here.
//
// The clearances of q for that use (ClearanceUse::stepping, nothing left unmeasured): `contact` is
// set when q collides.
void measure_end_clearances(const ArmCollisionChecker& checker, const JointAngles& q, ArmClearances& out);
// certify_motion with the ends' clearances, each measured by measure_end_clearances at that very
// configuration (bit for bit) or null when not known. Clearances of an end that is not normalised
// are not used (the motion's end is its normalised angle, a slightly different real angle).
MotionCertificate certify_motion(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to,
                                 const ArmClearances* from_clearances, const ArmClearances* to_clearances);

// How far each joint alone may turn from a configuration q, either way, with every configuration
// on the way free: the same motion bound and clearances as certify_motion's first step, for the
// motion that turns joint j only (links before j stand still); a turn below safe[j] keeps the
// true arm free. A grid planner measures this once per cell: a move of δ (a real turn) along
// joint j between cells a and b is then free when safe(a)[j] + safe(b)[j] > δ (the two ends'
// free stretches cover it), with no motion certified.
class JointSafeAngles {
 public:
  explicit JointSafeAngles(const ArmCollisionChecker& checker);
  // out[j] (out.size() == joints): a lower bound, in radians, of how far joint j may turn (every
  // turn below it free); a value of at least `enough` may be reported as `enough`. False (and out
  // untouched) when q collides.
  bool measure(const JointAngles& q, double enough, std::span<double> out) const;

 private:
  const ArmCollisionChecker* checker_;
  std::vector<double> link_speed_, pair_speed_;  // per joint j: the speeds of a unit turn of j alone
  double fastest_ = 0;                           // the largest of them
  mutable ArmClearances clearances_;
};

// k above (the number of steps between samples). Throws std::invalid_argument when the sizes
// differ, an angle is not finite, the resolution is not positive and finite, or k would exceed 10^9.
std::size_t motion_step_count(const JointAngles& from, const JointAngles& to, double resolution);

// The k+1 samples above: `from` itself, k−1 interpolated configurations, `to` itself (bit for bit:
// the path a planner returns begins and ends at the exact values it was given).
std::vector<JointAngles> motion_samples(const JointAngles& from, const JointAngles& to, double resolution);

}  // namespace polyplan
