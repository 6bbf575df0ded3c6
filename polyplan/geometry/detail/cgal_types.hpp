#pragma once
// The CGAL side of polyplan: the exact kernel and conversions from and to the plain exact
// types of the public headers. Include only from .cpp files: a CGAL translation unit costs
// tens of seconds to compile.
#include <polyplan/geometry/world.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace polyplan::detail {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonH = CGAL::Polygon_with_holes_2<Kernel>;

// CGAL picks the exact rational type by configuration (mpq_class, Gmpq or Boost's
// gmp_rational); all three wrap a GMP mpq_t, so conversions copy that and nothing more.
using ExactRational = FT::ET;

template <typename E>
E make_exact(const Rational& q) {
  if constexpr (std::is_same_v<E, mpq_class>) return q;
  else return E(q.get_mpq_t());
}

template <typename E>
Rational from_exact(const E& e) {
  if constexpr (std::is_same_v<E, mpq_class>) return e;
  else if constexpr (std::is_same_v<E, CGAL::Gmpq>) return Rational(e.mpq());
  else return Rational(e.backend().data());
}

inline FT to_ft(const Rational& q) { return FT(make_exact<ExactRational>(q)); }
inline Rational to_rational(const FT& v) { return from_exact(CGAL::exact(v)); }

inline Point to_point(const ExactPoint& p) { return {to_ft(p.x), to_ft(p.y)}; }
inline ExactPoint to_exact(const Point& p) { return {to_rational(p.x()), to_rational(p.y())}; }

inline Polygon to_polygon(const Ring& ring) {
  Polygon polygon;
  for (const auto& p : ring) polygon.push_back(to_point(p));
  return polygon;
}

// The box [xmin, xmax] x [ymin, ymax], counterclockwise.
inline Polygon box_polygon(const Bounds& b) {
  Polygon box;
  box.push_back(to_point({b.xmin, b.ymin}));
  box.push_back(to_point({b.xmax, b.ymin}));
  box.push_back(to_point({b.xmax, b.ymax}));
  box.push_back(to_point({b.xmin, b.ymax}));
  return box;
}

inline PolygonH to_polygon(const PolygonWithHoles& p) {
  PolygonH result(to_polygon(p.outer));
  for (const auto& hole : p.holes) result.add_hole(to_polygon(hole));
  return result;
}

// Vertices in the middle of a straight run (Minkowski sums and overlays leave many) say nothing
// about the shape: reported rings leave them out. Exact: collinear and between its neighbours.
inline bool straight(const Point& prev, const Point& at, const Point& next) {
  return CGAL::collinear(prev, at, next) && CGAL::collinear_are_strictly_ordered_along_line(prev, at, next);
}

template <typename PointRange>
Ring without_straight_vertices(const PointRange& points) {
  std::vector<Point> kept;
  for (const Point& p : points) {
    while (kept.size() >= 2 && straight(kept[kept.size() - 2], kept.back(), p)) kept.pop_back();
    kept.push_back(p);
  }
  for (bool changed = true; changed && kept.size() > 3;) {  // straight runs through the seam
    changed = false;
    if (straight(kept[kept.size() - 2], kept.back(), kept.front())) {
      kept.pop_back();
      changed = true;
    } else if (straight(kept.back(), kept.front(), kept[1])) {
      kept.erase(kept.begin());
      changed = true;
    }
  }
  Ring ring;
  for (const Point& p : kept) ring.push_back(to_exact(p));
  return ring;
}

template <typename VertexRange>
Ring to_ring(const VertexRange& vertices) {
  return without_straight_vertices(vertices);
}

inline PolygonWithHoles to_exact(const PolygonH& p) {
  PolygonWithHoles result;
  if (!p.is_unbounded()) result.outer = to_ring(p.outer_boundary().vertices());
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) result.holes.push_back(to_ring(h->vertices()));
  return result;
}

inline std::string to_text(const ExactPoint& p) { return to_string(p); }
inline std::string to_text(const Point& p) { return to_text(to_exact(p)); }

}  // namespace polyplan::detail
