#include <polyplan/free_space/trapezoidal_decomposition.hpp>

#include <polyplan/geometry/detail/free_space_frame.hpp>
#include <polyplan/geometry/polyline.hpp>

#include <CGAL/Arr_default_overlay_traits.h>
#include <CGAL/Arr_overlay_2.h>
#include <CGAL/Arr_vertical_decomposition_2.h>
#include <CGAL/Arr_walk_along_line_point_location.h>

#include <boost/function_output_iterator.hpp>

#include <algorithm>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace polyplan {
namespace {

using detail::Point;
using detail::to_exact;
using detail::to_point;
using PolygonSet = CSpace::Impl::PolygonSet;
using Arrangement = CSpace::Impl::Arrangement;
// A walk down a vertical line from above, with no structure to build: it crosses only the cells
// stacked over the point (a few dozen on the MovingAI maps), while a trapezoidal-map search
// structure would cost as much to build as the decomposition itself.
using PointLocation = CGAL::Arr_walk_along_line_point_location<Arrangement>;

// The point of the non-vertical edge `h` above or below p, exactly: its line at p's x.
Point on_edge_at_x(Arrangement::Halfedge_const_handle h, const Point& p) {
  const Point &a = h->source()->point(), &b = h->target()->point();
  return {p.x(), a.y() + (p.x() - a.x()) * (b.y() - a.y()) / (b.x() - a.x())};
}

// The overlay keeps the free-space arrangement's face flags: a face of the result is free when
// the free-space face it lies in is.
struct KeepFreeFaces : CGAL::Arr_default_overlay_traits<Arrangement> {
  void create_face(Face_handle_A free_face, Face_handle_B, Face_handle_R face) const override {
    face->set_contained(free_face->contained());
  }
};

Rational cross(const ExactPoint& a, const ExactPoint& b) { return a.x * b.y - a.y * b.x; }

// The centre of area of a simple counterclockwise polygon (the shoelace formula's centroid).
ExactPoint centroid(const std::vector<ExactPoint>& ring) {
  Rational twice_area = 0, x = 0, y = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint &p = ring[i], &q = ring[(i + 1) % ring.size()];
    const Rational c = cross(p, q);
    twice_area += c;
    x += (p.x + q.x) * c;
    y += (p.y + q.y) * c;
  }
  return {x / (3 * twice_area), y / (3 * twice_area)};
}

// Sweep counts over the non-vertical edges of the free-space boundary, their ends compared
// exactly: at one x, the edges ending there leave the sweep line before those starting there
// enter it, so a line just right of x crosses what the count says.
SweepCounts sweep_counts(const Arrangement& arrangement) {
  std::vector<std::pair<Rational, int>> events;  // (x, -1 leaving | +1 entering)
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    const Rational a = detail::to_rational(e->source()->point().x()), b = detail::to_rational(e->target()->point().x());
    if (a == b) continue;
    events.push_back({std::min(a, b), +1});
    events.push_back({std::max(a, b), -1});
  }
  std::sort(events.begin(), events.end());
  SweepCounts counts;
  counts.insertions = counts.deletions = events.size() / 2;
  std::size_t crossed = 0;
  for (const auto& [x, change] : events) {
    crossed = change > 0 ? crossed + 1 : crossed - 1;
    counts.most_crossed = std::max(counts.most_crossed, crossed);
  }
  return counts;
}

}  // namespace

struct TrapezoidalDecomposition::Impl {
  std::optional<Bounds> frame;    // only for an unbounded free space
  Arrangement cells_arrangement;  // the free space's boundary and the walls
  std::unique_ptr<PointLocation> point_location;
  std::unordered_map<const void*, std::size_t> cell_of_face;  // keyed by &*face
  std::vector<Ring> cells;
  std::vector<ExactPoint> centroids;
  std::vector<TrapezoidWall> walls;
  SweepCounts sweep;

