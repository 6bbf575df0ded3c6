// arm/arm_motion: certified motions (conservative advancement) and the sampled check they replace,
// on hand-built cases, on the shipped data/arms files, and against dense independent sampling.
#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/arm_collision.hpp>
#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/io/arm_reader.hpp>
#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace polyplan;
using namespace polyplan::test;

// ---------------------------------------------------------------- the sampled check

TEST(Motion, SampleCountAndStepSize) {
  // Joint 0 turns 1 rad, joint 1 half of that: k = ceil(1 / 0.25) = 4 steps, 5 samples.
  const JointAngles from{0, 0}, to{1, 0.5};
  const auto samples = motion_samples(from, to, 0.25);
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(motion_step_count(from, to, 0.25), 4u);
  EXPECT_EQ(samples.front(), from);
  EXPECT_EQ(samples.back(), to);
  EXPECT_NEAR(samples[2][0], 0.5, 1e-15);
  EXPECT_NEAR(samples[2][1], 0.25, 1e-15);
  EXPECT_EQ(motion_samples(from, to, 0.3).size(), 5u);  // ceil(3.33) = 4
  EXPECT_EQ(motion_samples(from, to, 5).size(), 2u);    // at least one step
  EXPECT_EQ(motion_samples(from, from, 0.1).size(), 2u);
  // The ends are the given values bit for bit, even unnormalised.
  const auto raw = motion_samples({7.0}, {-1.0}, 0.01);
  EXPECT_EQ(raw.front(), JointAngles{7.0});
  EXPECT_EQ(raw.back(), JointAngles{-1.0});
  // Across 0 the short way, every step at most the resolution.
  const double resolution = 0.013;
  const JointAngles a{0.1, 3.0, 5.0}, b{two_pi - 0.1, 0.2, 5.0};
  const auto wrap = motion_samples(a, b, resolution);
  EXPECT_EQ(wrap.size(), static_cast<std::size_t>(std::ceil(angular_distance(3.0, 0.2) / resolution)) + 1);
  for (std::size_t i = 1; i < wrap.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j)
      ASSERT_LE(angular_distance(wrap[i - 1][j], wrap[i][j]), resolution * (1 + 1e-12));
  for (const auto& s : wrap) ASSERT_LE(angular_distance(s[0], 0), 0.1 + 1e-15);
  EXPECT_THROW(motion_samples(a, b, 0), std::invalid_argument);
  EXPECT_THROW(motion_samples(a, b, std::nan("")), std::invalid_argument);
  EXPECT_THROW(motion_samples(a, b, 1e-12), std::invalid_argument);  // over 10^9 samples
  EXPECT_THROW(motion_samples(a, {0.0}, 0.1), std::invalid_argument);
}

TEST(Motion, APointBetweenTwoFreeConfigurationsBlocksTheMotion) {
  // A point at (0, 1) and a link [2] 0.2 wide: the link holds the point while |θ − π/2| ≤
  // asin(0.1 / 1) = 0.1002. θ = π/2 ± 0.3 are both free; only the motion sweeps the point.
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(0, 1)});
  const JointAngles before{kPi / 2 - 0.3}, after{kPi / 2 + 0.3};
  ASSERT_TRUE(checker.is_free(before));
  ASSERT_TRUE(checker.is_free(after));
  EXPECT_FALSE(checker.is_free({kPi / 2 + 0.1}));
  EXPECT_TRUE(checker.is_free({kPi / 2 + 0.101}));
  EXPECT_FALSE(samples_free(checker, before, after, 0.01));
  EXPECT_FALSE(samples_free(checker, after, before, 0.01));
  EXPECT_FALSE(samples_free(checker, before, after, 0.2));  // samples at π/2 ± 0.1: both held
  // At resolution 0.7 the motion is one step: only its two free ends are checked, and it is
  // accepted. The resolution is part of the answer, as documented.
  EXPECT_EQ(motion_samples(before, after, 0.7).size(), 2u);
  EXPECT_TRUE(samples_free(checker, before, after, 0.7));
  // A motion that does not sweep the point: free. Every sample counts as a check.
  const std::size_t before_checks = checker.checks();
  EXPECT_TRUE(samples_free(checker, {0.2}, {0.4}, 0.05));
  EXPECT_EQ(checker.checks() - before_checks, 5u);
}

