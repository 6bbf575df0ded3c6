#include <polyplan/free_space/detail/free_space_triangulation.hpp>

#include <polyplan/geometry/detail/free_space_frame.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <unordered_map>

namespace polyplan::detail {
namespace {

struct FaceInfo {
  bool free = false;
  bool visited = false;  // flood fill
  int component = -1;    // free triangles joined across unconstrained edges: a free component
};
constexpr int kNoVertex = -1;  // triangulation vertices that are not free-space vertices (frame)

using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Face = CDT::Face_handle;
using VertexHandle = CDT::Vertex_handle;

// A closed cone of directions from `apex`, from the ray towards `right` counter-clockwise to the
// ray towards `left`; narrower than 180 degrees (it always lies within one triangle's view).
struct Cone {
  Point right, left;
};

}  // namespace

struct FreeSpaceTriangulation::Impl {
  CDT cdt;
  std::optional<Bounds> frame;  // only for an unbounded free space
  std::vector<Point> points;
  std::vector<VertexWedges> wedges;
  std::vector<VertexHandle> handles;
  // Per-query "already reported" marks, reset in O(1) by a generation counter.
  mutable std::vector<std::uint32_t> seen;
  mutable std::uint32_t generation = 0;

  struct Step {
    Face face;
    int entry;  // index of the edge we entered through
    Cone cone;
  };

  void report(VertexHandle v, std::vector<std::size_t>& out) const {
    const int id = v->info();
    if (id == kNoVertex || seen[static_cast<std::size_t>(id)] == generation) return;
    seen[static_cast<std::size_t>(id)] = generation;
    out.push_back(static_cast<std::size_t>(id));
  }

  static bool in_cone(const Point& apex, const Cone& c, const Point& q) {
    return CGAL::orientation(apex, c.right, q) != CGAL::RIGHT_TURN &&
           CGAL::orientation(apex, c.left, q) != CGAL::LEFT_TURN;
  }

  // The part of `cone` that passes through the edge a-b; false when none passes through the
  // edge's interior. A cone of positive width must keep a positive width: rays that only touch
  // the edge at an endpoint would continue past that vertex into whatever lies behind it (an
  // obstacle, say). Positive width everywhere is what makes the closed cones exact: every ray of
  // a cone, its boundary rays included, is a limit of rays that cross the same open edges, so it
  // lies in the closure of the free space.
  static bool narrow(const Point& apex, const Cone& cone, const Point& a, const Point& b, Cone& out) {
    const CGAL::Orientation turn = CGAL::orientation(apex, a, b);
    if (turn == CGAL::COLLINEAR) return false;  // seen end-on
    const Point& r = turn == CGAL::LEFT_TURN ? a : b;
    const Point& l = turn == CGAL::LEFT_TURN ? b : a;
    out.right = CGAL::orientation(apex, cone.right, r) == CGAL::LEFT_TURN ? r : cone.right;
    out.left = CGAL::orientation(apex, cone.left, l) == CGAL::RIGHT_TURN ? l : cone.left;
    return CGAL::orientation(apex, out.right, out.left) == CGAL::LEFT_TURN;
  }

  // Enters the triangle across edge `edge` of `face` with the part of `cone` that crosses it.
  void cross(const Point& apex, Face face, int edge, const Cone& cone, std::vector<Step>& stack) const {
    if (cdt.is_constrained({face, edge})) return;
    const Point& a = face->vertex(CDT::ccw(edge))->point();
    const Point& b = face->vertex(CDT::cw(edge))->point();
    Cone narrowed;
    if (!narrow(apex, cone, a, b, narrowed)) return;
    Face next = face->neighbor(edge);
    if (!next->info().free) return;
    stack.push_back({next, next->index(face), narrowed});
  }

  // Walks the stacked steps: reports each triangle's far vertex inside the cone and goes on
  // across its two other edges.
  void expand(const Point& apex, std::vector<Step>& stack, std::vector<std::size_t>& out) const {
    while (!stack.empty()) {
      const Step step = stack.back();
      stack.pop_back();
      const VertexHandle far = step.face->vertex(step.entry);
      if (in_cone(apex, step.cone, far->point())) report(far, out);
      cross(apex, step.face, CDT::ccw(step.entry), step.cone, stack);
      cross(apex, step.face, CDT::cw(step.entry), step.cone, stack);
    }
  }

