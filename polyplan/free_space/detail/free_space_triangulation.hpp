#pragma once
// A constrained triangulation of the free space (the free-space arrangement's edges are its
// constraints) that answers "which boundary vertices can be seen from here" by triangular
// expansion: walk from the viewpoint's triangles across unconstrained edges while a cone of
// directions survives. Only orientation predicates on input points decide anything (exact, no
// constructions), and cones are closed, so grazing a corner or sliding along an edge counts as
// seeing — the closure semantics of docs/design.md. Walls (constraints) are never crossed, so a sight
// line can touch a pinch point but never pass from one of its free wedges into another.
// Include only from .cpp files (CGAL).
#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/detail/vertex_wedges.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace polyplan::detail {

class FreeSpaceTriangulation {
 public:
  // Without bounds, a frame closes the free space around its vertices and `inside`.
  explicit FreeSpaceTriangulation(const CSpace::Impl& cspace, const std::vector<ExactPoint>& inside = {});
  ~FreeSpaceTriangulation();

  // Whether p is strictly inside the frame; always true in a world with bounds.
  bool in_frame(const ExactPoint& p) const;

  // The free-space arrangement's vertices, numbered 0..n-1.
  std::size_t vertex_count() const;
  const Point& point(std::size_t v) const;
  const VertexWedges& wedges(std::size_t v) const;

  // Vertices visible from vertex v looking into its free wedge `wedge` (appended to `out`, each
  // once, v itself excluded).
  void visible_from_corner(std::size_t v, std::size_t wedge, std::vector<std::size_t>& out) const;
  // Vertices visible from a point of the free space's closure; false when p is blocked.
  bool visible_from_point(const Point& p, std::vector<std::size_t>& out) const;

  // The free components (numbered by the triangulation) whose closure holds p; empty when p is
  // blocked. Two at a pinch point between components.
  std::vector<int> components_at(const Point& p) const;

  // nullopt when the segment a-b is a valid motion (docs/design.md: in the closure of the free space,
  // through no zero-width place); else why not. Exact, and a different walk from the visibility
  // cones: it is what checks every path the visibility graph returns.
  std::optional<std::string> why_blocked(const Point& a, const Point& b) const;

  // Where a point lies (the triangle its location found), kept by a caller that walks from the
  // same point again and again (a sampling planner's milestone): locating it is most of a short
  // walk's cost. A hint only, opaque: the walk's answer is the same with it or without.
  struct Place;
  // p's place, and whether p is in the free space's closure (components_at(p) not empty).
  std::shared_ptr<const Place> place(const Point& p, bool& free) const;
  // why_blocked(a, b), located from a's place (made by place(a) for this very point) when given.
  std::optional<std::string> why_blocked(const Point& a, const Point& b, const Place* a_place) const;

  // The same for a polyline, with the pinch rule at its turning points.
  std::optional<std::string> why_path_blocked(const std::vector<Point>& path) const;

  std::size_t triangle_count() const;

  // The triangulation as plain arrays, for engines that re-run these walks in other arithmetic
  // (integer_triangulation.hpp). Vertices 0..vertex_count()-1 are the free-space vertices, then
  // the frame's corners; triangles are the finite ones, counter-clockwise, CGAL's numbering:
  // edge i is opposite vertex i, between vertices i+1 and i+2 (mod 3).
  struct Arrays {
    struct Triangle {
      int vertex[3];
      int neighbour[3];  // across edge i; -1 beyond the convex hull
      bool constrained[3];
      bool free;
      int component;  // free component, -1 for blocked triangles
    };
    std::vector<Point> points;
    std::vector<Triangle> triangles;
  };
  Arrays arrays() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan::detail
