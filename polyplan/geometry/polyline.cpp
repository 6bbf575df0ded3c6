#include <polyplan/geometry/polyline.hpp>

#include <cmath>

namespace polyplan {

double euclidean_length(const std::vector<ExactPoint>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += std::hypot(to_double(path[i].x - path[i - 1].x), to_double(path[i].y - path[i - 1].y));
  return length;
}

}  // namespace polyplan
