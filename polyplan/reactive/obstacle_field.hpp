#pragma once
// What repels a reactive planner's robot: each connected C-obstacle of a C-space (its outer
// boundary and holes) and each wall of the reference box, with the total potential of
// reactive/potential_field.hpp at a configuration — the goal's attraction plus each obstacle's
// repulsion from its own nearest point (Choset et al. 4.3: one term per obstacle, so that two
// obstacles close together do not merge into one that repels less).
//
// The rings are the exact C-obstacles' vertices rounded to doubles: a potential only steers, and
// the planners check every step against the exact C-space.
#include <polyplan/geometry/cspace.hpp>
#include <polyplan/reactive/potential_field.hpp>

#include <optional>
#include <span>
#include <vector>

namespace polyplan {

struct PotentialParameters {
  AttractiveParameters attractive;
  RepulsiveParameters repulsive;
};

class ObstacleField {
 public:
  // The C-obstacles and walls of `cspace` (copied: the field does not keep the C-space).
  explicit ObstacleField(const CSpace& cspace);

  // The nearest point of each obstacle (C-obstacles in CSpace::cobstacles() order, then the walls
  // the reference box has: left, right, bottom, top).
  std::vector<NearestPoint> nearest_points(Vec2 q) const;
  // The distance to the nearest obstacle or wall (infinite when there is none).
  double clearance(Vec2 q) const;
  // Attraction to `goal` plus every obstacle's repulsion.
  Potential potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters) const;
  // The same from the nearest points nearest_points(q) found already (a descent needs them for
  // its clearance too, and finding them is the work of the step).
  static Potential potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters,
                             std::span<const NearestPoint> nearest);

  // The smallest of the distances (infinite for none).
  static double clearance(std::span<const NearestPoint> nearest);

  std::size_t obstacles() const { return cobstacles_.size() + walls_.size(); }

 private:
  struct Wall {
    bool vertical;  // x = at (left or right), else y = at
    double at;
  };
  std::vector<std::vector<std::vector<Vec2>>> cobstacles_;  // per C-obstacle: its rings
  std::vector<Wall> walls_;
};

}  // namespace polyplan
