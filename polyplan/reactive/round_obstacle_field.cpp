#include <polyplan/reactive/round_obstacle_field.hpp>

#include <cmath>

namespace polyplan {

RoundObstacleField::RoundObstacleField(const RoundWorld& round) {
  const World& world = round.world();
  robot_ = world.robot.disc ? to_double(*world.robot.disc) : 0;
  for (const Disc& d : world.discs) discs_.push_back({approximate(d.center), to_double(d.radius) + robot_});
  for (const Wall& wall : world.walls) {
    std::vector<Vec2>& line = walls_.emplace_back();
    for (const ExactPoint& p : wall) line.push_back(approximate(p));
  }
  for (const PolygonWithHoles& p : world.obstacles) polygons_.push_back(rounded_rings(p));
  // The reference disc and box are the bounds already shrunk by the robot's radius.
  if (const auto& disc = round.reference_disc())
    disc_bounds_ = RoundDisc{approximate(disc->center), to_double(disc->radius)};
  if (const auto& box = round.reference_box())
    box_bounds_ = SideBox{to_double(box->xmin), to_double(box->ymin), to_double(box->xmax), to_double(box->ymax)};
}

std::vector<NearestPoint> RoundObstacleField::nearest_points(Vec2 q) const {
  std::vector<NearestPoint> out;
  // A disc repels as its centre does, the robot's rim and the disc's radius nearer.
  for (const RoundDisc& d : discs_)
    out.push_back(grown(q, {std::hypot(q.x - d.centre.x, q.y - d.centre.y), d.centre, true}, d.radius));
  for (const std::vector<Vec2>& line : walls_) out.push_back(grown(q, nearest_on_polyline(q, line), robot_));
  for (const auto& rings : polygons_) out.push_back(grown(q, nearest_on_rings(q, rings), robot_));
  if (disc_bounds_) {
    // The circle's nearest point lies on the ray from its centre through q (any ray at the centre);
    // inside, the distance curves about that centre the other way (a negative offset).
    const double from_centre = std::hypot(q.x - disc_bounds_->centre.x, q.y - disc_bounds_->centre.y);
    const Vec2 u = from_centre > 0 ? Vec2{(q.x - disc_bounds_->centre.x) / from_centre,
                                          (q.y - disc_bounds_->centre.y) / from_centre}
                                   : Vec2{1, 0};
    const double radius = disc_bounds_->radius;
    out.push_back({radius - from_centre,
                   {disc_bounds_->centre.x + radius * u.x, disc_bounds_->centre.y + radius * u.y},
                   true,
                   -radius});
  }
  if (box_bounds_) {
    const auto sides = nearest_on_sides(q, *box_bounds_);
    out.insert(out.end(), sides.begin(), sides.end());
  }
  return out;
}

}  // namespace polyplan
