#include <polyplan/reactive/obstacle_field.hpp>

#include <cmath>
#include <limits>

namespace polyplan {
namespace {

std::vector<Vec2> rounded(const Ring& ring) {
  std::vector<Vec2> out;
  out.reserve(ring.size());
  for (const ExactPoint& p : ring) out.push_back(approximate(p));
  return out;
}

}  // namespace

ObstacleField::ObstacleField(const CSpace& cspace) {
  for (const PolygonWithHoles& c : cspace.cobstacles()) {
    std::vector<std::vector<Vec2>> rings{rounded(c.outer)};
    for (const Ring& hole : c.holes) rings.push_back(rounded(hole));
    cobstacles_.push_back(std::move(rings));
  }
  if (const auto& box = cspace.reference_box()) {
    walls_ = {{true, to_double(box->xmin)},
              {true, to_double(box->xmax)},
              {false, to_double(box->ymin)},
              {false, to_double(box->ymax)}};
  }
}

std::vector<NearestPoint> ObstacleField::nearest_points(Vec2 q) const {
  std::vector<NearestPoint> out;
  out.reserve(obstacles());
  for (const auto& rings : cobstacles_) {
    NearestPoint best = nearest_on_ring(q, rings.front());
    for (std::size_t h = 1; h < rings.size(); ++h) {
      const NearestPoint n = nearest_on_ring(q, rings[h]);
      if (n.distance < best.distance) best = n;
    }
    out.push_back(best);
  }
  for (const Wall& w : walls_) {
    const Vec2 at = w.vertical ? Vec2{w.at, q.y} : Vec2{q.x, w.at};
    out.push_back({std::abs(w.vertical ? q.x - w.at : q.y - w.at), at, false});
  }
  return out;
}

double ObstacleField::clearance(std::span<const NearestPoint> nearest) {
  double d = std::numeric_limits<double>::infinity();
  for (const NearestPoint& n : nearest) d = std::min(d, n.distance);
  return d;
}

double ObstacleField::clearance(Vec2 q) const { return clearance(nearest_points(q)); }

Potential ObstacleField::potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters,
                                   std::span<const NearestPoint> nearest) {
  Potential total = attractive_potential(q, goal, parameters.attractive);
  for (const NearestPoint& n : nearest) total = total + repulsive_potential(q, n, parameters.repulsive);
  return total;
}

Potential ObstacleField::potential(Vec2 q, Vec2 goal, const PotentialParameters& parameters) const {
  return potential(q, goal, parameters, nearest_points(q));
}

}  // namespace polyplan
