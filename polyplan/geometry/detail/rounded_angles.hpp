#pragma once
// Angles bounded for sure: MPFR's atan2 and π rounded down for a lower bound and up for an upper,
// so that an interval of doubles holds the exact angle. Shared by the certified arc lengths of the
// tangent graph (roadmaps/certified_length.cpp) and the certified free area of round worlds
// (geometry/round_cspace_area.cpp). Include only from .cpp files that link MPFR.
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyplan::detail {

struct AngleBounds {
  double lower = 0, upper = 0;
};

// One MPFR number of a double's precision, freed on leaving.
class RoundedNumber {
 public:
  RoundedNumber() { mpfr_init2(value_, 53); }
  ~RoundedNumber() { mpfr_clear(value_); }
  RoundedNumber(const RoundedNumber&) = delete;
  RoundedNumber& operator=(const RoundedNumber&) = delete;
  mpfr_ptr get() { return value_; }
  double rounded(mpfr_rnd_t way) const { return mpfr_get_d(value_, way); }

 private:
  mpfr_t value_;
};

inline double atan2_rounded(double y, double x, mpfr_rnd_t way) {
  RoundedNumber by, bx, out;
  mpfr_set_d(by.get(), y, MPFR_RNDN);  // exact: a double
  mpfr_set_d(bx.get(), x, MPFR_RNDN);
  mpfr_atan2(out.get(), by.get(), bx.get(), way);
  return out.rounded(way);
}

inline double pi_rounded(mpfr_rnd_t way) {
  RoundedNumber pi;
  mpfr_const_pi(pi.get(), way);
  return pi.rounded(way);
}

// atan2(y, x) over the box [ylo, yhi] × [xlo, xhi] of the closed upper half-plane (0 ≤ ylo) that
// leaves out the origin. atan2 falls as x grows there (∂/∂x = −y/|p|² ≤ 0) and is monotone in y on
// each side of x = 0, so its least and greatest values over the box are at corners: each corner's
// value is rounded down for the lower bound and up for the upper.
inline AngleBounds upper_half_angle(double ylo, double yhi, double xlo, double xhi) {
  AngleBounds out{std::numeric_limits<double>::infinity(), 0};
  for (const double y : {ylo, yhi})
    for (const double x : {xlo, xhi}) {
      out.lower = std::min(out.lower, atan2_rounded(y, x, MPFR_RNDD));
      out.upper = std::max(out.upper, atan2_rounded(y, x, MPFR_RNDU));
    }
  return out;
}

}  // namespace polyplan::detail
