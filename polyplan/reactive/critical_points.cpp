#include <polyplan/reactive/critical_points.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace polyplan {
namespace {

// Whether the values take both signs (or touch 0).
bool straddles(double a, double b, double c, double d) {
  return std::min({a, b, c, d}) <= 0 && std::max({a, b, c, d}) >= 0;
}

struct Newton {
  const ObstacleField& field;
  Vec2 goal;
  const PotentialParameters& parameters;
  double tolerance;  // on |∇U|

  // Newton's steps on ∇U = 0 from `from`; the point where |∇U| ≤ tolerance, if it comes within
  // `reach` of where it began.
  std::optional<Vec2> from(Vec2 start, double reach) const {
    Vec2 q = start;
    for (int i = 0; i < 60; ++i) {
      const Potential p = field.potential(q, goal, parameters);
      if (std::hypot(p.gradient.x, p.gradient.y) <= tolerance) return q;
      const Hessian2& h = p.hessian;
      const double det = h.xx * h.yy - h.xy * h.xy;
      if (!(std::abs(det) > 0) || !std::isfinite(det)) return std::nullopt;
      q = {q.x - (h.yy * p.gradient.x - h.xy * p.gradient.y) / det,
           q.y - (h.xx * p.gradient.y - h.xy * p.gradient.x) / det};
      if (!(std::hypot(q.x - start.x, q.y - start.y) <= reach)) return std::nullopt;
    }
    return std::nullopt;
  }
};

CriticalPoints find_critical_points_of_scale(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                                             const PotentialParameters& parameters, const BoxGrid& search) {
  search.check();
  const std::size_t n = search.cells_per_axis;
  const double w = (search.xmax - search.xmin) / static_cast<double>(n),
               h = (search.ymax - search.ymin) / static_cast<double>(n);
  const auto corner = [&](std::size_t i, std::size_t j) {
    return Vec2{search.xmin + static_cast<double>(i) * w, search.ymin + static_cast<double>(j) * h};
  };
  // The gradient at every corner of the subdivision, once.
  std::vector<Vec2> gradient((n + 1) * (n + 1));
  for (std::size_t j = 0; j <= n; ++j)
    for (std::size_t i = 0; i <= n; ++i)
      gradient[i + j * (n + 1)] = field.potential(corner(i, j), goal, parameters).gradient;
  const double pull = parameters.attractive.d_star > 0 ? parameters.attractive.zeta * parameters.attractive.d_star
                                                       : parameters.attractive.zeta;
  const Newton newton{field, goal, parameters, 1e-9 * pull};
  const double cell = std::hypot(w, h), same = 1e-6 * std::hypot(search.xmax - search.xmin, search.ymax - search.ymin);

  CriticalPoints found;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = gradient[i + j * (n + 1)], b = gradient[i + 1 + j * (n + 1)], c = gradient[i + (j + 1) * (n + 1)],
                 d = gradient[i + 1 + (j + 1) * (n + 1)];
      if (!straddles(a.x, b.x, c.x, d.x) || !straddles(a.y, b.y, c.y, d.y)) continue;
      ++found.candidates;
      const Vec2 centre{corner(i, j).x + w / 2, corner(i, j).y + h / 2};
      const auto zero = newton.from(centre, 2 * cell);
      if (!zero || cspace.locate(exactly(*zero)).kind != Location::Kind::free) continue;
      const bool known = std::any_of(found.points.begin(), found.points.end(), [&](const CriticalPoint& p) {
        return std::hypot(p.at.x - zero->x, p.at.y - zero->y) <= same;
      });
      if (known) continue;
      const Potential p = field.potential(*zero, goal, parameters);
      found.points.push_back({*zero, critical_point_kind(p.hessian), eigenvalues(p.hessian), p.value,
                              std::hypot(p.gradient.x, p.gradient.y)});
    }
  std::sort(found.points.begin(), found.points.end(), [](const CriticalPoint& p, const CriticalPoint& q) {
    return p.at.x != q.at.x ? p.at.x < q.at.x : p.at.y < q.at.y;
  });
  return found;
}

}  // namespace

// s·U has the critical points of U: the weights are scaled by a power of two (exactly) so that the
// larger is in [1, 2), and the values found scaled back. Newton's tolerances and the gradients'
// sign tests then see the same numbers whether the weights are 1 or 1e200 (which found none).
CriticalPoints find_critical_points(const CSpace& cspace, const ObstacleField& field, Vec2 goal,
                                    const PotentialParameters& parameters, const BoxGrid& search) {
  const double largest = std::max(parameters.attractive.zeta, parameters.repulsive.eta);
  const int scale = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
  PotentialParameters unit = parameters;
  unit.attractive.zeta = std::ldexp(unit.attractive.zeta, -scale);
  unit.repulsive.eta = std::ldexp(unit.repulsive.eta, -scale);
  CriticalPoints found = find_critical_points_of_scale(cspace, field, goal, unit, search);
  for (CriticalPoint& p : found.points) {
    p.value = std::ldexp(p.value, scale);
    p.gradient = std::ldexp(p.gradient, scale);
    p.eigenvalues.smaller = std::ldexp(p.eigenvalues.smaller, scale);
    p.eigenvalues.larger = std::ldexp(p.eigenvalues.larger, scale);
  }
  return found;
}

}  // namespace polyplan
