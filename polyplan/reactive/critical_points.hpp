#pragma once
// The critical points of a potential (reactive/obstacle_field.hpp) in the free space of a box:
// a subdivision of the box into n × n cells, each cell whose corners' gradients take both signs in
// each component (a zero may lie inside) refined by Newton's method on the gradient from its
// centre; the zeros it converges to (|∇U| below 1e-9 of the pull's strength, within two cells of
// where it began, in the free space by the exact C-space) are kept once each and classified by
// the Hessian's eigenvalues. A zero of the gradient where it is not smooth (on the ridge where an
// obstacle's nearest point jumps) is not found this way; neither is the goal of a conic
// attraction, where the cone's point leaves the gradient undefined (the global minimum, not among
// the points returned).
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/reactive/obstacle_field.hpp>
#include <polyplan/reactive/potential_map.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {

struct CriticalPoint {
  Vec2 at;
  std::string kind;  // "minimum", "maximum", "saddle", "degenerate"
  Eigenvalues eigenvalues;
  double value = 0;     // U there
  double gradient = 0;  // |∇U| there (the residual Newton left)
};

struct CriticalPoints {
  std::vector<CriticalPoint> points;  // by x, then y
  std::size_t candidates = 0;         // cells whose corners' gradients change sign
};

// Throws std::invalid_argument for an empty box or 0 cells.
CriticalPoints find_critical_points(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                                    const PotentialParameters& parameters, const BoxGrid& search);

}  // namespace polyplan