  std::optional<std::size_t> cell(Arrangement::Face_const_handle face) const {
    auto it = cell_of_face.find(&*face);
    if (it == cell_of_face.end()) return std::nullopt;
    return it->second;
  }

  Impl(const CSpace& cspace, const std::vector<ExactPoint>& inside) {
    detail::FramedFreeSpace framed = detail::framed_free_space(detail::CSpaceAccess::impl(cspace), inside);
    frame = framed.frame;
    const Arrangement& boundary = framed.free_set.arrangement();
    sweep = sweep_counts(boundary);

    Arrangement wall_arrangement;
    std::vector<Arrangement::X_monotone_curve_2> wall_segments = vertical_walls(cspace, boundary);
    CGAL::insert(wall_arrangement, wall_segments.begin(), wall_segments.end());
    KeepFreeFaces keep_free_faces;
    CGAL::overlay(boundary, wall_arrangement, cells_arrangement, keep_free_faces);
    collect_cells();
    collect_walls();
    point_location = std::make_unique<PointLocation>(cells_arrangement);
  }

  // A vertex in the middle of a straight edge (Boolean operations and Minkowski sums leave many)
  // is no corner of the free space: it makes no wall.
  static bool is_straight(Arrangement::Vertex_const_handle v) {
    if (v->degree() != 2) return false;
    const auto in = v->incident_halfedges();
    return detail::straight(in->source()->point(), v->point(), std::next(in)->source()->point());
  }

  // From every vertex, the segments up and down to the first boundary feature that lie in the
  // free space. A wall between two vertices on one vertical line is made once.
  static std::vector<Arrangement::X_monotone_curve_2> vertical_walls(const CSpace& cspace,
                                                                     const Arrangement& boundary) {
    using Vertex = Arrangement::Vertex_const_handle;
    using Halfedge = Arrangement::Halfedge_const_handle;
    std::vector<Arrangement::X_monotone_curve_2> segments;
    // A wall lies in one face: the first feature it meets is its end.
    auto add_if = [&](bool free, const Point& lower, const Point& upper) {
      if (free) segments.emplace_back(detail::Segment(lower, upper));
    };
    // Between two vertices the face is found by locating the wall's midpoint.
    auto free_between = [&](const Point& lower, const Point& upper) {
      return cspace.locate(to_exact(CGAL::midpoint(lower, upper))).kind == Location::Kind::free;
    };
    // decompose hands out the halfedge of an edge that runs from right to left: its face (on its
    // left) is the one below the edge, its twin's the one above.
    auto each_vertex = [&](const auto& entry) {
      const Vertex v = entry.first;
      if (is_straight(v)) return;
      const Point& p = v->point();
      const auto& [below, above] = entry.second;
      if (above) {
        if (const Vertex* w = boost::get<Vertex>(&*above)) add_if(free_between(p, (*w)->point()), p, (*w)->point());
        else if (const Halfedge* h = boost::get<Halfedge>(&*above))
          add_if((*h)->face()->contained(), p, on_edge_at_x(*h, p));
      }
      if (below) {
        // A wall down to a vertex is the lower vertex's wall up, unless that one is straight
        // (and makes no walls of its own).
        if (const Vertex* w = boost::get<Vertex>(&*below); w && is_straight(*w))
          add_if(free_between((*w)->point(), p), (*w)->point(), p);
        else if (const Halfedge* h = boost::get<Halfedge>(&*below))
          add_if((*h)->twin()->face()->contained(), on_edge_at_x(*h, p), p);
      }
    };
    CGAL::decompose(boundary, boost::make_function_output_iterator(each_vertex));
    return segments;
  }

