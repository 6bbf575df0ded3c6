#include <polyplan/geometry/turn_enclosure.hpp>

#include <polyplan/geometry/detail/cgal_types.hpp>

#include <CGAL/Partition_traits_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/partition_2.h>

#include <iterator>
#include <list>
#include <stdexcept>

namespace polyplan {
namespace {

using detail::Point;
using detail::Polygon;

// Why the enclosure contains the sweep. Let P be a convex piece and R(α) the rotation by α about
// the reference point O, α running from the rotation R₀ to R₁ through an angle Δ, |Δ| < 180°. Each
// turned piece R(α)P is the convex hull of its turned vertices R(α)v, so the sweep ∪α R(α)P lies
// in the convex hull of the arcs {R(α)v}. The arc of a vertex v (radius r = |v|) runs from
// a = R₀v to b = R₁v; both are exact and |a|² = |b|² = r² exactly, because sin² + cos² = 1
// exactly. The whole disc of radius r lies on O's side of the tangent at a, {p : p·a ≤ r²}, and of
// the tangent at b, {p : p·b ≤ r²}; the arc, shorter than a half circle, lies on the far side of
// the chord ab from O. These three half-planes bound the triangle a, b, t where t, the
// tangents' intersection (p·a = r², p·b = r²), is rational: a 2×2 linear system in rationals. So
// every arc lies in its triangle, and the sweep in the convex hull of all a, b and t.
Point tangent_apex(const Point& a, const Point& b) {
  const detail::FT r2 = a.x() * a.x() + a.y() * a.y();
  const detail::FT det = a.x() * b.y() - a.y() * b.x();  // r² sin Δ: zero only at 0° or 180°
  return {r2 * (b.y() - a.y()) / det, r2 * (a.x() - b.x()) / det};
}

std::vector<Polygon> convex_pieces(const Ring& part) {
  const Polygon polygon = detail::to_polygon(part);
  if (polygon.is_convex()) return {polygon};
  using Traits = CGAL::Partition_traits_2<detail::Kernel>;
  std::list<Traits::Polygon_2> pieces;
  CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(pieces),
                                  Traits());
  std::vector<Polygon> out;
  for (const auto& piece : pieces) out.emplace_back(piece.vertices_begin(), piece.vertices_end());
  return out;
}

}  // namespace

std::vector<Ring> convex_pieces(const Robot& robot) {
  std::vector<Ring> out;
  for (const Ring& part : robot.parts)
    for (const Polygon& piece : convex_pieces(part)) out.push_back(detail::to_ring(piece.vertices()));
  return out;
}

Robot turn_enclosure(const Robot& robot, const Rotation& from, const Rotation& to) {
  if (from == to) return rotated(robot, from);
  if (from.sin == -to.sin && from.cos == -to.cos)
    throw std::invalid_argument("a half turn has no short way: turn through 180 degrees in two steps");
  const detail::FT s0 = detail::to_ft(from.sin), c0 = detail::to_ft(from.cos);
  const detail::FT s1 = detail::to_ft(to.sin), c1 = detail::to_ft(to.cos);
  const auto turn = [](const Point& v, const detail::FT& s, const detail::FT& c) {
    return Point(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  };
  Robot enclosure;
  for (const Ring& part : robot.parts)
    for (const Polygon& piece : convex_pieces(part)) {
      std::vector<Point> points;
      for (const Point& v : piece.vertices()) {
        const Point a = turn(v, s0, c0), b = turn(v, s1, c1);
        points.push_back(a);
        points.push_back(b);
        if (a != b) points.push_back(tangent_apex(a, b));  // a == b: v is the reference point
      }
      std::vector<Point> hull;
      CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
      enclosure.parts.push_back(detail::to_ring(hull));
    }
  return enclosure;
}

}  // namespace polyplan
