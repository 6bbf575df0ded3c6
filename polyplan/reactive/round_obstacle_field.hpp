#pragma once
// What repels a point or disc robot among discs, walls and polygons (RoundRobot): each obstacle's
// nearest point to the robot's centre q, at the distance the robot's rim keeps from it —
//
//   a disc (centre c, radius R)      |q − c| − R − r          (r the robot's radius, 0 for a point)
//   a wall (a polyline)              its distance − r          (one term per wall, as per polygon:
//                                                              its pieces do not repel twice at a joint)
//   a polygon                        its distance − r
//   disc bounds (centre c, radius R) R − r − |q − c|
//   box bounds                       each side's distance − r  (left, right, bottom, top)
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

  // The discs in the world's order, then the walls, the polygons, and the bounds (the disc, or
  // the box's four sides).
  std::vector<NearestPoint> nearest_points(Vec2 q) const override;

 private:
  struct RoundDisc {  // a disc grown by the robot: centre and radius
    Vec2 centre;
    double radius = 0;
  };
  double robot_ = 0;                                      // the robot's radius
  std::vector<RoundDisc> discs_;                          // grown by the robot
  std::vector<std::vector<Vec2>> walls_;                  // polylines
  std::vector<std::vector<std::vector<Vec2>>> polygons_;  // per polygon: its rings
  std::optional<RoundDisc> disc_bounds_;                  // shrunk by the robot
  std::optional<SideBox> box_bounds_;                     // shrunk by the robot
};

}  // namespace polyplan
