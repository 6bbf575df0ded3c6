#include <polyplan/geometry/path_check.hpp>

#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/detail/vertex_wedges.hpp>

#include <boost/variant/get.hpp>

#include <algorithm>

namespace polyplan {
namespace {

using namespace detail;
using Impl = CSpace::Impl;
using Arrangement = Impl::Arrangement;

std::string segment_text(std::size_t i, const Point& a, const Point& b) {
  return "segment " + std::to_string(i) + " " + to_text(a) + "-" + to_text(b);
}

PathCheck invalid(std::size_t segment, std::string reason) { return {false, std::move(reason), segment}; }

// Cells of the arrangement that the open segment a-b meets, split by kind.
struct Zone {
  std::vector<Impl::Face> faces;
  std::vector<Impl::Vertex> vertices;
  std::vector<Impl::Halfedge> edges;
};

Zone zone_of(const Impl& impl, const Point& a, const Point& b) {
  using Cell = boost::variant<Arrangement::Vertex_handle, Arrangement::Halfedge_handle, Arrangement::Face_handle>;
  std::vector<Cell> cells;
  // CGAL's zone takes a mutable arrangement but only reads it.
  auto& arr = const_cast<Arrangement&>(impl.free_set.arrangement());
  CGAL::zone(arr, Arrangement::X_monotone_curve_2(a, b), std::back_inserter(cells), *impl.point_location);
  Zone zone;
  for (const Cell& cell : cells) {
    if (auto* f = boost::get<Arrangement::Face_handle>(&cell)) zone.faces.push_back(*f);
    else if (auto* v = boost::get<Arrangement::Vertex_handle>(&cell)) zone.vertices.push_back(*v);
    else if (auto* e = boost::get<Arrangement::Halfedge_handle>(&cell)) zone.edges.push_back(*e);
  }
  return zone;
}

// A point of the open segment a-b inside a blocked face, if there is one: the midpoints between
// consecutive crossings with the zone's edges and vertices each lie in one cell.
std::optional<Point> blocked_witness(const CSpace& cspace, const Zone& zone, const Point& a, const Point& b) {
  const Segment s(a, b);
  std::vector<Point> cuts{a, b};
  for (const auto& e : zone.edges) {
    const Segment edge(e->source()->point(), e->target()->point());
    if (auto x = CGAL::intersection(s, edge))
      if (auto* p = boost::get<Point>(&*x)) cuts.push_back(*p);
  }
  for (const auto& v : zone.vertices) cuts.push_back(v->point());
  std::sort(cuts.begin(), cuts.end(),
            [&](const Point& p, const Point& q) { return CGAL::compare_distance_to_point(a, p, q) == CGAL::SMALLER; });
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i] == cuts[i + 1]) continue;
    const Point mid = CGAL::midpoint(cuts[i], cuts[i + 1]);
    if (cspace.locate(to_exact(mid)).kind == Location::Kind::blocked) return mid;
  }
  return std::nullopt;
}

}  // namespace

PathCheck check_path(const CSpace& cspace, const std::vector<ExactPoint>& path) {
  const Impl& impl = CSpaceAccess::impl(cspace);
  std::vector<Point> points;
  for (const ExactPoint& p : path) {
    Point q = to_point(p);
    if (points.empty() || points.back() != q) points.push_back(q);  // zero-length steps carry no motion
  }
  if (points.empty()) return {false, "the path is empty", std::nullopt};

  const auto located = [&](const Point& p) { return cspace.locate(to_exact(p)); };
  for (std::size_t i = 0; i < points.size(); ++i)
    if (located(points[i]).kind == Location::Kind::blocked) {
      std::string why = cspace.collision_at(to_exact(points[i])).value_or("blocked");
      return invalid(i == 0 ? 0 : i - 1,
                     "point " + std::to_string(i) + " " + to_text(points[i]) + " is not free: " + why);
    }

  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Point &a = points[i], &b = points[i + 1];
    const Zone zone = zone_of(impl, a, b);
    // The zone may list a face the segment only touches at an end (CGAL reports the face beyond
    // an endpoint that lies on an edge), so a blocked face is a reason to look, and the verdict
    // is a blocked point: each open piece between consecutive crossings lies in a single cell.
    const bool touches_blocked_face =
        std::any_of(zone.faces.begin(), zone.faces.end(), [](const auto& face) { return !face->contained(); });
    if (touches_blocked_face)
      if (auto witness = blocked_witness(cspace, zone, a, b)) {
        const std::string what = cspace.collision_at(to_exact(*witness)).value_or("");
        return invalid(i, segment_text(i, a, b) + " enters a C-obstacle at " + to_text(*witness) +
                              (what.empty() ? "" : ": " + what));
      }
    // Passing straight through a pinch point: arriving and leaving wedges must be the same.
    for (const auto& v : zone.vertices) {
      if (v->point() == a || v->point() == b || v->is_isolated()) continue;
      VertexWedges wedges(v->point(), v->incident_halfedges());
      if (!wedges.is_pinch()) continue;
      if (wedges.wedge(Kernel::Direction_2(a - v->point())) != wedges.wedge(Kernel::Direction_2(b - v->point())))
        return invalid(i, segment_text(i, a, b) + " passes through the pinch point " + to_text(v->point()) +
                              " where C-obstacles touch (zero-width passage)");
    }
  }

  // Turning at a pinch point: allowed only back into the wedge the path came from.
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    auto where = impl.point_location->locate(points[i]);
    auto* vertex = boost::get<Impl::Vertex>(&where);
    if (!vertex || (*vertex)->is_isolated()) continue;
    VertexWedges wedges((*vertex)->point(), (*vertex)->incident_halfedges());
    if (!wedges.is_pinch()) continue;
    if (wedges.wedge(Kernel::Direction_2(points[i - 1] - points[i])) !=
        wedges.wedge(Kernel::Direction_2(points[i + 1] - points[i])))
      return invalid(i, "the path turns at the pinch point " + to_text(points[i]) +
                            " into another free wedge than it came from (zero-width passage)");
  }
  return {};
}

PathCheck check_segment(const CSpace& cspace, const ExactPoint& a, const ExactPoint& b) {
  return check_path(cspace, {a, b});
}

}  // namespace polyplan
