#include <polyplan/geometry/polyline.hpp>

#include <cmath>

namespace polyplan {

double euclidean_length(const std::vector<ExactPoint>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += std::hypot(to_double(path[i].x - path[i - 1].x), to_double(path[i].y - path[i - 1].y));
  return length;
}

std::vector<ExactPoint> without_straight_corners(const std::vector<ExactPoint>& path) {
  std::vector<ExactPoint> kept;
  for (const ExactPoint& p : path) {
    if (!kept.empty() && kept.back() == p) continue;
    while (kept.size() >= 2) {
      const ExactPoint &a = kept[kept.size() - 2], &b = kept.back();
      const bool between = (b.x - a.x) * (p.x - b.x) + (b.y - a.y) * (p.y - b.y) > 0;
      if (!(orientation(a, b, p) == 0 && between)) break;
      kept.pop_back();
    }
    kept.push_back(p);
  }
  return kept;
}

int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return sgn((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

}  // namespace polyplan
