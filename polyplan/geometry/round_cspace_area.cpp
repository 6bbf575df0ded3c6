// The free area of a round world, exact or certified.
//
// Exact (every core of radius 0, box bounds): the C-obstacles are the polygon cores (a wall of
// radius 0 has no area), so the free space is the polygon world's of a point robot among them in
// the box, whose components' areas CSpace computes exactly (geometry/cspace.hpp).
//
// Certified (some radius r > 0, or disc bounds). A core grown by r is the set within r of it:
//   - a point c: the disc D(c, r), exactly a circle of CGAL's circle–segment traits (rational
//     centre, rational squared radius r²);
//   - a segment ab: D(a, r) ∪ D(b, r) ∪ the rectangle {a + t(b − a) + s·n : t ∈ [0, 1], |s| ≤ r}
//     (n the unit normal): a point's nearest point on ab is an end or the foot of its perpendicular;
//   - a wall: the union over its segments;
//   - a polygon P: P ∪ the grown segments of every ring (a point outside P has its nearest point of P
//     on the boundary).
// Only the rectangles are not rational: n = (−dy, dx)/|d| has an irrational length in general. So
// each rectangle is replaced by the exactly perpendicular one spanned by u = k·(−dy, dx) with k a
// rational bound of r/|d| from below (|u| ≤ r: inside the exact rectangle, the inner set) or from
// above (|u| ≥ r: round it, the outer set); k = r/|d| exactly when that is rational. The bounds
// come from MPFR's square root of r²/|d|² rounded down and up, and are checked in rationals
// (k_lo² ≤ r²/|d|² ≤ k_hi²), so nothing rests on a floating-point result.
//   inner union ⊆ C-obstacles ⊆ outer union, hence
//   area(region − outer union) ≤ free area ≤ area(region − inner union),
// with the region the box or the disc bounds (a circle), and every union and difference computed
// exactly by CGAL's General_polygon_set_2 over rationals and one-root numbers a + b√c.
// (CGAL's approximated_offset_2 gives the outer set too, but whether it lies within eps of the
// exact offset rests on a bound it computes in doubles; these rectangles certify both sides.)
//
// The area of a region bounded by segments and circular arcs is ½∮(x dy − y dx): a segment pq adds
// ½ p×q; an arc from p to q on a circle of centre c and radius R, swept through the angle θ
// counter-clockwise, adds ½ c×(q − p) + ½R²θ (clockwise: ½ c×(q − p) − ½R²θ). That is the chord's
// ½ p×q plus the circular segment's ½R²(θ − sin θ), as R² sin θ = (p − c)×(q − c). The endpoints are
// one-root numbers: CGAL's to_interval bounds each coordinate outward (the square root in interval
// arithmetic with directed rounding), c and R² are rational and bounded likewise, and every sum
// and product is taken in CGAL::Interval_nt, which rounds outward. θ of an x-monotone arc (at most
// a half turn) is atan2(sweep's cross, dot) over the interval box of the cross and dot products,
// with MPFR's atan2 rounded down and up at the box's corners (geometry/detail/rounded_angles.hpp).
// So each area is an interval that holds the exact area for sure; the free area's lower bound is
// the outer difference's interval's lower end, its upper bound the inner difference's upper end.
#include <polyplan/geometry/round_cspace_area.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/detail/rounded_angles.hpp>

#include <CGAL/Cartesian.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/Interval_nt.h>

#include <boost/variant/get.hpp>

#include <algorithm>
#include <limits>
#include <list>
#include <stdexcept>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

using ArcKernel = CGAL::Cartesian<detail::ExactRational>;
using ArcTraits = CGAL::Gps_circle_segment_traits_2<ArcKernel>;
using ArcSet = CGAL::General_polygon_set_2<ArcTraits>;
using ArcPolygon = ArcTraits::Polygon_2;
using ArcPolygonH = ArcTraits::Polygon_with_holes_2;
using ArcCurve = ArcTraits::X_monotone_curve_2;
using KPoint = ArcKernel::Point_2;
using Interval = CGAL::Interval_nt<>;

// Bits of the square roots' bounds: the inner and outer rectangles' heights differ by about r·2⁻⁶⁰.
constexpr mpfr_prec_t root_bits = 64;

detail::ExactRational exact(const Rational& q) { return detail::make_exact<detail::ExactRational>(q); }
KPoint kernel_point(const Rational& x, const Rational& y) { return {exact(x), exact(y)}; }

bool is_square(const mpz_class& n) { return mpz_perfect_square_p(n.get_mpz_t()) != 0; }

// √q for q > 0, rounded down (inner) or up (outer): exact when q is a rational square.
Rational root_bound(const Rational& q, bool up) {
  if (is_square(q.get_num()) && is_square(q.get_den())) {
    mpz_class num, den;
    mpz_sqrt(num.get_mpz_t(), q.get_num_mpz_t());
    mpz_sqrt(den.get_mpz_t(), q.get_den_mpz_t());
    return Rational(num, den);
  }
  const mpfr_rnd_t way = up ? MPFR_RNDU : MPFR_RNDD;
  mpfr_t root;
  mpfr_init2(root, root_bits);
  mpfr_set_q(root, q.get_mpq_t(), way);
  mpfr_sqrt(root, root, way);
  Rational out;
  mpfr_get_q(out.get_mpq_t(), root);  // exact: a binary fraction
  mpfr_clear(root);
  out.canonicalize();
  if (up ? out * out < q : out * out > q) throw std::logic_error("round_free_area: a square root bounded wrongly");
  return out;
}

