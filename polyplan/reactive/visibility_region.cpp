#include <polyplan/reactive/visibility_region.hpp>

#include <polyplan/geometry/detail/cgal_types.hpp>

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Triangular_expansion_visibility_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace polyplan::walk {
namespace {

using detail::to_exact;
using detail::to_point;
using Arrangement = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<detail::Kernel>>;
using Visibility = CGAL::Triangular_expansion_visibility_2<Arrangement, CGAL::Tag_true>;  // regularised: no antennas
using Location = CGAL::Arr_naive_point_location<Arrangement>;

// The cycles' edges, and a frame round them all (half their extent away, at least 1) where the
// world has no bounds: visibility is computed in bounded faces only.
std::vector<detail::Segment> segments(const Boundary& boundary) {
  std::vector<detail::Segment> out;
  bool bounded = false;
  Rational xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  bool first = true;
  for (const auto& cycle : boundary.cycles())
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      const Point& p = cycle[i];
      out.emplace_back(to_point(p), to_point(cycle[(i + 1) % cycle.size()]));
      if (first) xmin = xmax = p.x, ymin = ymax = p.y, first = false;
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
  for (const FreeComponent& c : boundary.cspace().free_components()) bounded |= !c.outer.empty();
  if (!bounded) {
    const Rational margin = std::max({Rational(1), Rational(xmax - xmin), Rational(ymax - ymin)});
    const Point corners[] = {{xmin - margin, ymin - margin},
                             {xmax + margin, ymin - margin},
                             {xmax + margin, ymax + margin},
                             {xmin - margin, ymax + margin}};
    for (int k = 0; k < 4; ++k) out.emplace_back(to_point(corners[k]), to_point(corners[(k + 1) % 4]));
  }
  return out;
}

// Of a halfedge along the cycle's edge and its twin, the one with the free space on its left: the
// one running the cycle's way (a face lies left of its boundary's halfedges).
Arrangement::Halfedge_const_handle free_side(const Boundary& boundary, const Edge& edge,
                                             Arrangement::Halfedge_const_handle candidate) {
  const Point& a = boundary.vertex(edge.cycle, edge.index);
  const Point& b = boundary.vertex(edge.cycle, edge.index + 1);
  const Point dir{b.x - a.x, b.y - a.y};
  const auto agrees = [&](Arrangement::Halfedge_const_handle h) {
    const Point s = to_exact(h->source()->point()), t = to_exact(h->target()->point());
    return (t.x - s.x) * dir.x + (t.y - s.y) * dir.y > 0;
  };
  return agrees(candidate) ? candidate : candidate->twin();
}

}  // namespace

struct VisibilityRegions::Impl {
  const Boundary* boundary;
  Arrangement arrangement;
  std::unique_ptr<Visibility> visibility;
  std::unique_ptr<Location> location;
};

VisibilityRegions::VisibilityRegions(const Boundary& boundary) : impl_(std::make_unique<Impl>()) {
  impl_->boundary = &boundary;
  const auto edges = segments(boundary);
  CGAL::insert(impl_->arrangement, edges.begin(), edges.end());
  impl_->visibility = std::make_unique<Visibility>(impl_->arrangement);
  impl_->location = std::make_unique<Location>(impl_->arrangement);
}

VisibilityRegions::~VisibilityRegions() = default;

std::vector<Point> VisibilityRegions::visible_from(const Point& x) const {
  const Impl& r = *impl_;
  const detail::Point q = to_point(x);
  Arrangement out;
  Arrangement::Face_handle seen;
  const auto located = r.location->locate(q);
  const auto on = r.boundary->edge_at(x);
  if (!on) {
    const auto* face = boost::get<Arrangement::Face_const_handle>(&located);
    if (!face) throw std::logic_error("visibility: " + text(x) + " is on the boundary but on no cycle's edge");
    seen = r.visibility->compute_visibility(q, *face, out);
  } else if (const auto* halfedge = boost::get<Arrangement::Halfedge_const_handle>(&located)) {
    seen = r.visibility->compute_visibility(q, free_side(*r.boundary, *on, *halfedge), out);
  } else {
    // A vertex: the halfedge arriving from the cycle's vertex before it, or from a point on that edge.
    const auto* vertex = boost::get<Arrangement::Vertex_const_handle>(&located);
    if (!vertex)
      throw std::logic_error("visibility: " + text(x) + " is a cycle's point but not on the arrangement's boundary");
    const Point& before = r.boundary->vertex(on->cycle, on->index + r.boundary->cycles()[on->cycle].size() - 1);
    auto h = (*vertex)->incident_halfedges(), end = h;
    std::optional<Arrangement::Halfedge_const_handle> arriving;
    do {
      const Point s = to_exact(h->source()->point());
      if (cross(before, x, s) == 0 && dot(s, before, x) <= 0 && !(s == x)) arriving = h;  // s on the segment before-x
    } while (!arriving && ++h != end);
    if (!arriving) throw std::logic_error("visibility: no edge arrives at " + text(x) + " along its cycle");
    seen = r.visibility->compute_visibility(q, *arriving, out);
  }
  std::vector<Point> ring;
  if (seen->has_outer_ccb()) {
    auto e = seen->outer_ccb(), first = e;
    do ring.push_back(to_exact(e->source()->point()));
    while (++e != first);
  }
  return ring;
}

std::vector<std::pair<Point, Point>> windows(const Boundary& boundary, const Point& x,
                                             const std::vector<Point>& region) {
  std::vector<std::pair<Point, Point>> out;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const Point &p = region[i], &q = region[(i + 1) % region.size()];
    if (p == x || q == x || cross(x, p, q) != 0) continue;
    const Point middle = along(p, q, Rational(1, 2));
    if (boundary.edge_at(middle)) continue;  // along the boundary: seen, not a window
    out.push_back(squared(x, p) < squared(x, q) ? std::pair{p, q} : std::pair{q, p});
  }
  return out;
}

