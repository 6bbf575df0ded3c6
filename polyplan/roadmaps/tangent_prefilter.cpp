#include <polyplan/roadmaps/detail/tangent_prefilter.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan::tangent {
namespace {

using P2 = std::array<double, 2>;
using Core = round_rules::Obstacle<Algebraic>::Core;

constexpr double kMargin = 1e-9;  // of the world's scale: far beyond the doubles' rounding

P2 to_double(const AlgebraicPoint& p) { return {p.x.doubleValue(), p.y.doubleValue()}; }
double cross(const P2& o, const P2& a, const P2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double point_segment_distance(const P2& p, const P2& a, const P2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// Whether ab and cd cross with every end farther than `tolerance` (an area: length × scale)
// from the other's line.
bool cross_clearly(const P2& a, const P2& b, const P2& c, const P2& d, double tolerance) {
  const double o1 = cross(a, b, c), o2 = cross(a, b, d), o3 = cross(c, d, a), o4 = cross(c, d, b);
  const auto clear = [&](double x, double y) { return std::abs(x) > tolerance && std::abs(y) > tolerance; };
  return o1 * o2 < 0 && o3 * o4 < 0 && clear(o1, o2) && clear(o3, o4);
}

double segment_distance(const P2& a, const P2& b, const P2& c, const P2& d) {
  if (cross_clearly(a, b, c, d, 0)) return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

}  // namespace

Prefilter::Prefilter(const round_rules::RoundRules<Algebraic>& rules) {
  const auto grow = [this](const P2& p) { scale_ = std::max({scale_, std::abs(p[0]), std::abs(p[1])}); };
  for (const auto& o : rules.obstacles()) {
    const double radius = o.radius.doubleValue();
    const bool thin = round_rules::sign_of(o.radius) == 0;
    const auto add = [&](const AlgebraicPoint& a, const AlgebraicPoint& b) {
      const P2 from = to_double(a), to = to_double(b);
      grow(from);
      grow(to);
      if (thin) thin_.push_back({from, to});
      else rounded_.push_back({from, to, radius});
    };
    if (o.core == Core::point) add(o.centre, o.centre);
    if (o.core == Core::segment) add(o.from, o.to);
    if (o.core == Core::wall)
      for (std::size_t k = 0; k + 1 < o.wall.size(); ++k) add(o.wall[k], o.wall[k + 1]);
    if (o.core == Core::polygon)
      for (const auto& ring : o.rings)
        for (std::size_t k = 0; k < ring.size(); ++k) add(ring[k], ring[(k + 1) % ring.size()]);
  }
}

bool Prefilter::clearly_blocked(const AlgebraicPoint& a, const AlgebraicPoint& b) const {
  const P2 from = to_double(a), to = to_double(b);
  const double scale = std::max({scale_, std::abs(from[0]), std::abs(from[1]), std::abs(to[0]), std::abs(to[1])});
  const double margin = kMargin * scale;
  for (const Rounded& r : rounded_)
    if (segment_distance(from, to, r.from, r.to) < r.radius - margin) return true;
  for (const Thin& t : thin_)
    if (cross_clearly(from, to, t.from, t.to, margin * scale)) return true;
  return false;
}

}  // namespace polyplan::tangent
