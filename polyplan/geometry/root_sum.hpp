#pragma once
// Exact comparisons of lengths. A polyline with rational corners is Σ √q_i long (q_i its
// segments' squared lengths), and a decision taken on such lengths in doubles can go either way
// where two are equal or nearly so: a tether 0.85 + 0.85 long against a bound of 1.7, two classes
// of paths whose lengths differ in the 16th digit. Here a length is kept as its terms and an
// interval of doubles rounded outward; a comparison decides on the intervals when they are apart
// (the common case, a few additions), and only when they overlap on the exact numbers: CORE's
// real algebraic numbers, whose signs are exact (CORE is compiled in root_sum.cpp alone).
#include <polyplan/geometry/rational.hpp>

#include <vector>

namespace polyplan {

// An interval [lower, upper] of doubles that holds a length.
struct LengthBounds {
  double lower = 0, upper = 0;
};

// Bounds on a + b: each sum rounded to nearest is within half a unit in the last place of the
// exact sum, so the next double outward bounds it (the error analysis of every sum here).
LengthBounds operator+(const LengthBounds& a, const LengthBounds& b);

// Bounds on √square (square ≥ 0), MPFR's square root rounded down and up; bounds on c.
LengthBounds root_bounds(const Rational& square);
LengthBounds rational_bounds(const Rational& c);

// −1 or 1 when the bounds alone decide which of two lengths is shorter, 0 when they overlap.
int compare_bounds(const LengthBounds& a, const LengthBounds& b);

// The exact squared distance between two points, and bounds on the distance.
Rational squared_distance(const ExactPoint& a, const ExactPoint& b);
LengthBounds distance_bounds(const ExactPoint& a, const ExactPoint& b);

// Bounds on the distance between two exact points from the doubles nearest their coordinates (a
// search's), touching no exact number: ℓ = std::hypot of the doubles' differences, widened by
// 2^-49 (ℓ + M), M the largest coordinate's magnitude. The error analysis (u = 2^-53): each
// double is within uM of its coordinate; each difference of doubles, rounded, within
// 2uM + u(|d| + 2uM) of the exact difference d; the error vector's norm is at most √2 times that;
// std::hypot adds at most one unit in the last place (2uℓ; glibc's documented bound): in all
// below 3uM + 4uℓ, and the slack of 16u covers the rounding of the widening itself.
LengthBounds distance_bounds(double ax, double ay, double bx, double by);

// A sum of square roots of rationals ≥ 0, Σ √squares[i], and bounds on it.
class RootSum {
 public:
  RootSum() = default;
  // The length of the polyline through `points`.
  static RootSum polyline(const std::vector<ExactPoint>& points);

  // Adds √square, whose bounds are `bounds` (root_bounds(square) when not given).
  void add(const Rational& square);
  void add(const Rational& square, const LengthBounds& bounds);
  void add(const RootSum& other);

  const std::vector<Rational>& squares() const { return squares_; }
  const LengthBounds& bounds() const { return bounds_; }
  // The double nearest the middle of the bounds: for printing, never for deciding.
  double approximate() const { return bounds_.lower + (bounds_.upper - bounds_.lower) / 2; }

 private:
  std::vector<Rational> squares_;
  LengthBounds bounds_;
};

// The sign of a − b, and of a − c: −1, 0 or 1, exactly.
int compare(const RootSum& a, const RootSum& b);
int compare(const RootSum& a, const Rational& c);

inline bool operator<(const RootSum& a, const RootSum& b) { return compare(a, b) < 0; }
inline bool operator<=(const RootSum& a, const Rational& c) { return compare(a, c) <= 0; }

}  // namespace polyplan
