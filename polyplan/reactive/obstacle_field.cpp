#include <polyplan/reactive/obstacle_field.hpp>

#include <cmath>
#include <limits>

namespace polyplan {

std::vector<std::vector<Vec2>> rounded_rings(const PolygonWithHoles& polygon) {
  std::vector<std::vector<Vec2>> rings;
  const auto add = [&](const Ring& ring) {
    std::vector<Vec2>& out = rings.emplace_back();
    out.reserve(ring.size());
    for (const ExactPoint& p : ring) out.push_back(approximate(p));
  };
  add(polygon.outer);
  for (const Ring& hole : polygon.holes) add(hole);
  return rings;
}

NearestPoint nearest_on_rings(Vec2 q, const std::vector<std::vector<Vec2>>& rings) {
  NearestPoint best = nearest_on_ring(q, rings.front());
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const NearestPoint n = nearest_on_ring(q, rings[h]);
    if (n.distance < best.distance) best = n;
  }
  return best;
}

ObstacleField::ObstacleField(const CSpace& cspace) {
  for (const PolygonWithHoles& c : cspace.cobstacles()) cobstacles_.push_back(rounded_rings(c));
  if (const auto& box = cspace.reference_box())
    box_ = SideBox{to_double(box->xmin), to_double(box->ymin), to_double(box->xmax), to_double(box->ymax)};
}

std::vector<NearestPoint> ObstacleField::nearest_points(Vec2 q) const {
  std::vector<NearestPoint> out;
  out.reserve(obstacles());
  for (const auto& rings : cobstacles_) out.push_back(nearest_on_rings(q, rings));
  if (box_) {
    const auto sides = nearest_on_sides(q, *box_);
    out.insert(out.end(), sides.begin(), sides.end());
  }
  return out;
}

double Repellers::clearance(std::span<const NearestPoint> nearest) {
  double d = std::numeric_limits<double>::infinity();
  for (const NearestPoint& n : nearest) d = std::min(d, n.distance);
  return d;
}

double Repellers::clearance(Vec2 q) const { return clearance(nearest_points(q)); }

Potential Repellers::potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters,
                               std::span<const NearestPoint> nearest) {
  Potential total = attractive_potential(q, goal, parameters.attractive);
  for (const NearestPoint& n : nearest) total = total + repulsive_potential(q, n, parameters.repulsive);
  return total;
}

Potential Repellers::potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters) const {
  return potential(q, goal, parameters, nearest_points(q));
}

}  // namespace polyplan
