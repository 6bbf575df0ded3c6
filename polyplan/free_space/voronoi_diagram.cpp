#include <polyplan/free_space/voronoi_diagram.hpp>

#include <polyplan/geometry/detail/free_space_frame.hpp>
#include <polyplan/geometry/path_check.hpp>

#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace polyplan {
namespace {

// Constructions in double, predicates exact on those doubles (CGAL's filtered traits); the
// traits that allow crossing sites, so that boundary edges which rounding makes cross are split
// rather than refused.
using CK = CGAL::Simple_cartesian<double>;
using Gt = CGAL::Segment_Delaunay_graph_filtered_traits_2<CK, CGAL::Field_with_sqrt_tag>;
using SDG = CGAL::Segment_Delaunay_graph_hierarchy_2<Gt>;
using SitePoint = CK::Point_2;

Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double norm(Vec2 a) { return std::hypot(a.x, a.y); }
bool same(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

double distance_to_site(Vec2 p, const BoundarySite& s) { return distance_to_segment(p, s.a, s.b); }

// An edge's curve. Straight: the segment between its vertices, parameter the fraction. Parabolic:
// apex + u t + u^2 / (4 f) n, with t along the directrix, n towards the focus and f half the
// focus's distance to the directrix; parameter u.
struct Curve {
  bool parabolic = false;
  Vec2 a, b;        // straight
  Vec2 apex, t, n;  // parabolic
  double f = 0;
  double t_from = 0, t_to = 1;
  std::size_t site = 0;  // the site a straight piece's clearance is measured from

  Vec2 point(double u) const {
    if (!parabolic) return a + u * (b - a);
    return apex + u * t + (u * u / (4 * f)) * n;
  }
  double parameter_of(Vec2 p) const {
    if (!parabolic) {
      const Vec2 d = b - a;
      const double l2 = dot(d, d);
      return l2 > 0 ? dot(p - a, d) / l2 : 0;
    }
    return dot(p - apex, t);
  }
};

// The arc length of u -> u^2 / (4 f) from 0 to u.
double parabola_length(double u, double f) {
  const double k = 1 / (2 * f);
  return u * std::sqrt(1 + k * k * u * u) / 2 + std::asinh(k * u) / (2 * k);
}

}  // namespace

struct VoronoiDiagram::Impl {
  const CSpace* cspace;
  std::optional<Bounds> frame;
  SDG sdg;
  std::unordered_map<const void*, std::size_t> site_of;  // keyed by &*sdg vertex
  std::vector<BoundarySite> sites;
  std::vector<DiagramVertex> vertices;
  std::vector<DiagramEdge> edges;
  std::vector<Curve> curves;
  std::vector<std::vector<std::size_t>> edges_of_site;  // the kept edges that bound each site's region

  Impl(const CSpace& c, const std::vector<ExactPoint>& inside) : cspace(&c) {
    const detail::FramedFreeSpace framed = detail::framed_free_space(detail::CSpaceAccess::impl(c), inside);
    frame = framed.frame;
    const auto& arrangement = framed.free_set.arrangement();
    for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
      const Vec2 a = approximate(detail::to_exact(e->source()->point())),
                 b = approximate(detail::to_exact(e->target()->point()));
      if (!same(a, b)) sdg.insert(SitePoint(a.x, a.y), SitePoint(b.x, b.y));
    }
    number_sites();
    edges_of_site.resize(sites.size());
    collect_edges();
  }

  // CGAL's segment Delaunay graph orders its faces, and the vertices within a face, by memory
  // address (std::map<Face_handle, ...> during insertion): two diagrams of one C-space built in
  // one process differ in that order, and so would their doubles. Everything below is numbered
  // by geometry instead — sites in the order of their coordinates, edges by their sites, a face's
  // vertex from its least site — so that the same input gives the same diagram every time.
  void number_sites() {
    std::vector<std::pair<BoundarySite, const void*>> found;
    for (auto v = sdg.finite_vertices_begin(); v != sdg.finite_vertices_end(); ++v) {
      const auto& site = v->site();
      BoundarySite s;
      if (site.is_point()) {
        s.a = s.b = {site.point().x(), site.point().y()};
      } else {
        const auto segment = site.segment();
        s.a = {segment.source().x(), segment.source().y()};
        s.b = {segment.target().x(), segment.target().y()};
      }
      found.emplace_back(s, &*v);
    }
    const auto key = [](const BoundarySite& s) { return std::tuple(s.a.x, s.a.y, s.b.x, s.b.y); };
    std::sort(found.begin(), found.end(), [&](const auto& l, const auto& r) { return key(l.first) < key(r.first); });
    for (const auto& [s, vertex] : found) {
      site_of.emplace(vertex, sites.size());
      sites.push_back(s);
    }
  }

