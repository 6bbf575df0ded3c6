#pragma once
// A quick test that throws out the tangents that plainly cross an obstacle before the full exact
// rules decide the rest (most tangents of a cluttered world cross something, and the full test of
// one runs the local test at every contact). Doubles only choose which obstacle to try: where they
// show the segment entering a rounded core, or crossing a wall or a point robot's polygon edge,
// that one obstacle is tested exactly (squared distance below the squared radius; a proper
// crossing, every orientation's sign nonzero and opposite), and only an exact yes rejects the
// segment. Everything else goes on to the full rules.
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
  // The points within `radius` of the segment from–to (a point when from == to); radius 0: a
  // wall's piece or a polygon's edge met by a point robot, which may not be crossed.
  struct Feature {
    Point from, to;
    double radius;
    round_rules::Seg<Algebraic> exact;
    Algebraic exact_radius;
  };
  std::vector<Feature> rounded_, thin_;
};

}  // namespace polyplan::tangent