TEST(Motion, WrapsAroundTheShortWay) {
  // A point at (−1, 0) holds a link [2] 0.2 wide for |θ − π| ≤ 0.1002. From 3.0 to 3.3 the
  // short way passes π: blocked. From 0.1 to 2π − 0.1 the short way passes 0, far from π: free
  // (the long way round would have been blocked).
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(-1, 0)});
  ASSERT_TRUE(checker.is_free({3.0}));
  ASSERT_TRUE(checker.is_free({3.3}));
  EXPECT_FALSE(samples_free(checker, {3.0}, {3.3}, 0.01));
  EXPECT_TRUE(samples_free(checker, {0.1}, {two_pi - 0.1}, 0.01));
  EXPECT_FALSE(samples_free(checker, {two_pi - 0.1}, {kPi}, 0.01));  // ends on the point
}

// ---------------------------------------------------------------- certified motions

namespace {

constexpr double kDegree = two_pi / 360;

// An independent re-check: some configuration along the motion, every `step` radians of its
// widest joint (and the two ends), collides by checker.is_free alone.
bool dense_sampling_finds_a_collision(const ArmCollisionChecker& checker, const JointAngles& from,
                                      const JointAngles& to, double step) {
  double widest = 0;
  for (std::size_t j = 0; j < from.size(); ++j) widest = std::max(widest, angular_distance(from[j], to[j]));
  const auto samples = static_cast<int>(std::ceil(widest / step));
  if (!checker.is_free(from) || !checker.is_free(to)) return true;
  for (int i = 1; i < samples; ++i)
    if (!checker.is_free(interpolate_angles(from, to, static_cast<double>(i) / samples))) return true;
  return false;
}

}  // namespace

TEST(CertifiedMotion, OneDegreeSamplingMissesAPointThatLinkTwoCutsThrough) {
  // Links 1 and 1, 0.1 wide; both joints turn −10°, so 1° sampling checks 11 configurations. At
  // t = 0.55, between two samples, the corner at link 2's tip cuts through the point (0.6174,
  // −0.7225), 7.6 mm deep; at every sample the point is at least 0.2 mm outside.
  const ArmCollisionChecker checker(arm_of({1, 1}, 0.1), {}, {Eigen::Vector2d(0.6174, -0.7225)});
  const JointAngles from{0.3, -two_pi / 3}, to{0.3 - 10 * kDegree, -two_pi / 3 - 10 * kDegree};
  ASSERT_EQ(motion_step_count(from, to, kDegree), 10u);
  EXPECT_TRUE(samples_free(checker, from, to, kDegree));  // the sampled check is fooled
  const auto contact = checker.first_contact(interpolate_angles(from, to, 0.55));
  ASSERT_TRUE(contact);
  EXPECT_EQ(contact->describe(), "link 2 meets points[0]");

  const MotionCertificate certificate = certify_motion(checker, from, to);
  EXPECT_EQ(certificate.verdict, MotionCertificate::Verdict::collides);
  EXPECT_FALSE(certificate.free());
  ASSERT_TRUE(certificate.contact);
  EXPECT_EQ(certificate.contact->describe(), "link 2 meets points[0]");
  // The point is inside the link for t in about [0.501, 0.581]; `at` names a colliding configuration.
  EXPECT_GT(certificate.at, 0.5);
  EXPECT_LT(certificate.at, 0.59);
  EXPECT_FALSE(checker.is_free(interpolate_angles(from, to, certificate.at)));
  EXPECT_GT(certificate.steps, 1u);
  EXPECT_FALSE(motion_is_free(checker, from, to));
  EXPECT_FALSE(motion_is_free(checker, to, from));
}

TEST(CertifiedMotion, APointBetweenTwoFreeConfigurationsBlocksTheMotionAtEveryScale) {
  // The sampled test's case (above): a one-step sampled check at 0.7 rad accepts the motion over
  // the point; the certificate does not depend on a resolution.
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(0, 1)});
  const JointAngles before{kPi / 2 - 0.3}, after{kPi / 2 + 0.3};
  EXPECT_TRUE(samples_free(checker, before, after, 0.7));
  const MotionCertificate there = certify_motion(checker, before, after);
  EXPECT_EQ(there.verdict, MotionCertificate::Verdict::collides);
  // The link holds the point for |θ − π/2| ≤ 0.1002, i.e. t in [0.33, 0.67].
  EXPECT_GT(there.at, 0.3);
  EXPECT_LT(there.at, 0.67);
  EXPECT_EQ(certify_motion(checker, after, before).verdict, MotionCertificate::Verdict::collides);
  // Away from the point: free, and each clearance computation counts as a check.
  const std::size_t checks_before = checker.checks();
  const MotionCertificate away = certify_motion(checker, {0.2}, {0.4});
  EXPECT_TRUE(away.free());
  EXPECT_GE(away.steps, 1u);
  EXPECT_EQ(checker.checks() - checks_before, away.steps + 1);  // + the exact test of the goal
}