  // From a free triangle containing the apex in its closure: its vertices are visible, and the
  // walk goes on across each edge that does not contain the apex.
  void expand_from(const Point& apex, Face face, std::vector<std::size_t>& out) const {
    std::vector<Step> stack;
    for (int i = 0; i < 3; ++i) {
      report(face->vertex(i), out);
      const Point& a = face->vertex(CDT::ccw(i))->point();
      const Point& b = face->vertex(CDT::cw(i))->point();
      const CGAL::Orientation turn = CGAL::orientation(apex, a, b);
      if (turn != CGAL::COLLINEAR) cross(apex, face, i, turn == CGAL::LEFT_TURN ? Cone{a, b} : Cone{b, a}, stack);
    }
    expand(apex, stack, out);
  }

  // The triangles whose closure contains p (one, two on an edge, the fan at a vertex, then
  // stored in *vertex).
  // `found`: the face the location ended in (a hint for locating p again).
  std::vector<Face> faces_at(const Point& p, VertexHandle* vertex = nullptr, Face* found = nullptr) const {
    std::vector<Face> faces;
    if (cdt.dimension() < 2) return faces;
    CDT::Locate_type type;
    int li = 0;
    const Face located = cdt.locate(p, type, li);
    if (found) *found = located;
    switch (type) {
      case CDT::FACE: faces.push_back(located); break;
      case CDT::EDGE:
        faces.push_back(located);
        faces.push_back(located->neighbor(li));
        break;
      case CDT::VERTEX: {
        auto face = cdt.incident_faces(located->vertex(li)), first = face;
        do faces.push_back(face);
        while (++face != first);
        if (vertex) *vertex = located->vertex(li);
        break;
      }
      default: break;
    }
    return faces;
  }

  static bool in_closed_triangle(Face f, const Point& q) {
    for (int i = 0; i < 3; ++i)
      if (CGAL::orientation(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point(), q) == CGAL::RIGHT_TURN)
        return false;
    return true;
  }

  void begin_query() const {
    if (++generation == 0) {  // wrapped: clear for real once every 4 billion queries
      std::fill(seen.begin(), seen.end(), 0);
      generation = 1;
    }
  }
};

FreeSpaceTriangulation::FreeSpaceTriangulation(const CSpace::Impl& cspace, const std::vector<ExactPoint>& inside)
    : impl_(std::make_unique<Impl>()) {
  Impl& t = *impl_;
  const auto& arr = cspace.free_set.arrangement();
  std::unordered_map<const void*, int> index;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->is_isolated()) continue;
    index.emplace(&*v, static_cast<int>(t.points.size()));
    t.points.push_back(v->point());
    t.wedges.emplace_back(v->point(), v->incident_halfedges());
  }
  t.seen.assign(t.points.size(), 0);

  VertexHandle hint;
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    VertexHandle h = hint == VertexHandle() ? t.cdt.insert(t.points[i]) : t.cdt.insert(t.points[i], hint->face());
    h->info() = static_cast<int>(i);
    t.handles.push_back(h);
    hint = h;
  }
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
    t.cdt.insert_constraint(t.handles[static_cast<std::size_t>(index.at(&*e->source()))],
                            t.handles[static_cast<std::size_t>(index.at(&*e->target()))]);

  // Without bounds the free space is unbounded: a frame closes it (geometry/detail/free_space_frame.hpp).
  if (arr.unbounded_face()->contained()) {
    t.frame = free_space_frame(cspace, inside);
    const Bounds& b = *t.frame;
    const Point corners[4] = {to_point({b.xmin, b.ymin}), to_point({b.xmax, b.ymin}), to_point({b.xmax, b.ymax}),
                              to_point({b.xmin, b.ymax})};
    VertexHandle frame[4];
    for (int i = 0; i < 4; ++i) {
      frame[i] = t.cdt.insert(corners[i]);
      frame[i]->info() = kNoVertex;
    }
    for (int i = 0; i < 4; ++i) t.cdt.insert_constraint(frame[i], frame[(i + 1) % 4]);
  }

  // No free space at all (the robot fits nowhere): no triangles, nothing is visible or free.
  if (t.cdt.dimension() < 2) return;

  // Every constraint separates free from blocked, and outside the triangulation is blocked: a
  // flood fill that flips at constraints marks the free triangles.
  std::vector<std::pair<Face, bool>> queue{{t.cdt.infinite_face(), false}};
  t.cdt.infinite_face()->info().visited = true;
  while (!queue.empty()) {
    auto [face, free] = queue.back();
    queue.pop_back();
    face->info().free = free && !t.cdt.is_infinite(face);
    for (int i = 0; i < 3; ++i) {
      Face next = face->neighbor(i);
      if (next->info().visited) continue;
      next->info().visited = true;
      queue.push_back({next, t.cdt.is_constrained({face, i}) ? !free : free});
    }
  }
  // Components of the open free space: free triangles that share an unconstrained edge (sharing
  // only a vertex, a pinch point, does not connect them).
  int components = 0;
  for (auto f = t.cdt.finite_faces_begin(); f != t.cdt.finite_faces_end(); ++f) {
    if (!f->info().free || f->info().component >= 0) continue;
    std::vector<Face> stack{f};
    f->info().component = components;
    while (!stack.empty()) {
      Face face = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        Face next = face->neighbor(i);
        if (t.cdt.is_constrained({face, i}) || !next->info().free || next->info().component >= 0) continue;
        next->info().component = components;
        stack.push_back(next);
      }
    }
    ++components;
  }
}

