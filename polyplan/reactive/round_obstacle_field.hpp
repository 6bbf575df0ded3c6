#pragma once
// What repels a robot among discs, walls and polygons (RoundRobot): each C-obstacle's nearest
// point to the robot's reference point q, at the distance from its grown core
// (geometry/round_cspace.hpp; for a disc robot of radius r the distance its rim keeps) —
//
//   a point core c of radius R       |q − c| − R
//   a wall (a polyline) of radius R  its distance − R          (one term per wall, as per polygon:
//                                                              its pieces do not repel twice at a joint)
//   a polygon core of radius R       its distance − R
//   the reference disc (c, R)        R − |q − c|
//   the reference box                each side's distance      (left, right, bottom, top)
//
// for reactive/obstacle_field.hpp's potential. Doubles: the potential only steers; every step a
// planner takes on it is checked exactly by geometry/round_world_check.hpp.
#include <polyplan/geometry/round_world_check.hpp>
#include <polyplan/reactive/obstacle_field.hpp>

#include <optional>
#include <vector>

namespace polyplan {

class RoundObstacleField final : public Repellers {
 public:
  // The world's obstacles and bounds (copied: the field does not keep the world).
  explicit RoundObstacleField(const RoundWorld& world);

  // The C-space's point cores (discs) in order, then its walls, its polygons, and the bounds (the
  // disc, or the box's four sides).
  std::vector<NearestPoint> nearest_points(Vec2 q) const override;

 private:
  struct RoundDisc {  // a disc grown by the robot: centre and radius
    Vec2 centre;
    double radius = 0;
  };
  template <class Core>
  struct Grown {  // a core and its radius
    Core core;
    double radius = 0;
  };
  std::vector<RoundDisc> discs_;                                 // point cores
  std::vector<Grown<std::vector<Vec2>>> walls_;                  // polylines
  std::vector<Grown<std::vector<std::vector<Vec2>>>> polygons_;  // per polygon: its rings
  std::optional<RoundDisc> disc_bounds_;                         // shrunk by the robot
  std::optional<SideBox> box_bounds_;                            // shrunk by the robot
};

}  // namespace polyplan