TEST(CertifiedMotion, WrapsAroundTheShortWay) {
  // A point at (−1, 0) holds a link [2] 0.2 wide for |θ − π| ≤ 0.1002: from 3.0 to 3.3 the short
  // way passes π; from 0.1 to 2π − 0.1 it passes 0, far from π.
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(-1, 0)});
  EXPECT_EQ(certify_motion(checker, {3.0}, {3.3}).verdict, MotionCertificate::Verdict::collides);
  EXPECT_TRUE(certify_motion(checker, {0.1}, {two_pi - 0.1}).free());
  const MotionCertificate onto = certify_motion(checker, {two_pi - 0.1}, {kPi});  // ends on the point
  EXPECT_EQ(onto.verdict, MotionCertificate::Verdict::collides);
  EXPECT_EQ(onto.at, 1.0);
  EXPECT_EQ(onto.steps, 0u);  // the goal is tested first
}

TEST(CertifiedMotion, ClearsAPointByAMillimetreAndByAMicrometre) {
  // Link [2], a segment, turns from 0.1 to 1.0; the point lies on the ray at 0.5, just beyond the
  // tip's circle: the tip passes it at 1 mm (1 µm). Closer than the rate bound can prove in one
  // step, but advancement slows near it and speeds up again.
  for (const double gap : {1e-3, 1e-6}) {
    const double r = 2 + gap;
    const ArmCollisionChecker checker(arm_of({2}), {}, {Eigen::Vector2d(r * std::cos(0.5), r * std::sin(0.5))});
    const MotionCertificate certificate = certify_motion(checker, {0.1}, {1.0});
    EXPECT_TRUE(certificate.free()) << gap;
    EXPECT_GT(certificate.steps, 5u) << gap;
    EXPECT_LT(certificate.steps, 200u) << gap;
  }
  // A point 1 mm inside the tip's circle and a link 1 cm wide: it collides.
  const double r = 2 - 1e-3;
  const ArmCollisionChecker inside(arm_of({2}, 0.01), {}, {Eigen::Vector2d(r * std::cos(0.5), r * std::sin(0.5))});
  const MotionCertificate hit = certify_motion(inside, {0.1}, {1.0});
  EXPECT_EQ(hit.verdict, MotionCertificate::Verdict::collides);
  EXPECT_NEAR(hit.at, 0.4 / 0.9, 0.01);
}

TEST(CertifiedMotion, AZeroWidthLinkSweepingOverAPointIsNeverFree) {
  // A segment crosses a point in a single instant: no sample lands on it and no clearance proves
  // the motion free. Advancement stalls just before the point: refused, not accepted.
  const double crossing = 0.5123456789;
  const ArmCollisionChecker checker(arm_of({2}), {}, {Eigen::Vector2d(std::cos(crossing), std::sin(crossing))});
  EXPECT_TRUE(samples_free(checker, {0.1}, {0.9}, kDegree / 100));  // sampling does not see it
  const MotionCertificate certificate = certify_motion(checker, {0.1}, {0.9});
  EXPECT_FALSE(certificate.free());
  EXPECT_NEAR(certificate.at, (crossing - 0.1) / 0.8, 1e-6);  // where it stopped: at the point
}