enum class Side { inner, outer };

struct Pieces {
  std::vector<ArcPolygon> polygons;
  std::vector<ArcPolygonH> with_holes;
};

ArcPolygon circle_polygon(const ExactPoint& centre, const Rational& radius) {
  const ArcTraits::Curve_2 circle(ArcKernel::Circle_2(kernel_point(centre.x, centre.y), exact(radius * radius)));
  std::list<boost::variant<ArcTraits::Point_2, ArcCurve>> arcs;
  ArcTraits().make_x_monotone_2_object()(circle, std::back_inserter(arcs));
  ArcPolygon polygon;
  for (const auto& arc : arcs) polygon.push_back(boost::get<ArcCurve>(arc));
  return polygon;
}

// The ring as a polygon of segments, turned counter-clockwise (ccw) or clockwise.
ArcPolygon ring_polygon(const Ring& ring, bool ccw) {
  Rational twice_area = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % ring.size()];
    twice_area += a.x * b.y - b.x * a.y;
  }
  const bool reverse = (twice_area > 0) != ccw;
  std::vector<KPoint> points;
  for (const ExactPoint& p : ring) points.push_back(kernel_point(p.x, p.y));
  if (reverse) std::reverse(points.begin(), points.end());
  ArcPolygon polygon;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i] != points[(i + 1) % points.size()])
      polygon.push_back(ArcCurve(points[i], points[(i + 1) % points.size()]));
  return polygon;
}

// The rectangle of segment ab grown by r, exactly perpendicular, its half-height |u| ≤ r (inner)
// or ≥ r (outer).
void add_rectangle(const ExactPoint& a, const ExactPoint& b, const Rational& r, Side side, Pieces& out) {
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  const Rational length2 = dx * dx + dy * dy;
  if (length2 == 0) return;
  const Rational k = root_bound(r * r / length2, side == Side::outer);
  const Rational ux = -k * dy, uy = k * dx;
  out.polygons.push_back(
      ring_polygon({{a.x - ux, a.y - uy}, {b.x - ux, b.y - uy}, {b.x + ux, b.y + uy}, {a.x + ux, a.y + uy}}, true));
}

// The polyline grown by r > 0: discs at its vertices, rectangles along its segments.
void add_grown_polyline(const std::vector<ExactPoint>& points, bool closed, const Rational& r, Side side, Pieces& out) {
  for (const ExactPoint& p : points) out.polygons.push_back(circle_polygon(p, r));
  for (std::size_t i = 0; i + (closed ? 0 : 1) < points.size(); ++i)
    add_rectangle(points[i], points[(i + 1) % points.size()], r, side, out);
}

void add_core(const RoundCore& core, Side side, Pieces& out) {
  switch (core.kind) {
    case RoundCore::Kind::point: out.polygons.push_back(circle_polygon(core.points.front(), core.radius)); break;
    case RoundCore::Kind::wall:
      if (core.radius > 0) add_grown_polyline(core.points, false, core.radius, side, out);
      break;  // a wall of radius 0 has no area
    case RoundCore::Kind::polygon: {
      ArcPolygonH polygon(ring_polygon(core.rings.front(), true));
      for (std::size_t i = 1; i < core.rings.size(); ++i) polygon.add_hole(ring_polygon(core.rings[i], false));
      out.with_holes.push_back(std::move(polygon));
      if (core.radius > 0)
        for (const Ring& ring : core.rings) add_grown_polyline(ring, true, core.radius, side, out);
      break;
    }
  }
}

// θ of the x-monotone arc from p to q round c, in its own direction (0 ≤ θ ≤ π).
detail::AngleBounds sweep(const ArcCurve& arc, Interval cx, Interval cy) {
  const Interval ax = Interval(CGAL::to_interval(arc.source().x())) - cx;
  const Interval ay = Interval(CGAL::to_interval(arc.source().y())) - cy;
  const Interval bx = Interval(CGAL::to_interval(arc.target().x())) - cx;
  const Interval by = Interval(CGAL::to_interval(arc.target().y())) - cy;
  const Interval turn = arc.orientation() == CGAL::COUNTERCLOCKWISE ? ax * by - ay * bx : ay * bx - ax * by;
  const Interval dot = ax * bx + ay * by;
  // The exact turn is ≥ 0 (a half turn at most): its bound below 0 is rounding.
  const double ylo = std::max(0.0, turn.inf()), yhi = std::max(0.0, turn.sup());
  if (ylo == 0 && dot.inf() <= 0 && dot.sup() >= 0)  // the box holds the origin: no arc is that short
    return {0, detail::pi_rounded(MPFR_RNDU)};
  return detail::upper_half_angle(ylo, yhi, dot.inf(), dot.sup());
}