FreeSpaceTriangulation::~FreeSpaceTriangulation() = default;

bool FreeSpaceTriangulation::in_frame(const ExactPoint& p) const {
  return !impl_->frame || strictly_inside(*impl_->frame, p);
}

std::size_t FreeSpaceTriangulation::vertex_count() const { return impl_->points.size(); }
const Point& FreeSpaceTriangulation::point(std::size_t v) const { return impl_->points[v]; }
const VertexWedges& FreeSpaceTriangulation::wedges(std::size_t v) const { return impl_->wedges[v]; }
std::size_t FreeSpaceTriangulation::triangle_count() const { return impl_->cdt.number_of_faces(); }

FreeSpaceTriangulation::Arrays FreeSpaceTriangulation::arrays() const {
  const Impl& t = *impl_;
  Arrays arrays;
  arrays.points = t.points;
  std::unordered_map<const void*, int> vertex_index, face_index;
  for (std::size_t i = 0; i < t.handles.size(); ++i) vertex_index.emplace(&*t.handles[i], static_cast<int>(i));
  for (auto v = t.cdt.finite_vertices_begin(); v != t.cdt.finite_vertices_end(); ++v)
    if (v->info() == kNoVertex) {  // a frame corner
      vertex_index.emplace(&*v, static_cast<int>(arrays.points.size()));
      arrays.points.push_back(v->point());
    }
  if (t.cdt.dimension() < 2) return arrays;
  for (auto f = t.cdt.finite_faces_begin(); f != t.cdt.finite_faces_end(); ++f)
    face_index.emplace(&*f, static_cast<int>(face_index.size()));
  arrays.triangles.resize(face_index.size());
  for (auto f = t.cdt.finite_faces_begin(); f != t.cdt.finite_faces_end(); ++f) {
    Arrays::Triangle& triangle = arrays.triangles[static_cast<std::size_t>(face_index.at(&*f))];
    for (int i = 0; i < 3; ++i) {
      triangle.vertex[i] = vertex_index.at(&*f->vertex(i));
      const Face n = f->neighbor(i);
      triangle.neighbour[i] = t.cdt.is_infinite(n) ? -1 : face_index.at(&*n);
      triangle.constrained[i] = t.cdt.is_constrained({f, i});
    }
    triangle.free = f->info().free;
    triangle.component = f->info().component;
  }
  return arrays;
}

void FreeSpaceTriangulation::visible_from_corner(std::size_t v, std::size_t wedge,
                                                 std::vector<std::size_t>& out) const {
  const Impl& t = *impl_;
  t.begin_query();
  t.seen[v] = t.generation;  // not itself
  const VertexHandle h = t.handles[v];
  const Point& apex = t.points[v];
  auto face = t.cdt.incident_faces(h), first = face;
  do {
    if (!face->info().free) continue;
    // A free triangle lies in one free wedge of its corner; any of its edges at the corner tells
    // which (a constrained one belongs to its free side, which is this triangle's).
    const Point& along = face->vertex(CDT::ccw(face->index(h)))->point();
    if (t.wedges[v].wedge(VertexWedges::Direction(along - apex)) != wedge) continue;
    const int i = face->index(h);
    const VertexHandle a = face->vertex(CDT::ccw(i)), b = face->vertex(CDT::cw(i));
    t.report(a, out);
    t.report(b, out);
    std::vector<Impl::Step> stack;
    t.cross(apex, face, i, Cone{a->point(), b->point()}, stack);  // counter-clockwise: a is on the right
    t.expand(apex, stack, out);
  } while (++face != first);
}

