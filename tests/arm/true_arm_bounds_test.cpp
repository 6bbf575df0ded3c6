// The enclosure of the true arm that every arm certificate rests on (arm/detail/true_arm_bounds.hpp),
// checked against MPFR at 256 bits: libm's cos and sin keep within the error the enclosure
// assumes, and the true joints and corners lie within the radii it gives.
#include <polyplan/arm/arm.hpp>
#include <polyplan/arm/detail/true_arm_bounds.hpp>

#include "arm/arm_fixtures.hpp"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <cfenv>
#include <cmath>
#include <random>
#include <vector>

namespace polyplan::test {
namespace {

// An MPFR number at 256 bits, freed on leaving scope.
struct Real {
  mpfr_t v;
  Real() { mpfr_init2(v, 256); }
  explicit Real(double x) : Real() { mpfr_set_d(v, x, MPFR_RNDN); }
  ~Real() { mpfr_clear(v); }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
};

// |computed − the real function at x|, rounded up to a double.
double trig_miss(double x, bool cosine) {
  Real arg(x), exact, miss;
  if (cosine) mpfr_cos(exact.v, arg.v, MPFR_RNDN);
  else mpfr_sin(exact.v, arg.v, MPFR_RNDN);
  Real computed(cosine ? std::cos(x) : std::sin(x));
  mpfr_sub(miss.v, computed.v, exact.v, MPFR_RNDN);
  return std::fabs(mpfr_get_d(miss.v, MPFR_RNDU));
}

TEST(TrueArmBounds, LibmCosAndSinKeepWithinTheErrorTheEnclosureAssumes) {
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> heading(-130.0, 130.0);  // ten links' sums of angles, and more
  double worst = 0;
  for (int i = 0; i < 100000; ++i) {
    const double x = heading(random);
    worst = std::max({worst, trig_miss(x, true), trig_miss(x, false)});
  }
  // Where the results are near ±1 and 0 (their ulps the largest and the smallest).
  for (int k = -80; k <= 80; ++k)
    for (const double x : {k * (two_pi / 4), up(k * (two_pi / 4)), down(k * (two_pi / 4))})
      worst = std::max({worst, trig_miss(x, true), trig_miss(x, false)});
  EXPECT_LE(worst, detail::trig_error);
  EXPECT_LE(worst, detail::trig_error / 4) << "glibc documents 1 ulp; the bound assumes 4";
}

// A point of the true arm, at 256 bits.
struct RealPoint {
  Real x, y;
};

// |(px, py) − p|, rounded down to a double: how far a computed point lies from a true one.
double miss(const Eigen::Vector2d& computed, const RealPoint& p) {
  Real dx(computed.x()), dy(computed.y()), d;
  mpfr_sub(dx.v, dx.v, p.x.v, MPFR_RNDN), mpfr_sub(dy.v, dy.v, p.y.v, MPFR_RNDN);
  mpfr_hypot(d.v, dx.v, dy.v, MPFR_RNDN);
  return mpfr_get_d(d.v, MPFR_RNDD);
}

// The true arm at the angles q (reals): its joints, and the corners of each link's rectangle in
// link_outline_into's order (joint k − n, joint k+1 − n, joint k+1 + n, joint k + n, n = (w/2)(−sin, cos)).
void true_arm(const Arm& arm, const std::vector<Real>& q, std::vector<RealPoint>& joints,
              std::vector<RealPoint>& corners) {
  const std::size_t n = arm.joints();
  joints = std::vector<RealPoint>(n + 1);
  corners = std::vector<RealPoint>(4 * n);
  Real heading, c, s, t, nx, ny;
  mpfr_set_zero(heading.v, 1);
  mpfr_set_zero(joints[0].x.v, 1), mpfr_set_zero(joints[0].y.v, 1);
  for (std::size_t k = 0; k < n; ++k) {
    mpfr_add(heading.v, heading.v, q[k].v, MPFR_RNDN);
    mpfr_sin_cos(s.v, c.v, heading.v, MPFR_RNDN);
    mpfr_mul_d(t.v, c.v, arm.links[k], MPFR_RNDN), mpfr_add(joints[k + 1].x.v, joints[k].x.v, t.v, MPFR_RNDN);
    mpfr_mul_d(t.v, s.v, arm.links[k], MPFR_RNDN), mpfr_add(joints[k + 1].y.v, joints[k].y.v, t.v, MPFR_RNDN);
    mpfr_mul_d(nx.v, s.v, -arm.link_width / 2, MPFR_RNDN), mpfr_mul_d(ny.v, c.v, arm.link_width / 2, MPFR_RNDN);
    const std::size_t joint_of[4] = {k, k + 1, k + 1, k};
    for (std::size_t i = 0; i < 4; ++i) {
      const auto add = i < 2 ? mpfr_sub : mpfr_add;
      add(corners[4 * k + i].x.v, joints[joint_of[i]].x.v, nx.v, MPFR_RNDN);
      add(corners[4 * k + i].y.v, joints[joint_of[i]].y.v, ny.v, MPFR_RNDN);
    }
  }
}

TEST(TrueArmBounds, TheTrueArmLiesWithinTheRadiiAndTheRadiiAreTight) {
  std::mt19937_64 random(2929);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> joints, directions;
  std::vector<double> headings;
  std::vector<RealPoint> true_joints, true_corners;
  double largest_radius = 0, largest_miss = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(unit(random) * 10);
    std::vector<double> links(n);
    for (double& l : links) l = 0.1 + 3 * unit(random);
    const Arm arm = arm_of(links, trial % 2 ? 0.0 : 0.3 * unit(random));
    JointAngles q(n);
    for (double& a : q) a = (unit(random) - 0.25) * 2 * two_pi;  // also negative and beyond 2π
    const double spread = trial % 3 == 0 ? 0.0 : 1e-9 * unit(random);
    const std::vector<double> spreads(n, spread);
    joint_positions_into(arm, q, joints, &headings, &directions);
    detail::TrueArmBounds bounds(arm);
    std::vector<std::array<Eigen::Vector2d, 4>> corners(n);
    std::vector<std::size_t> used(n);
    for (std::size_t k = 0; k < n; ++k) used[k] = link_outline_into(arm, joints, k, corners[k]);
    std::vector<double> radius(n);
    std::fesetround(FE_UPWARD);  // as the collision checker calls it: rounding upward throughout
    bounds.enclose(q, spread == 0 ? std::span<const double>() : std::span<const double>(spreads), headings, directions,
                   joints);
    for (std::size_t k = 0; k < n; ++k) radius[k] = bounds.link_radius(k, std::span(corners[k].data(), used[k]));
    std::fesetround(FE_TONEAREST);
    // The true arm at q, and at angles moved by the whole spread (alternating signs) and a third of it.
    for (const double moved : {0.0, spread, -spread, spread / 3}) {
      std::vector<Real> angles(n);
      for (std::size_t j = 0; j < n; ++j) {
        mpfr_set_d(angles[j].v, q[j], MPFR_RNDN);
        Real shift((j % 2 ? -1 : 1) * moved);
        mpfr_add(angles[j].v, angles[j].v, shift.v, MPFR_RNDN);
      }
      true_arm(arm, angles, true_joints, true_corners);
      for (std::size_t k = 0; k < n; ++k) {
        const double r = radius[k];
        if (spread == 0) largest_radius = std::max(largest_radius, r);
        for (std::size_t i = 0; i < used[k]; ++i) {
          const double off = miss(corners[k][i], used[k] == 2 ? true_joints[k + i] : true_corners[4 * k + i]);
          if (spread == 0) largest_miss = std::max(largest_miss, off);
          EXPECT_LE(off, r) << "trial " << trial << " link " << k << " corner " << i;
        }
      }
    }
  }
  // Tight as well as sound: at a point configuration the arm is known to a few ulps of its
  // headings (up to 100 rad here, an ulp of 1.4e-14) times its reach (up to 31), and the computed
  // arm does miss the true one (the radii are not there for nothing).
  EXPECT_LT(largest_radius, 1e-12);
  EXPECT_GT(largest_miss, 0.0);
}

}  // namespace
}  // namespace polyplan::test
