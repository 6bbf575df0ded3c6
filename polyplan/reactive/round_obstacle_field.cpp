#include <polyplan/reactive/round_obstacle_field.hpp>

#include <cmath>

namespace polyplan {

RoundObstacleField::RoundObstacleField(const RoundWorld& round) {
  for (const RoundCore& core : round.cspace().obstacles) {
    const double radius = to_double(core.radius);
    if (core.kind == RoundCore::Kind::point) discs_.push_back({approximate(core.points[0]), radius});
    if (core.kind == RoundCore::Kind::wall) {
      std::vector<Vec2> line;
      for (const ExactPoint& p : core.points) line.push_back(approximate(p));
      walls_.push_back({std::move(line), radius});
    }
    if (core.kind == RoundCore::Kind::polygon)
      polygons_.push_back(
          {rounded_rings(PolygonWithHoles{core.rings[0], {core.rings.begin() + 1, core.rings.end()}}), radius});
  }
  // The reference disc and box are the bounds already shrunk by the robot.
  if (const auto& disc = round.reference_disc())
    disc_bounds_ = RoundDisc{approximate(disc->center), to_double(disc->radius)};
  if (const auto& box = round.reference_box())
    box_bounds_ = SideBox{to_double(box->xmin), to_double(box->ymin), to_double(box->xmax), to_double(box->ymax)};
}

std::vector<NearestPoint> RoundObstacleField::nearest_points(Vec2 q) const {
  std::vector<NearestPoint> out;
  // A disc repels as its centre does, its grown radius nearer.
  for (const RoundDisc& d : discs_)
    out.push_back(grown(q, {std::hypot(q.x - d.centre.x, q.y - d.centre.y), d.centre, true}, d.radius));
  for (const auto& [line, radius] : walls_) out.push_back(grown(q, nearest_on_polyline(q, line), radius));
  for (const auto& [rings, radius] : polygons_) out.push_back(grown(q, nearest_on_rings(q, rings), radius));
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