Interval curve_area(const ArcCurve& curve) {
  const Interval px(CGAL::to_interval(curve.source().x())), py(CGAL::to_interval(curve.source().y()));
  const Interval qx(CGAL::to_interval(curve.target().x())), qy(CGAL::to_interval(curve.target().y()));
  if (curve.is_linear()) return (px * qy - qx * py) / 2;
  const ArcKernel::Circle_2 circle = curve.supporting_circle();
  const Interval cx(CGAL::to_interval(circle.center().x())), cy(CGAL::to_interval(circle.center().y()));
  const Interval r2(CGAL::to_interval(circle.squared_radius()));
  const detail::AngleBounds theta = sweep(curve, cx, cy);
  const Interval swept = r2 * Interval(theta.lower, theta.upper);
  const Interval chord_term = cx * (qy - py) - cy * (qx - px);
  return (chord_term + (curve.orientation() == CGAL::COUNTERCLOCKWISE ? swept : -swept)) / 2;
}

// Signed: counter-clockwise outer boundaries count, clockwise holes take away.
Interval polygon_area(const ArcPolygon& polygon) {
  Interval area(0);
  for (auto curve = polygon.curves_begin(); curve != polygon.curves_end(); ++curve) area += curve_area(*curve);
  return area;
}

Interval set_area(const ArcSet& set) {
  std::vector<ArcPolygonH> polygons;
  set.polygons_with_holes(std::back_inserter(polygons));
  Interval area(0);
  for (const ArcPolygonH& polygon : polygons) {
    area += polygon_area(polygon.outer_boundary());
    for (auto hole = polygon.holes_begin(); hole != polygon.holes_end(); ++hole) area += polygon_area(*hole);
  }
  return area;
}

// The region the reference point keeps to, minus the side's union of the grown cores.
Interval free_area_of(const RoundCSpace& space, Side side) {
  Pieces pieces;
  for (const RoundCore& core : space.obstacles) add_core(core, side, pieces);
  ArcSet blocked;
  blocked.join(pieces.polygons.begin(), pieces.polygons.end(), pieces.with_holes.begin(), pieces.with_holes.end());
  ArcSet free;
  if (space.box) {
    const Bounds& b = *space.box;
    free.insert(ring_polygon({{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}}, true));
  } else {
    free.insert(circle_polygon(space.disc->center, space.disc->radius));
  }
  free.difference(blocked);
  return set_area(free);
}

double rounded(const Rational& q, mpfr_rnd_t way) {
  detail::RoundedNumber value;
  mpfr_set_q(value.get(), q.get_mpq_t(), way);
  return value.rounded(way);
}

FreeArea exact_area(const Rational& area) { return {true, area, rounded(area, MPFR_RNDD), rounded(area, MPFR_RNDU)}; }

bool empty_region(const RoundCSpace& space) {
  if (space.box) return !(space.box->xmin < space.box->xmax && space.box->ymin < space.box->ymax);
  return !(space.disc->radius > 0);
}

// A point robot among the polygon cores in the box: the polygon world's exact C-space.
Rational polygon_free_area(const RoundCSpace& space, const std::string& source) {
  World world;
  world.source = source;
  world.bounds = space.box;
  for (const RoundCore& core : space.obstacles) {
    if (core.kind != RoundCore::Kind::polygon) continue;
    world.obstacles.push_back({core.rings.front(), {core.rings.begin() + 1, core.rings.end()}});
    world.obstacle_names.push_back(core.name);
  }
  const CSpace cspace(world);
  Rational area = 0;
  for (const FreeComponent& component : cspace.free_components()) area += component.area.value_or(0);
  return area;
}

}  // namespace

FreeArea round_free_area(const RoundCSpace& space, const std::string& source) {
  if (!space.box && !space.disc) {
    const double infinity = std::numeric_limits<double>::infinity();
    return {false, std::nullopt, infinity, infinity};
  }
  if (empty_region(space)) return exact_area(0);
  if (straight_edged(space)) return exact_area(polygon_free_area(space, source));
  return {true, std::nullopt, free_area_of(space, Side::outer).inf(), free_area_of(space, Side::inner).sup()};
}

std::string free_area_text(const FreeArea& area) {
  if (!area.bounded) return "unbounded";
  const auto decimal = [](double value, const char* format) {  // MPFR's printf rounds as told
    detail::RoundedNumber number;
    mpfr_set_d(number.get(), value, MPFR_RNDN);  // exact: a double
    char text[64];
    mpfr_snprintf(text, sizeof text, format, number.get());
    return std::string(text);
  };
  if (area.exact) {
    const std::string fraction = to_string(*area.exact);
    const std::string near = decimal(to_double(*area.exact), "%.12RNg");
    return near + (fraction == near ? " (exact)" : " (exact, " + fraction + ")");
  }
  return decimal(area.lower, "%.12RDg") + " ≤ … ≤ " + decimal(area.upper, "%.12RUg") + ", certified";
}

}  // namespace polyplan
