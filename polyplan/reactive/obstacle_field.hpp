#pragma once
// What repels a reactive planner's robot, and the total potential of reactive/potential_field.hpp
// at a configuration: the goal's attraction plus each obstacle's repulsion from its own nearest
// point (Choset et al. 4.3: one term per obstacle, so that two obstacles close together do not
// merge into one that repels less). `Repellers` is what a potential-field planner descends over:
// the nearest point of each obstacle. `ObstacleField` gives them for a C-space: each connected
// C-obstacle (its outer boundary and holes) and each wall of the reference box;
// reactive/round_obstacle_field.hpp for a point or disc robot among discs, walls and polygons.
//
// The obstacles are the exact ones rounded to doubles: a potential only steers, and the planners
// check every step exactly.
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

class Repellers {
 public:
  virtual ~Repellers() = default;

  // The nearest point of each obstacle to q, in an order of the repellers' own.
  virtual std::vector<NearestPoint> nearest_points(Vec2 q) const = 0;
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
};

class ObstacleField final : public Repellers {
 public:
  // The C-obstacles and walls of `cspace` (copied: the field does not keep the C-space).
  explicit ObstacleField(const CSpace& cspace);

  // The nearest point of each obstacle (C-obstacles in CSpace::cobstacles() order, then the walls
  // the reference box has: left, right, bottom, top).
  std::vector<NearestPoint> nearest_points(Vec2 q) const override;

  std::size_t obstacles() const { return cobstacles_.size() + (box_ ? 4 : 0); }

 private:
  std::vector<std::vector<std::vector<Vec2>>> cobstacles_;  // per C-obstacle: its rings
  std::optional<SideBox> box_;                              // the reference box, whose sides are walls
};

// The nearest point of a polygon with holes (its rings) to q: the nearest of its rings'.
NearestPoint nearest_on_rings(Vec2 q, const std::vector<std::vector<Vec2>>& rings);
// A polygon's rings (outer first, then its holes) rounded to doubles.
std::vector<std::vector<Vec2>> rounded_rings(const PolygonWithHoles& polygon);

}  // namespace polyplan