bool FreeSpaceTriangulation::visible_from_point(const Point& p, std::vector<std::size_t>& out) const {
  const Impl& t = *impl_;
  t.begin_query();
  VertexHandle itself;
  const std::vector<Face> faces = t.faces_at(p, &itself);
  if (itself != VertexHandle() && itself->info() != kNoVertex)  // a viewpoint does not see itself
    t.seen[static_cast<std::size_t>(itself->info())] = t.generation;
  bool any_free = false;
  for (Face f : faces)
    if (f->info().free) {
      any_free = true;
      t.expand_from(p, f, out);
    }
  return any_free;
}

std::vector<int> FreeSpaceTriangulation::components_at(const Point& p) const {
  std::vector<int> components;
  for (Face f : impl_->faces_at(p))
    if (f->info().free && std::find(components.begin(), components.end(), f->info().component) == components.end())
      components.push_back(f->info().component);
  return components;
}

struct FreeSpaceTriangulation::Place {
  Face face;
};

std::shared_ptr<const FreeSpaceTriangulation::Place> FreeSpaceTriangulation::place(const Point& p, bool& free) const {
  auto place = std::make_shared<Place>();
  const std::vector<Face> faces = impl_->faces_at(p, nullptr, &place->face);
  free = std::any_of(faces.begin(), faces.end(), [](Face f) { return f->info().free; });
  return place;
}

std::optional<std::string> FreeSpaceTriangulation::why_blocked(const Point& a, const Point& b) const {
  return why_blocked(a, b, nullptr);
}

