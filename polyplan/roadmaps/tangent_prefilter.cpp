#include <polyplan/roadmaps/detail/tangent_prefilter.hpp>

#include <algorithm>
#include <cmath>

namespace polyplan::tangent {
namespace {

using P2 = std::array<double, 2>;
using Core = round_rules::Obstacle<Algebraic>::Core;

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

// Whether ab and cd cross properly in doubles (a guess: the exact test decides).
bool cross_in_doubles(const P2& a, const P2& b, const P2& c, const P2& d) {
  return cross(a, b, c) * cross(a, b, d) < 0 && cross(c, d, a) * cross(c, d, b) < 0;
}

double segment_distance(const P2& a, const P2& b, const P2& c, const P2& d) {
  if (cross_in_doubles(a, b, c, d)) return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

}  // namespace

Prefilter::Prefilter(const round_rules::RoundRules<Algebraic>& rules) {
  for (const auto& o : rules.obstacles()) {
    const auto add = [&](const AlgebraicPoint& a, const AlgebraicPoint& b) {
      Feature f{to_double(a), to_double(b), o.radius.doubleValue(), {a, b}, o.radius};
      (round_rules::sign_of(o.radius) == 0 ? thin_ : rounded_).push_back(std::move(f));
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
  const round_rules::Seg<Algebraic> segment{a, b};
  for (const Feature& r : rounded_)
    if (segment_distance(from, to, r.from, r.to) < r.radius &&
        round_rules::squared_distance(segment, r.exact) < r.exact_radius * r.exact_radius)
      return true;
  for (const Feature& t : thin_)
    if (cross_in_doubles(from, to, t.from, t.to) && round_rules::cross_properly(segment, t.exact)) return true;
  return false;
}

}  // namespace polyplan::tangent