TEST(CertifiedMotion, StartOrGoalInCollision) {
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(0, 1)});
  const MotionCertificate from_inside = certify_motion(checker, {kPi / 2}, {kPi / 2 + 0.5});
  EXPECT_EQ(from_inside.verdict, MotionCertificate::Verdict::collides);
  EXPECT_EQ(from_inside.at, 0.0);
  EXPECT_EQ(from_inside.steps, 1u);
  ASSERT_TRUE(from_inside.contact);
  EXPECT_EQ(from_inside.contact->describe(), "link 1 meets points[0]");
  const MotionCertificate into = certify_motion(checker, {kPi / 2 + 0.5}, {kPi / 2});
  EXPECT_EQ(into.verdict, MotionCertificate::Verdict::collides);
  EXPECT_EQ(into.at, 1.0);
  EXPECT_EQ(into.steps, 0u);
  // Zero-length motions: free exactly when the configuration is, whatever turn it is written in.
  EXPECT_TRUE(certify_motion(checker, {7.0}, {7.0 - two_pi}).free());
  EXPECT_EQ(certify_motion(checker, {7.0}, {7.0 - two_pi}).steps, 0u);
  EXPECT_EQ(certify_motion(checker, {kPi / 2}, {kPi / 2 + two_pi}).verdict, MotionCertificate::Verdict::collides);
  // Sizes and angles are checked.
  EXPECT_THROW(certify_motion(checker, {0.0, 0.0}, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(certify_motion(checker, {0.0}, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(certify_motion(checker, {std::nan("")}, {0.0}), std::invalid_argument);
  EXPECT_THROW(motion_is_free(checker, {0.0}, {std::numeric_limits<double>::infinity()}), std::invalid_argument);
}

TEST(CertifiedMotion, SlidingAtATinyClearanceIsRefusedAtTheStepCap) {
  // The point is 1 µm behind the base of link [1]; as the link turns from −1 to 1 (pointing away),
  // it stays 1 µm from the point. Free, but each step proves only about 1 µm / 2 of the motion:
  // the step cap ends it, and the motion is refused.
  const ArmCollisionChecker behind(arm_of({1}), {}, {Eigen::Vector2d(-1e-6, 0)});
  EXPECT_FALSE(dense_sampling_finds_a_collision(behind, {-1.0}, {1.0}, 0.001));
  const MotionCertificate slide = certify_motion(behind, {-1.0}, {1.0});
  EXPECT_EQ(slide.verdict, MotionCertificate::Verdict::uncertified);
  EXPECT_EQ(slide.steps, motion_max_steps);
  EXPECT_GT(slide.at, 0.0);
  EXPECT_LT(slide.at, 0.01);
  EXPECT_FALSE(motion_is_free(behind, {-1.0}, {1.0}));
  // 1e-13 behind the base: the clearance, about 1e-13 less the true arm's radius of a few 1e-16,
  // proves steps of 5e-14 only, below motion_min_step: refused at once.
  const ArmCollisionChecker touching(arm_of({1}), {}, {Eigen::Vector2d(-1e-13, 0)});
  ASSERT_TRUE(touching.is_free({-1.0}));
  const MotionCertificate stuck = certify_motion(touching, {-1.0}, {1.0});
  EXPECT_EQ(stuck.verdict, MotionCertificate::Verdict::uncertified);
  EXPECT_EQ(stuck.steps, 1u);
  EXPECT_EQ(stuck.at, 0.0);
}

TEST(CertifiedMotion, SelfCollision) {
  // Links 2, 1, 2 folded into a U (link 3 above link 1, 1 apart). Link 3 swinging down from
  // heading π + 0.3 to π + 1.6 crosses link 1 (at heading 5π/4 it passes (1, 0)); both ends are
  // free (at π + 1.6 it passes x = 2.03, beyond link 1's tip).
  const ArmCollisionChecker self(arm_of({2, 1, 2}, 0, true), {}, {});
  const JointAngles swing_from{0, kPi / 2, kPi / 2 + 0.3}, swing_to{0, kPi / 2, kPi / 2 + 1.6};
  ASSERT_TRUE(self.is_free(swing_from));
  ASSERT_TRUE(self.is_free(swing_to));
  const MotionCertificate swing = certify_motion(self, swing_from, swing_to);
  EXPECT_EQ(swing.verdict, MotionCertificate::Verdict::collides);
  ASSERT_TRUE(swing.contact);
  EXPECT_EQ(swing.contact->describe(), "link 1 meets link 3");
  EXPECT_FALSE(self.is_free(interpolate_angles(swing_from, swing_to, swing.at)));
  // Without self-collision the links pass each other; nothing else is there: one step.
  const MotionCertificate apart = certify_motion(ArmCollisionChecker(arm_of({2, 1, 2}), {}, {}), swing_from, swing_to);
  EXPECT_TRUE(apart.free());
  EXPECT_EQ(apart.steps, 1u);
  // Link 3 wagging ±0.2 around the U stays at least 1 − 2 sin 0.2 = 0.6 above link 1: free.
  EXPECT_TRUE(certify_motion(self, {0, kPi / 2, kPi / 2 - 0.2}, {0, kPi / 2, kPi / 2 + 0.2}).free());
  // Turning the whole U by joint 1 alone moves links 1 and 3 rigidly together: their distance
  // cannot change (the pair's relative speed is 0), so one clearance computation proves it.
  const MotionCertificate rigid = certify_motion(self, {0, kPi / 2, kPi / 2}, {2, kPi / 2, kPi / 2});
  EXPECT_TRUE(rigid.free());
  EXPECT_EQ(rigid.steps, 1u);
  // 0.1 wide links: the swing collides; swung on to π + 1.7 link 3 clears link 1's tip corner
  // (2, 0.05) by 0.129 − 0.05 at its goal, and the motion is still blocked in between.
  const ArmCollisionChecker wide(arm_of({2, 1, 2}, 0.1, true), {}, {});
  const JointAngles wide_from = swing_from, wide_to{0, kPi / 2, kPi / 2 + 1.7};
  ASSERT_TRUE(wide.is_free(wide_from));
  ASSERT_TRUE(wide.is_free(wide_to));
  EXPECT_EQ(certify_motion(wide, wide_from, wide_to).verdict, MotionCertificate::Verdict::collides);
}

namespace {

// Counts of certify_motion's verdicts over many motions, each checked against dense sampling.
struct Verdicts {
  int free = 0, collides = 0, uncertified = 0;
};

// certify_motion must never call a motion free that dense independent sampling (every 0.001 rad)
// sees collide; a "collides" must name a configuration that collides.
void check_against_dense_sampling(const ArmCollisionChecker& checker, const JointAngles& from, const JointAngles& to,
                                  Verdicts& verdicts) {
  const MotionCertificate certificate = certify_motion(checker, from, to);
  const bool dense_collides = dense_sampling_finds_a_collision(checker, from, to, 0.001);
  switch (certificate.verdict) {
    case MotionCertificate::Verdict::free:
      ++verdicts.free;
      ASSERT_FALSE(dense_collides) << "certified a colliding motion";
      break;
    case MotionCertificate::Verdict::collides: {
      ++verdicts.collides;
      const JointAngles& at = certificate.at == 0   ? from
                              : certificate.at == 1 ? to
                                                    : interpolate_angles(from, to, certificate.at);
      ASSERT_FALSE(checker.is_free(at)) << "a collision at t = " << certificate.at << " that is not one";
      break;
    }
    case MotionCertificate::Verdict::uncertified: ++verdicts.uncertified; break;
  }
}

JointAngles random_configuration(std::mt19937& rng, std::size_t joints) {
  std::uniform_real_distribution<double> angle(0, two_pi);
  JointAngles q(joints);
  for (double& a : q) a = angle(rng);
  return q;
}

// A motion from a random configuration: every joint turns by up to `spread` either way.
JointAngles random_neighbour(std::mt19937& rng, const JointAngles& from, double spread) {
  std::uniform_real_distribution<double> turn(-spread, spread);
  JointAngles to = from;
  for (double& a : to) a = normalize_angle(a + turn(rng));
  return to;
}

}  // namespace

TEST(CertifiedMotion, NeverFreeWhereDenseSamplingCollidesOnTheShippedArms) {
  std::mt19937 rng(2024);
  for (const char* file : {"two_link_points.json", "three_link_forest.json", "four_link_forest.json"}) {
    const ArmProblem p = read_arm_problem(arm_data_file(file));
    const ArmCollisionChecker checker(p);
    Verdicts verdicts;
    for (int i = 0; i < 400; ++i) {
      // Short moves like the grid planner's, and longer joins.
      const JointAngles from = random_configuration(rng, p.arm.joints());
      const JointAngles to = random_neighbour(rng, from, i % 3 == 0 ? 1.0 : 0.15);
      check_against_dense_sampling(checker, from, to, verdicts);
      if (HasFatalFailure()) return;
    }
    SCOPED_TRACE(file);
    RecordProperty(std::string(file) + " free/collides/uncertified", std::to_string(verdicts.free) + "/" +
                                                                         std::to_string(verdicts.collides) + "/" +
                                                                         std::to_string(verdicts.uncertified));
    EXPECT_GT(verdicts.free, 20);  // both answers occur: the test can fail
    EXPECT_GT(verdicts.collides, 20);
    EXPECT_LT(verdicts.uncertified, 10);
  }
}

TEST(CertifiedMotion, NeverFreeWhereDenseSamplingCollidesAmongRandomPoints) {
  // Random arms of 2 to 4 links (segments or rectangles, with or without self-collision) among
  // 30 random points, random motions of up to 0.5 rad per joint. Zero-width links cross points in
  // single instants, so there many motions are refused (uncertified), never accepted.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  Verdicts verdicts;
  for (int world = 0; world < 60; ++world) {
    const std::size_t joints = 2 + world % 3;
    std::vector<double> links(joints);
    for (double& l : links) l = 0.5 + unit(rng);
    const double width = world % 2 == 0 ? 0.0 : 0.05 + 0.2 * unit(rng);
    const Arm arm = arm_of(links, width, world % 4 == 1);
    std::vector<Eigen::Vector2d> points(30);
    for (Eigen::Vector2d& point : points) {
      const double r = arm.reach() * std::sqrt(unit(rng)), phi = two_pi * unit(rng);
      point = {r * std::cos(phi), r * std::sin(phi)};
    }
    const ArmCollisionChecker checker(arm, {}, points);
    for (int i = 0; i < 20; ++i) {
      const JointAngles from = random_configuration(rng, joints);
      check_against_dense_sampling(checker, from, random_neighbour(rng, from, 0.5), verdicts);
      if (HasFatalFailure()) return;
    }
  }
  RecordProperty("free/collides/uncertified", std::to_string(verdicts.free) + "/" + std::to_string(verdicts.collides) +
                                                  "/" + std::to_string(verdicts.uncertified));
  EXPECT_GT(verdicts.free, 60);
  EXPECT_GT(verdicts.collides, 200);
}

TEST(CertifiedMotion, NeverFreeWhereDenseSamplingCollidesWithSelfCollision) {
  // Random folding arms of 3 to 5 links, thin rectangles (0.01 to 0.05 wide) that may collide only
  // with each other, random motions of up to 1.5 rad per joint: the links sweep across each other.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(0, 1);
  Verdicts verdicts;
  for (int arm_number = 0; arm_number < 40; ++arm_number) {
    std::vector<double> links(3 + arm_number % 3);
    for (double& l : links) l = 0.5 + unit(rng);
    const ArmCollisionChecker checker(arm_of(links, 0.01 + 0.04 * unit(rng), true), {}, {});
    for (int i = 0; i < 25; ++i) {
      const JointAngles from = random_configuration(rng, links.size());
      check_against_dense_sampling(checker, from, random_neighbour(rng, from, 1.5), verdicts);
      if (HasFatalFailure()) return;
    }
  }
  RecordProperty("free/collides/uncertified", std::to_string(verdicts.free) + "/" + std::to_string(verdicts.collides) +
                                                  "/" + std::to_string(verdicts.uncertified));
  EXPECT_GT(verdicts.free, 100);
  EXPECT_GT(verdicts.collides, 100);
}

TEST(ReusedClearances, NeverFreeWhereDenseSamplingCollidesAndMeasureLess) {
  // What a tree node keeps (its clearances) certifies the ends of every motion that leaves or
  // reaches it: the verdicts are those of the plain certificate's kind — never free where dense
  // sampling collides — with fewer clearances measured, none at all where the ends' free stretches
  // meet.
  std::mt19937 rng(2031);
  std::size_t free = 0, refused = 0;
  for (const char* file : {"three_link_forest.json", "four_link_dense.json", "six_link_forest.json"}) {
    SCOPED_TRACE(file);
    const ArmProblem p = read_arm_problem(arm_data_file(file));
    const ArmCollisionChecker checker(p);
    std::size_t plain_steps = 0, reused_steps = 0, both_free = 0, measured_nothing = 0, agree = 0, motions = 0;
    ArmClearances from_clearances, to_clearances;
    while (motions < 150) {
      const JointAngles from = random_configuration(rng, p.arm.joints());
      const JointAngles to = random_neighbour(rng, from, motions % 2 == 0 ? 0.6 : 0.1);
      if (!checker.is_free(from) || !checker.is_free(to)) continue;
      ++motions;
      measure_end_clearances(checker, from, from_clearances);
      measure_end_clearances(checker, to, to_clearances);
      ASSERT_FALSE(from_clearances.contact);
      const MotionCertificate plain = certify_motion(checker, from, to);
      const MotionCertificate reused = certify_motion(checker, from, to, &from_clearances, &to_clearances);
      if (reused.free()) {
        ++free;
        ASSERT_FALSE(dense_sampling_finds_a_collision(checker, from, to, 0.001)) << "certified a colliding motion";
      } else {
        ++refused;
        if (reused.verdict == MotionCertificate::Verdict::collides) {  // braces: ASSERT_FALSE is an if-else
          ASSERT_FALSE(checker.is_free(interpolate_angles(from, to, reused.at)));
        }
      }
      agree += plain.free() == reused.free();
      if (plain.free() && reused.free()) plain_steps += plain.steps, reused_steps += reused.steps, ++both_free;
      measured_nothing += reused.free() && reused.steps == 0;
    }
    EXPECT_GE(agree, motions - 3);  // the same proofs, met at other points of the motion
    // A free motion measures at least one clearance fewer (its first step; mostly its last too):
    // the many steps of a long motion through clutter remain.
    EXPECT_LE(reused_steps + both_free, plain_steps) << reused_steps << " against " << plain_steps;
    EXPECT_GT(measured_nothing, 5u);
  }
  EXPECT_GT(free, 100u);  // both answers occur: the test can fail
  EXPECT_GT(refused, 30u);
}

TEST(ReusedClearances, AnEndThatCollidesRefusesTheMotionAndUnnormalisedEndsAreMeasuredAgain) {
  // A point at (0, 1) and a link [2] 0.2 wide (as above): π/2 holds the point.
  const ArmCollisionChecker checker(arm_of({2}, 0.2), {}, {Eigen::Vector2d(0, 1)});
  ArmClearances blocked, free_end;
  measure_end_clearances(checker, {kPi / 2}, blocked);
  ASSERT_TRUE(blocked.contact);
  measure_end_clearances(checker, {kPi}, free_end);
  ASSERT_FALSE(free_end.contact);
  EXPECT_EQ(certify_motion(checker, {kPi / 2}, {kPi}, &blocked, &free_end).verdict,
            MotionCertificate::Verdict::collides);
  EXPECT_EQ(certify_motion(checker, {kPi}, {kPi / 2}, &free_end, &blocked).at, 1.0);
  // Clearances handed over for an unnormalised angle are not used (the motion starts at the
  // normalised one): with the collision's clearances given for the free 2π + π, the motion is
  // still certified, from scratch.
  const MotionCertificate fresh = certify_motion(checker, {two_pi + kPi}, {kPi + 0.1}, &blocked, nullptr);
  EXPECT_TRUE(fresh.free());
  EXPECT_GE(fresh.steps, 1u);
}

// ---------------------------------------------------------------- shipped arms

TEST(ArmData, TwoLinkPointsQueriesAreFreeAndTheStraightMotionsAreAsDesigned) {
  const ArmProblem p = read_arm_problem(arm_data_file("two_link_points.json"));
  EXPECT_EQ(p.arm.links, (std::vector<double>{5, 5}));
  EXPECT_GT(p.arm.link_width, 0);
  EXPECT_GE(p.points.size(), 20u);
  EXPECT_LE(p.points.size(), 40u);
  const ArmCollisionChecker checker(p);
  ASSERT_EQ(p.queries.size(), 3u);
  const std::vector<std::string> names{"easy", "medium", "hard"};
  for (std::size_t i = 0; i < 3; ++i) {
    const ArmQuery& q = p.queries[i];
    EXPECT_EQ(q.name, names[i]);
    EXPECT_TRUE(checker.is_free(q.start)) << q.name;
    EXPECT_TRUE(checker.is_free(q.goal)) << q.name;
  }
  // easy on the torus: θ1 fixed, θ2 from 0.12 back through 0 to 6.00 (0.40 rad) is free...
  EXPECT_NEAR(total_angular_distance(p.queries[0].start, p.queries[0].goal), 0.4031853071795866, 1e-12);
  EXPECT_TRUE(samples_free(checker, p.queries[0].start, p.queries[0].goal, two_pi / 3600));
  EXPECT_TRUE(motion_is_free(checker, p.queries[0].start, p.queries[0].goal));  // and certified
  // ...while the long way up at θ1 = 0.76 is blocked (by the group of points above the arm).
  bool long_way_blocked = false;
  for (int k = 0; k <= 1000 && !long_way_blocked; ++k)
    long_way_blocked = !checker.is_free({0.76, 0.12 + 5.88 * k / 1000});
  EXPECT_TRUE(long_way_blocked);
  // hard: the straight short-way motion crosses the wall that separates it on the bounded square.
  EXPECT_FALSE(samples_free(checker, p.queries[2].start, p.queries[2].goal, two_pi / 3600));
  EXPECT_EQ(certify_motion(checker, p.queries[2].start, p.queries[2].goal).verdict,
            MotionCertificate::Verdict::collides);
}

TEST(ArmData, ForestsAreSeed001sArmsAndTheirStartAndGoalAreFree) {
  struct Forest {
    const char* file;
    std::size_t links;
    JointAngles start, goal;
  };
  for (const Forest& f : {Forest{"three_link_forest.json", 3, {1.0, 0.5, 5.0}, {4.0, 1.0, 1.0}},
                          Forest{"four_link_forest.json", 4, {0.1, 0.2, 0.3, 0.4}, {5.0, 1.0, 5.0, 0.5}}}) {
    const ArmProblem p = read_arm_problem(arm_data_file(f.file));
    EXPECT_EQ(p.arm.links, std::vector<double>(f.links, 1.0)) << f.file;
    EXPECT_EQ(p.arm.link_width, 0) << f.file;
    EXPECT_EQ(p.obstacles.size(), 4 * f.links) << f.file;
    for (const PolygonWithHoles& t : p.obstacles) {  // the seed's triangle on the half grid
      ASSERT_EQ(t.outer.size(), 3u);
      const Rational x = t.outer[0].x, y = t.outer[0].y;
      EXPECT_EQ(Rational(2 * x).get_den(), 1);
      EXPECT_EQ(Rational(2 * y).get_den(), 1);
      EXPECT_TRUE(x >= -static_cast<long>(f.links) && x < static_cast<long>(f.links));
      EXPECT_EQ(t.outer[1], (ExactPoint{x + Rational(1, 2), y}));
      EXPECT_EQ(t.outer[2], (ExactPoint{x + Rational(1, 4), y + Rational(1, 2)}));
    }
    ASSERT_EQ(p.queries.size(), 1u);
    EXPECT_EQ(p.queries[0].start, f.start);
    EXPECT_EQ(p.queries[0].goal, f.goal);
    const ArmCollisionChecker checker(p);
    EXPECT_TRUE(checker.is_free(f.start)) << f.file;
    EXPECT_TRUE(checker.is_free(f.goal)) << f.file;
    EXPECT_FALSE(samples_free(checker, f.start, f.goal, two_pi / 360))
        << f.file << ": the straight motion should need planning";
    EXPECT_EQ(certify_motion(checker, f.start, f.goal).verdict, MotionCertificate::Verdict::collides) << f.file;
  }
}

// ---------------------------------------------------------------- single-joint safe angles

// One unit segment link at angle 0 and a point at distance 0.5 in direction 0.3 rad: the link
// first touches it after turning 0.3 rad counter-clockwise. The safe angle is the clearance
// (0.5·sin 0.3, the point's distance to the link) over the tip's speed (1 per radian): a lower
// bound of 0.3, and that value up to the enclosure of the true arm (a few ulps).
TEST(JointSafeAngles, OneLinkAndAPoint) {
  ArmProblem p;
  p.arm.links = {1};
  p.points = {{0.5 * std::cos(0.3), 0.5 * std::sin(0.3)}};
  const ArmCollisionChecker checker(p);
  const JointSafeAngles safe(checker);
  std::vector<double> out(1);
  ASSERT_TRUE(safe.measure({0.0}, 10, out));
  EXPECT_NEAR(out[0], 0.5 * std::sin(0.3), 1e-10);
  EXPECT_LT(out[0], 0.3);
  // Capped: a clearance beyond what the caller needs is reported as that need.
  ASSERT_TRUE(safe.measure({0.0}, 0.01, out));
  EXPECT_EQ(out[0], 0.01);
  EXPECT_FALSE(safe.measure({0.3}, 10, out)) << "the link lies on the point";
}

// Two unit links, a point near link 2 only: joint 2 moves link 2 at radius 1, joint 1 at radius 2,
// so joint 1's safe angle is half of joint 2's.
TEST(JointSafeAngles, TheFartherAJointFromTheTipTheSmallerItsAngle) {
  ArmProblem p;
  p.arm.links = {1, 1};
  p.points = {{1.5, 0.1}};
  const ArmCollisionChecker checker(p);
  const JointSafeAngles safe(checker);
  std::vector<double> out(2);
  ASSERT_TRUE(safe.measure({0.0, 0.0}, 10, out));
  EXPECT_NEAR(out[1], 0.1, 1e-10);
  EXPECT_NEAR(out[0], 0.05, 1e-10);
}

// On the shipped 4R forest, at random free configurations: turning any one joint by its safe angle
// either way is a motion certify_motion proves free, and dense samples along it are free.
TEST(JointSafeAngles, EveryStretchIsFreeOnTheForest) {
  const ArmProblem p = read_arm_problem(arm_data_file("four_link_forest.json"));
  const ArmCollisionChecker checker(p);
  const JointSafeAngles safe(checker);
  std::mt19937 random(14);
  std::uniform_real_distribution<double> angle(0, two_pi);
  std::vector<double> out(4);
  int measured = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const JointAngles q{angle(random), angle(random), angle(random), angle(random)};
    if (!safe.measure(q, 1.0, out)) {
      EXPECT_FALSE(checker.is_free(q));
      continue;
    }
    ++measured;
    for (std::size_t j = 0; j < 4; ++j)
      for (const double sign : {-1.0, 1.0}) {
        if (out[j] == 0) continue;
        JointAngles to = q;
        to[j] += sign * out[j] * (1 - 1e-9);
        EXPECT_TRUE(certify_motion(checker, q, to).free()) << "trial " << trial << " joint " << j;
        EXPECT_TRUE(samples_free(checker, q, to, out[j] / 200)) << "trial " << trial << " joint " << j;
      }
  }
  EXPECT_GT(measured, 30);
}