  // The Voronoi vertex of a face of the Delaunay graph: the centre of the circle its three sites
  // touch, and that circle's radius. Computed from the face's least site on, in the face's order.
  DiagramVertex circle_of(SDG::Face_handle f) const {
    int first = 0;
    for (int i = 1; i < 3; ++i)
      if (site_index(f->vertex(i)) < site_index(f->vertex(first))) first = i;
    const SitePoint p = sdg.geom_traits().construct_svd_vertex_2_object()(
        f->vertex(first)->site(), f->vertex(sdg.ccw(first))->site(), f->vertex(sdg.cw(first))->site());
    const Vec2 at{p.x(), p.y()};
    return {at, distance_to_site(at, sites[site_index(f->vertex(first))])};
  }
  std::size_t site_index(SDG::Vertex_handle v) const { return site_of.at(&*v); }

  // The diagram's vertex of a face, numbered when an edge first keeps it.
  std::size_t vertex_of(SDG::Face_handle f, std::unordered_map<const void*, std::size_t>& numbered) {
    auto [it, inserted] = numbered.emplace(&*f, vertices.size());
    if (inserted) vertices.push_back(circle_of(f));
    return it->second;
  }

  // The finite Delaunay edges, each from the side where its first site is the lesser, in the
  // order of their four sites (the two it joins, then the faces' third ones).
  std::vector<SDG::Edge> edges_in_site_order() const {
    std::vector<std::pair<std::array<std::size_t, 4>, SDG::Edge>> keyed;
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
      SDG::Edge edge = *e;
      if (sdg.is_infinite(edge.first) || sdg.is_infinite(edge.first->neighbor(edge.second))) continue;
      if (site_index(edge.first->vertex(sdg.ccw(edge.second))) > site_index(edge.first->vertex(sdg.cw(edge.second))))
        edge = sdg.data_structure().mirror_edge(edge);
      const SDG::Face_handle f = edge.first, g = f->neighbor(edge.second);
      keyed.push_back({{site_index(f->vertex(sdg.ccw(edge.second))), site_index(f->vertex(sdg.cw(edge.second))),
                        site_index(f->vertex(edge.second)),
                        site_index(g->vertex(sdg.data_structure().mirror_index(f, edge.second)))},
                       edge});
    }
    std::sort(keyed.begin(), keyed.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    std::vector<SDG::Edge> ordered;
    for (const auto& [key, edge] : keyed) ordered.push_back(edge);
    return ordered;
  }