  void collect_cells() {
    for (auto f = cells_arrangement.faces_begin(); f != cells_arrangement.faces_end(); ++f) {
      if (!f->contained()) continue;
      if (f->is_unbounded() || f->number_of_holes() != 0)
        throw std::logic_error("trapezoidal decomposition: a free cell is unbounded or has a hole");
      std::vector<ExactPoint> ring;
      auto h = f->outer_ccb();
      do ring.push_back(to_exact(h->source()->point()));
      while (++h != f->outer_ccb());
      std::vector<Point> points;
      for (const ExactPoint& p : ring) points.push_back(to_point(p));
      Ring corners = detail::without_straight_vertices(points);
      // Every cell is a trapezoid or a triangle: a corner turning right means a missing wall.
      for (std::size_t i = 0; i < corners.size(); ++i)
        if (orientation(corners[i], corners[(i + 1) % corners.size()], corners[(i + 2) % corners.size()]) <= 0)
          throw std::logic_error("trapezoidal decomposition: a cell is not convex at " +
                                 to_string(corners[(i + 1) % corners.size()]));
      cell_of_face.emplace(&*f, cells.size());
      centroids.push_back(centroid(ring));
      cells.push_back(std::move(corners));
    }
  }

  // Walls are the edges with free cells on both sides: the free space's own boundary has a
  // C-obstacle (or the outside of the bounds) on one side.
  void collect_walls() {
    for (auto e = cells_arrangement.edges_begin(); e != cells_arrangement.edges_end(); ++e) {
      auto a = cell(e->face()), b = cell(e->twin()->face());
      if (!a || !b) continue;
      const Point &s = e->source()->point(), &t = e->target()->point();
      if (CGAL::compare_x(s, t) != CGAL::EQUAL)
        throw std::logic_error("trapezoidal decomposition: free cells on both sides of a non-vertical edge at " +
                               detail::to_text(s));
      // A halfedge has its face on its left: going up, that is the cell on the wall's left.
      const bool upward = CGAL::compare_y(s, t) == CGAL::SMALLER;
      walls.push_back(upward ? TrapezoidWall{*a, *b, to_exact(s), to_exact(t)}
                             : TrapezoidWall{*b, *a, to_exact(t), to_exact(s)});
    }
  }
};

TrapezoidalDecomposition::TrapezoidalDecomposition(const CSpace& cspace, const std::vector<ExactPoint>& inside)
    : impl_(std::make_unique<Impl>(cspace, inside)) {}
TrapezoidalDecomposition::~TrapezoidalDecomposition() = default;
TrapezoidalDecomposition::TrapezoidalDecomposition(TrapezoidalDecomposition&&) noexcept = default;
TrapezoidalDecomposition& TrapezoidalDecomposition::operator=(TrapezoidalDecomposition&&) noexcept = default;

const std::vector<Ring>& TrapezoidalDecomposition::cells() const { return impl_->cells; }
const std::vector<ExactPoint>& TrapezoidalDecomposition::centroids() const { return impl_->centroids; }
const std::vector<TrapezoidWall>& TrapezoidalDecomposition::walls() const { return impl_->walls; }
const SweepCounts& TrapezoidalDecomposition::sweep() const { return impl_->sweep; }

bool TrapezoidalDecomposition::in_frame(const ExactPoint& p) const {
  return !impl_->frame || detail::strictly_inside(*impl_->frame, p);
}

std::vector<std::size_t> TrapezoidalDecomposition::cells_at(const ExactPoint& p) const {
  std::vector<std::size_t> found;
  auto add = [&](Arrangement::Face_const_handle f) {
    if (auto c = impl_->cell(f); c && std::find(found.begin(), found.end(), *c) == found.end()) found.push_back(*c);
  };
  const auto where = impl_->point_location->locate(to_point(p));
  if (const auto* f = boost::get<Arrangement::Face_const_handle>(&where)) {
    add(*f);
  } else if (const auto* h = boost::get<Arrangement::Halfedge_const_handle>(&where)) {
    add((*h)->face());
    add((*h)->twin()->face());
  } else if (const auto* v = boost::get<Arrangement::Vertex_const_handle>(&where)) {
    if (!(*v)->is_isolated()) {
      auto around = (*v)->incident_halfedges(), first = around;
      do add(around->face());
      while (++around != first);
    }
  }
  return found;
}

}  // namespace polyplan