// Walks the segment a-b through the triangulation: across unconstrained edges, along edges, and
// through vertices, where docs/design.md's pinch rule decides (arrive and leave in one free wedge).
// Entering a blocked triangle or crossing a constrained edge is entering a C-obstacle.
std::optional<std::string> FreeSpaceTriangulation::why_blocked(const Point& a, const Point& b,
                                                               const Place* a_place) const {
  const Impl& t = *impl_;
  if (a == b) {
    const std::vector<Face> faces = t.faces_at(a);
    if (std::none_of(faces.begin(), faces.end(), [](Face f) { return f->info().free; }))
      return std::string("the point is blocked");
    return std::nullopt;
  }
  auto ahead = [&](const Point& q) {  // strictly beyond a in the direction of b
    return CGAL::scalar_product(q - a, b - a) > 0;
  };
  auto on_segment_before = [&](const Point& q, const Point& far) {  // b on [q, far]?
    return CGAL::collinear(q, far, b) && CGAL::collinear_are_ordered_along_line(q, b, far);
  };
  Face face;               // the triangle the segment runs into, or
  VertexHandle at;         // the vertex the segment passes through
  VertexHandle came_from;  // the vertex we left the last time, if any
  bool arrived = false;    // at a vertex: reached it along the segment (not its start)

  CDT::Locate_type type;
  int li = 0;
  if (t.cdt.dimension() < 2) return std::string("no free space");
  const Face start = t.cdt.locate(a, type, li, a_place ? a_place->face : Face());
  switch (type) {
    case CDT::FACE: face = start; break;
    case CDT::VERTEX: at = start->vertex(li); break;
    case CDT::EDGE: {
      // An edge between two blocked triangles lies inside a C-obstacle (a free-space boundary
      // edge has a free side).
      if (!start->info().free && !start->neighbor(li)->info().free) return std::string("starts inside a C-obstacle");
      const VertexHandle u = start->vertex(CDT::ccw(li)), w = start->vertex(CDT::cw(li));
      const CGAL::Orientation side = CGAL::orientation(u->point(), w->point(), b);
      if (side == CGAL::COLLINEAR) {  // along the edge, towards u or w
        at = ahead(u->point()) ? u : w;
        if (on_segment_before(a, at->point())) return std::nullopt;
        arrived = true;
      } else {
        // start lies left of u->w (counter-clockwise triangle); the neighbour is on the right.
        face = side == CGAL::LEFT_TURN ? start : start->neighbor(li);
      }
      break;
    }
    default: return std::string("the start is outside the free space");
  }

  for (std::size_t steps = 0; steps < 4 * t.cdt.number_of_faces() + 8; ++steps) {
    if (at != VertexHandle()) {
      if (at->point() == b) return std::nullopt;
      const int id = at->info();
      if (id == kNoVertex) return std::string("leaves the free space at the frame");
      const VertexWedges& wedges = t.wedges[static_cast<std::size_t>(id)];
      const auto leaving = wedges.wedge(VertexWedges::Direction(b - a));
      if (!leaving) return "enters a C-obstacle at " + to_text(at->point());
      if (arrived && wedges.wedge(VertexWedges::Direction(a - b)) != leaving)
        return "passes through the pinch point " + to_text(at->point()) + " (zero-width passage)";
      // Leave into the triangle (or along the edge) of the vertex's fan that holds the direction.
      VertexHandle next_vertex;
      Face next_face;
      auto fan = t.cdt.incident_faces(at), first = fan;
      do {
        if (t.cdt.is_infinite(fan)) continue;
        const int j = fan->index(at);
        const VertexHandle p1 = fan->vertex(CDT::ccw(j)), p2 = fan->vertex(CDT::cw(j));
        const CGAL::Orientation o1 = CGAL::orientation(at->point(), p1->point(), b);
        const CGAL::Orientation o2 = CGAL::orientation(at->point(), p2->point(), b);
        // An edge of the fan along the direction (either side of this triangle: the triangle
        // on the other side may be the infinite one), or a triangle the direction enters.
        if (o1 == CGAL::COLLINEAR && CGAL::scalar_product(p1->point() - at->point(), b - a) > 0) next_vertex = p1;
        else if (o2 == CGAL::COLLINEAR && CGAL::scalar_product(p2->point() - at->point(), b - a) > 0) next_vertex = p2;
        else if (o1 == CGAL::LEFT_TURN && o2 == CGAL::RIGHT_TURN) next_face = fan;
      } while ((next_face == Face() && next_vertex == VertexHandle()) && ++fan != first);
      came_from = at;
      at = VertexHandle();
      if (next_vertex != VertexHandle()) {  // along an edge of the fan; the wedge says it is free
        if (on_segment_before(came_from->point(), next_vertex->point())) return std::nullopt;
        at = next_vertex;
        arrived = true;
        continue;
      }
      if (next_face == Face() || !next_face->info().free)
        return "enters a C-obstacle at " + to_text(came_from->point());
      face = next_face;
      continue;
    }
    // In a free triangle: done if b is in it; else leave through a vertex on the line or an edge.
    if (!face->info().free) return std::string("enters a C-obstacle");
    if (Impl::in_closed_triangle(face, b)) return std::nullopt;
    int exit_edge = -1;
    for (int i = 0; i < 3 && at == VertexHandle(); ++i) {
      const VertexHandle v = face->vertex(i);
      if (v != came_from && CGAL::orientation(a, b, v->point()) == CGAL::COLLINEAR && ahead(v->point())) at = v;
    }
    if (at != VertexHandle()) {
      arrived = true;
      continue;
    }
    for (int i = 0; i < 3; ++i)
      if (CGAL::orientation(a, b, face->vertex(CDT::ccw(i))->point()) == CGAL::RIGHT_TURN &&
          CGAL::orientation(a, b, face->vertex(CDT::cw(i))->point()) == CGAL::LEFT_TURN)
        exit_edge = i;
    if (exit_edge < 0) return std::string("lost its way in the triangulation");  // cannot happen
    if (t.cdt.is_constrained({face, exit_edge})) return std::string("crosses into a C-obstacle");
    face = face->neighbor(exit_edge);
    came_from = VertexHandle();
  }
  return std::string("lost its way in the triangulation");
}

std::optional<std::string> FreeSpaceTriangulation::why_path_blocked(const std::vector<Point>& given) const {
  // A zero-length step carries no motion and has no direction to turn by.
  std::vector<Point> path;
  for (const Point& p : given)
    if (path.empty() || path.back() != p) path.push_back(p);
  if (path.size() == 1) return why_blocked(path[0], path[0]);
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (auto why = why_blocked(path[i], path[i + 1]))
      return "segment " + std::to_string(i) + " " + to_text(path[i]) + "-" + to_text(path[i + 1]) + ": " + *why;
  // Turning at a pinch point: back into the wedge the path came from, never across.
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    CDT::Locate_type type;
    int li = 0;
    const Face f = impl_->cdt.locate(path[i], type, li);
    if (type != CDT::VERTEX || f->vertex(li)->info() == kNoVertex) continue;
    const VertexWedges& w = impl_->wedges[static_cast<std::size_t>(f->vertex(li)->info())];
    if (w.is_pinch() && w.wedge(VertexWedges::Direction(path[i - 1] - path[i])) !=
                            w.wedge(VertexWedges::Direction(path[i + 1] - path[i])))
      return "turns at the pinch point " + to_text(path[i]) + " into another free wedge";
  }
  return std::nullopt;
}

}  // namespace polyplan::detail