  void collect_edges() {
    std::unordered_map<const void*, std::size_t> vertex_of_face;
    for (const SDG::Edge& e : edges_in_site_order()) {
      const SDG::Face_handle f = e.first, g = f->neighbor(e.second);  // a ray (an infinite face) is left out
      const std::size_t sa = site_index(f->vertex(sdg.ccw(e.second))), sb = site_index(f->vertex(sdg.cw(e.second)));
      const BoundarySite &a = sites[sa], &b = sites[sb];
      const BoundarySite* point = a.is_point() ? &a : b.is_point() ? &b : nullptr;
      const BoundarySite* segment = !a.is_point() ? &a : !b.is_point() ? &b : nullptr;
      // The perpendicular between an edge and its own corner runs into the boundary there.
      if (point && segment && (same(point->a, segment->a) || same(point->a, segment->b))) continue;

      Curve curve;
      curve.site = sa;
      curve.a = circle_of(f).at;
      curve.b = circle_of(g).at;
      if (point && segment) {
        const Vec2 direction = segment->b - segment->a;
        curve.t = (1 / norm(direction)) * direction;
        Vec2 normal{-curve.t.y, curve.t.x};
        double d = dot(point->a - segment->a, normal);
        if (d < 0) {
          normal = -1 * normal;
          d = -d;
        }
        if (d > 0) {  // a focus on the directrix leaves a straight bisector
          curve.parabolic = true;
          curve.n = normal;
          curve.f = d / 2;
          curve.apex = point->a - curve.f * normal;
        }
      }
      curve.t_from = curve.parabolic ? curve.parameter_of(curve.a) : 0;
      curve.t_to = curve.parabolic ? curve.parameter_of(curve.b) : 1;
      const Vec2 middle = curve.point((curve.t_from + curve.t_to) / 2);
      if (!std::isfinite(middle.x) || !std::isfinite(middle.y)) continue;
      // Diagram edges never cross the boundary: one point tells the free ones.
      if (cspace->locate(exactly(middle)).kind != Location::Kind::free) continue;

      const std::size_t id = edges.size(), from = vertex_of(f, vertex_of_face), to = vertex_of(g, vertex_of_face);
      curves.push_back(curve);
      DiagramEdge edge{from, to, sa, sb, 0, 0};
      edges.push_back(edge);
      edges.back().clearance = clearance_between(id, curve.t_from, curve.t_to);
      edges.back().length = length_between(id, curve.t_from, curve.t_to);
      edges_of_site[sa].push_back(id);
      edges_of_site[sb].push_back(id);
    }
  }

  double clearance_between(std::size_t e, double t1, double t2) const {
    const Curve& c = curves[e];
    if (!c.parabolic) return distance_between_segments(c.point(t1), c.point(t2), sites[c.site].a, sites[c.site].b);
    const double lo = std::min(t1, t2), hi = std::max(t1, t2);
    const double nearest = lo <= 0 && 0 <= hi ? 0 : std::min(std::abs(lo), std::abs(hi));
    return c.f + nearest * nearest / (4 * c.f);
  }

  double length_between(std::size_t e, double t1, double t2) const {
    const Curve& c = curves[e];
    if (!c.parabolic) return norm(c.point(t2) - c.point(t1));
    return std::abs(parabola_length(t2, c.f) - parabola_length(t1, c.f));
  }

  std::size_t site_at(Vec2 p) const { return site_index(sdg.nearest_neighbor(SitePoint(p.x, p.y))); }

  // A point near p in the free space, off the boundary, joined to p by a segment in the free space
  // (the exact segment test): the first of sixteen directions, from a thousandth of p's size
  // down, that gives one.
  std::optional<Vec2> step_off_boundary(const ExactPoint& p) const {
    const Vec2 at = approximate(p);
    for (int k = 0; k < 16; ++k) {
      const Vec2 direction{std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)};
      double step = 1e-3 * (1 + std::max(std::abs(at.x), std::abs(at.y)));
      for (int halving = 0; halving < 40; ++halving, step /= 2) {
        const Vec2 q = at + step * direction;
        if (cspace->locate(exactly(q)).kind == Location::Kind::free && check_segment(*cspace, p, exactly(q)).valid)
          return q;
      }
    }
    return std::nullopt;
  }

  static Vec2 nearest_on(const BoundarySite& s, Vec2 p) {
    const Vec2 d = s.b - s.a;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(p - s.a, d) / l2, 0.0, 1.0) : 0;
    return s.a + t * d;
  }
};

VoronoiDiagram::VoronoiDiagram(const CSpace& cspace, const std::vector<ExactPoint>& inside)
    : impl_(std::make_unique<Impl>(cspace, inside)) {}
VoronoiDiagram::~VoronoiDiagram() = default;
VoronoiDiagram::VoronoiDiagram(VoronoiDiagram&&) noexcept = default;
VoronoiDiagram& VoronoiDiagram::operator=(VoronoiDiagram&&) noexcept = default;

