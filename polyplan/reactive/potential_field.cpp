#include <polyplan/reactive/potential_field.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace polyplan {
namespace {

// (I − u uᵀ) · s for a unit vector u: the Hessian of s·|q − c| (u from c to q, s = weight / distance).
Hessian2 across(Vec2 u, double s) { return {s * (1 - u.x * u.x), -s * u.x * u.y, s * (1 - u.y * u.y)}; }

}  // namespace

NearestPoint nearest_on_segment(Vec2 q, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / length2 : 0;
  NearestPoint n;
  if (t <= 0 || t >= 1) {
    n.at = t <= 0 ? a : b;
    n.at_corner = true;
  } else {
    n.at = {a.x + t * dx, a.y + t * dy};
  }
  n.distance = std::hypot(q.x - n.at.x, q.y - n.at.y);
  return n;
}

NearestPoint nearest_on_polyline(Vec2 q, std::span<const Vec2> line) {
  if (line.empty()) throw std::invalid_argument("nearest_on_polyline: an empty polyline");
  NearestPoint best = nearest_on_segment(q, line.front(), line.front());
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const NearestPoint n = nearest_on_segment(q, line[i], line[i + 1]);
    if (i == 0 || n.distance < best.distance) best = n;
  }
  return best;
}

NearestPoint nearest_on_ring(Vec2 q, std::span<const Vec2> ring) {
  if (ring.empty()) throw std::invalid_argument("nearest_on_ring: an empty ring");
  const NearestPoint closing = nearest_on_segment(q, ring.back(), ring.front());
  const NearestPoint open = nearest_on_polyline(q, ring);
  return open.distance < closing.distance ? open : closing;
}

std::array<NearestPoint, 4> nearest_on_sides(Vec2 q, const SideBox& box) {
  return {NearestPoint{std::abs(q.x - box.xmin), {box.xmin, q.y}, false},
          NearestPoint{std::abs(q.x - box.xmax), {box.xmax, q.y}, false},
          NearestPoint{std::abs(q.y - box.ymin), {q.x, box.ymin}, false},
          NearestPoint{std::abs(q.y - box.ymax), {q.x, box.ymax}, false}};
}

NearestPoint grown(Vec2 q, NearestPoint n, double radius) {
  if (n.distance > 0) {
    const double t = radius / n.distance;
    n.at = {n.at.x + t * (q.x - n.at.x), n.at.y + t * (q.y - n.at.y)};
  }
  n.distance -= radius;
  n.curve_offset += radius;
  return n;
}

Potential attractive_potential(Vec2 q, Vec2 goal, const AttractiveParameters& p) {
  const Vec2 v{q.x - goal.x, q.y - goal.y};
  const double d = std::hypot(v.x, v.y);
  if (p.d_star > 0 && d <= p.d_star) return {0.5 * p.zeta * d * d, {p.zeta * v.x, p.zeta * v.y}, {p.zeta, 0, p.zeta}};
  if (d == 0) return {};
  // Conic: the pull's strength is ζ d* (ζ when d* = 0, the purely conic potential ζ d).
  const double pull = p.d_star > 0 ? p.zeta * p.d_star : p.zeta;
  const double value = p.d_star > 0 ? pull * d - 0.5 * p.zeta * p.d_star * p.d_star : pull * d;
  const Vec2 u{v.x / d, v.y / d};
  return {value, {pull * u.x, pull * u.y}, across(u, pull / d)};
}

Potential repulsive_potential(Vec2 q, const NearestPoint& nearest, const RepulsiveParameters& p) {
  const double d = nearest.distance;
  if (d > p.q_star) return {};
  const double inverse = 1 / d - 1 / p.q_star;
  // U = f(D) with f(D) = ½ η (1/D − 1/Q*)²: f' = −η (1/D − 1/Q*) / D², f'' = η (1/D⁴ + 2 (1/D − 1/Q*) / D³).
  const double f1 = -p.eta * inverse / (d * d);
  const double f2 = p.eta * (1 / (d * d * d * d) + 2 * inverse / (d * d * d));
  const Vec2 u{(q.x - nearest.at.x) / d, (q.y - nearest.at.y) / d};
  Hessian2 h{f2 * u.x * u.x, f2 * u.x * u.y, f2 * u.y * u.y};
  if (nearest.at_corner) {  // D is the distance to a point: it curves across u
    const Hessian2 c = across(u, f1 / (d + nearest.curve_offset));
    h = {h.xx + c.xx, h.xy + c.xy, h.yy + c.yy};
  }
  return {0.5 * p.eta * inverse * inverse, {f1 * u.x, f1 * u.y}, h};
}

Eigenvalues eigenvalues(const Hessian2& h) {
  const double mean = (h.xx + h.yy) / 2, radius = std::hypot((h.xx - h.yy) / 2, h.xy);
  return {mean - radius, mean + radius};
}

const char* critical_point_kind(const Hessian2& h) {
  const Eigenvalues e = eigenvalues(h);
  if (e.smaller > 0) return "minimum";
  if (e.larger < 0) return "maximum";
  if (e.smaller < 0 && e.larger > 0) return "saddle";
  return "degenerate";
}

}  // namespace polyplan