std::vector<Point> within_range(const std::vector<Point>& region, const Point& x, double range) {
  if (!std::isfinite(range) || region.empty()) return region;
  const double cx = to_double(x.x), cy = to_double(x.y);
  const auto inside = [&](double px, double py) { return std::hypot(px - cx, py - cy) <= range; };
  const auto on_circle = [&](double t) {
    return Point{Rational(cx + range * std::cos(t)), Rational(cy + range * std::sin(t))};
  };
  std::vector<Point> out;
  double last_exit = std::numeric_limits<double>::quiet_NaN();
  const auto arc_to = [&](double angle) {  // chords along the circle from the last exit
    if (std::isnan(last_exit)) return;
    double sweep = angle - last_exit;
    while (sweep < 0) sweep += 2 * M_PI;
    const int steps = std::max(1, static_cast<int>(std::ceil(sweep / (M_PI / 36))));
    for (int k = 1; k < steps; ++k) out.push_back(on_circle(last_exit + sweep * k / steps));
  };
  // Each edge of the (star-shaped) region: the part inside the disc, joined by arcs.
  for (std::size_t i = 0; i < region.size(); ++i) {
    const double ax = to_double(region[i].x), ay = to_double(region[i].y);
    const double bx = to_double(region[(i + 1) % region.size()].x), by = to_double(region[(i + 1) % region.size()].y);
    const double dx = bx - ax, dy = by - ay, fx = ax - cx, fy = ay - cy;
    const double a = dx * dx + dy * dy, b = 2 * (fx * dx + fy * dy), c = fx * fx + fy * fy - range * range;
    const double disc = b * b - 4 * a * c;
    double t0 = 0, t1 = 1;
    if (a == 0 || disc < 0) {
      if (!inside(ax, ay)) continue;
    } else {
      t0 = std::max(0.0, (-b - std::sqrt(disc)) / (2 * a));
      t1 = std::min(1.0, (-b + std::sqrt(disc)) / (2 * a));
      if (t0 > t1) continue;
    }
    const double sx = ax + t0 * dx, sy = ay + t0 * dy;
    if (t0 > 0 || !inside(ax, ay)) arc_to(std::atan2(sy - cy, sx - cx));
    out.push_back({Rational(sx), Rational(sy)});
    if (t1 < 1) {
      const double ex = ax + t1 * dx, ey = ay + t1 * dy;
      out.push_back({Rational(ex), Rational(ey)});
      last_exit = std::atan2(ey - cy, ex - cx);
    } else {
      last_exit = std::numeric_limits<double>::quiet_NaN();
    }
  }
  if (!out.empty() && !std::isnan(last_exit)) {  // close the last arc to the first point
    const Point& f = out.front();
    arc_to(std::atan2(to_double(f.y) - cy, to_double(f.x) - cx));
  }
  if (out.empty()) {  // the disc lies inside the region
    last_exit = 0;
    out.push_back(on_circle(0));
    arc_to(2 * M_PI - 1e-9);
  }
  return out;
}

}  // namespace polyplan::walk