const std::vector<BoundarySite>& VoronoiDiagram::sites() const { return impl_->sites; }
const std::vector<DiagramVertex>& VoronoiDiagram::vertices() const { return impl_->vertices; }
const std::vector<DiagramEdge>& VoronoiDiagram::edges() const { return impl_->edges; }
bool VoronoiDiagram::in_frame(const ExactPoint& p) const {
  return !impl_->frame || detail::strictly_inside(*impl_->frame, p);
}
bool VoronoiDiagram::is_parabolic(std::size_t edge) const { return impl_->curves[edge].parabolic; }
double VoronoiDiagram::parameter_from(std::size_t edge) const { return impl_->curves[edge].t_from; }
double VoronoiDiagram::parameter_to(std::size_t edge) const { return impl_->curves[edge].t_to; }
Vec2 VoronoiDiagram::point(std::size_t edge, double parameter) const { return impl_->curves[edge].point(parameter); }
double VoronoiDiagram::clearance_between(std::size_t edge, double t1, double t2) const {
  return impl_->clearance_between(edge, t1, t2);
}
double VoronoiDiagram::length_between(std::size_t edge, double t1, double t2) const {
  return impl_->length_between(edge, t1, t2);
}

double VoronoiDiagram::sagitta(std::size_t edge, double t1, double t2) const {
  const Curve& c = impl_->curves[edge];
  return c.parabolic ? (t2 - t1) * (t2 - t1) / (16 * c.f) : 0;
}

Vec2 VoronoiDiagram::bezier_control(std::size_t edge, double t1, double t2) const {
  const Curve& c = impl_->curves[edge];
  if (!c.parabolic) return 0.5 * (c.point(t1) + c.point(t2));
  return c.apex + ((t1 + t2) / 2) * c.t + (t1 * t2 / (4 * c.f)) * c.n;
}

// Along the ray from p away from its nearest boundary point, the nearest site stays the same
// until the ray crosses the diagram: bisected on CGAL's exact nearest-site predicate, to the last
// double, then matched to the nearest edge of the site's region.
std::optional<VoronoiDiagram::Retraction> VoronoiDiagram::retract(const ExactPoint& exact_p) const {
  const Impl& d = *impl_;
  if (d.sites.empty() || d.cspace->locate(exact_p).kind == Location::Kind::blocked) return std::nullopt;
  Vec2 p = approximate(exact_p);
  const double clearance = distance_to_site(p, d.sites[d.site_at(p)]);
  std::optional<Vec2> off_boundary;
  if (clearance == 0) {  // on the boundary: no direction away from it yet
    off_boundary = d.step_off_boundary(exact_p);
    if (!off_boundary) return std::nullopt;
    p = *off_boundary;
  }
  const std::size_t own = d.site_at(p);
  const Vec2 away = p - Impl::nearest_on(d.sites[own], p);
  if (!(norm(away) > 0)) return std::nullopt;
  const Vec2 direction = (1 / norm(away)) * away;
  auto along = [&](double t) { return p + t * direction; };
  double inside = 0, outside = 1e-9 * (1 + norm(p));
  while (d.site_at(along(outside)) == own) {
    inside = outside;
    outside *= 2;
    if (!std::isfinite(outside) || outside > 1e300) return std::nullopt;
  }
  for (int i = 0; i < 200 && inside < outside; ++i) {
    const double middle = inside + (outside - inside) / 2;
    if (middle <= inside || middle >= outside) break;
    (d.site_at(along(middle)) == own ? inside : outside) = middle;
  }
  // The edge of the own site's region nearest to where the ray left it (at a Voronoi vertex several
  // edges meet: any of them).
  const Vec2 hit = along(inside);
  std::optional<CurvePoint> best;
  double best_distance = INFINITY;
  for (std::size_t e : d.edges_of_site[own]) {
    const Curve& c = d.curves[e];
    const double lo = std::min(c.t_from, c.t_to), hi = std::max(c.t_from, c.t_to);
    const double u = std::clamp(c.parameter_of(hit), lo, hi);
    const double miss = norm(c.point(u) - hit);
    if (miss < best_distance) {
      best_distance = miss;
      best = CurvePoint{e, u};
    }
  }
  if (!best) return std::nullopt;
  return Retraction{*best, off_boundary, clearance};
}

}  // namespace polyplan
