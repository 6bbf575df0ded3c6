#pragma once
// A quick test in doubles that throws out the tangents that plainly cross an obstacle before the
// exact rules decide the rest (most tangents of a cluttered world cross something, and the exact
// test of one costs far more). Sound: it rejects a segment only when doubles show it entering a
// rounded core by more than 1e-9 of the world's scale, or crossing a wall or a point robot's
// polygon edge with both ends of each segment farther than that from the other's line; the doubles
// of the points and their products err by less than 1e-14 of the scale (squared, for products), so
// a rejected segment is blocked exactly too. Everything it lets through is decided exactly.
#include <polyplan/roadmaps/detail/algebraic.hpp>

#include <array>
#include <vector>

namespace polyplan::tangent {

class Prefilter {
 public:
  explicit Prefilter(const round_rules::RoundRules<Algebraic>& rules);
  bool clearly_blocked(const AlgebraicPoint& a, const AlgebraicPoint& b) const;

 private:
  using Point = std::array<double, 2>;
  struct Rounded {  // the points within `radius` of the segment from–to (a point when from == to)
    Point from, to;
    double radius;
  };
  struct Thin {  // a wall's piece or a polygon's edge met by a point robot
    Point from, to;
  };
  std::vector<Rounded> rounded_;
  std::vector<Thin> thin_;
  double scale_ = 1;
};

}  // namespace polyplan::tangent
