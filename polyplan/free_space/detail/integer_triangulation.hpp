#pragma once
// The free-space triangulation of free_space_triangulation.hpp again, for a free space whose
// vertices all have integer coordinates (MovingAI maps: every corner is a grid point), with the
// same walks — visibility by triangular expansion, the exact segment walk with the pinch rule —
// in 64-bit integer arithmetic. With |coordinates| below 2^30 an orientation is a difference of
// two products below 2^62: exact, so every answer is the exact kernel's, without its lazy numbers
// and allocations. Plain arrays, no CGAL: the walks are const and take their scratch space from
// the caller, so threads share one triangulation.
#include <polyplan/geometry/integer_point.hpp>
#include <polyplan/geometry/rational.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace polyplan {
struct GridMap;
}

namespace polyplan::detail {

class FreeSpaceTriangulation;

// "[x, y]", as messages name points (geometry/rational.hpp's to_string of an ExactPoint).
inline std::string to_text(const IntegerPoint& p) {
  return to_string(ExactPoint{Rational(static_cast<long>(p.x)), Rational(static_cast<long>(p.y))});
}

// +1 left turn, -1 right turn, 0 collinear.
inline int orientation(const IntegerPoint& a, const IntegerPoint& b, const IntegerPoint& c) {
  const std::int64_t d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (d > 0) - (d < 0);
}

// Coordinates of a free-space vertex or query point must lie within this bound.
constexpr std::int64_t kIntegerCoordinateLimit = std::int64_t{1} << 30;

class IntegerTriangulation {
 public:
  // What a triangulation is made of (arrays, as FreeSpaceTriangulation::arrays gives them).
  struct Parts {
    struct Triangle {
      int vertex[3];     // counter-clockwise
      int neighbour[3];  // across edge i (opposite vertex i); -1 beyond the convex hull
      bool constrained[3];
      bool free;
      int component;  // free component, -1 for blocked triangles
    };
    struct WedgeEdge {
      IntegerPoint direction;  // along a free-space boundary edge leaving the vertex
      bool free_on_left;
    };
    std::vector<IntegerPoint> points;  // free-space vertices first, then any others (a frame's)
    std::size_t space_vertices = 0;
    std::vector<Triangle> triangles;
    // wedges[v]: the boundary edges at free-space vertex v, counter-clockwise from the +x direction.
    std::vector<std::vector<WedgeEdge>> wedges;
  };
  static IntegerTriangulation assemble(const Parts& parts);

  // nullopt unless every vertex of `triangulation` is an integer point within the limit.
  static std::optional<IntegerTriangulation> from(const FreeSpaceTriangulation& triangulation);
  // The free space of a MovingAI map (cells [x, x+1] x [y, y+1], outside blocked) straight from
  // its cells (grid_triangulation.cpp): the same vertices, wedges and free space as the exact
  // C-space of world_from_grid(map) for a point robot, without building either.
  static IntegerTriangulation from_grid(const GridMap& map);

  // Where a point lies: in a triangle, on the edge `index` of a triangle, at vertex `index`, or
  // outside the triangulated frame.
  struct Location {
    enum Type : std::uint8_t { outside, face, edge, vertex } type = outside;
    int triangle = -1;
    int index = -1;
  };

  // Per-thread scratch space of the walks ("already reported" marks, the walk's stack).
  class Scratch {
    friend class IntegerTriangulation;
    std::vector<std::uint32_t> seen;
    std::uint32_t generation = 0;
    struct Step {
      int triangle, entry;
      IntegerPoint right, left;
    };
    std::vector<Step> stack;
  };

  // Free-space vertices are 0..vertex_count()-1 (FreeSpaceTriangulation's numbering).
  std::size_t vertex_count() const { return space_vertices_; }
  const IntegerPoint& point(std::size_t v) const { return points_[v]; }

  // Where p lies (a walk from a bucket's triangle: a few steps).
  Location locate(const IntegerPoint& p) const;
  static Location at_vertex(std::size_t v) { return {Location::vertex, -1, static_cast<int>(v)}; }

  // The free wedges at vertex v (VertexWedges in integers): wedge k spans from edge k
  // counter-clockwise to edge k+1.
  std::size_t wedge_count(std::size_t v) const { return wedge_begin_[v + 1] - wedge_begin_[v]; }
  bool is_free_wedge(std::size_t v, std::size_t k) const { return wedges_[wedge_begin_[v] + k].free_on_left; }
  bool is_reflex_wedge(std::size_t v, std::size_t k) const;
  bool is_pinch(std::size_t v) const;
  // The free wedge a motion leaving v in direction d moves into (along an edge: its free side).
  std::optional<std::size_t> wedge(std::size_t v, const IntegerPoint& d) const;

  // Free-space vertices visible from p (a point of the free space's closure), appended to `out`;
  // false when p is blocked.
  bool visible_from_point(const IntegerPoint& p, const Location& where, std::vector<int>& out, Scratch& scratch) const;
  // Free-space vertices visible from vertex v looking into its free wedge `wedge`.
  void visible_from_corner(std::size_t v, std::size_t wedge, std::vector<int>& out, Scratch& scratch) const;

  // The free components whose closure holds the point (two at a pinch between components).
  void components_at(const Location& where, std::vector<int>& out) const;

  // Why a segment is not a valid motion (docs/design.md): reason none when it is.
  struct Blocked {
    enum Reason : std::uint8_t {
      none,
      point_blocked,
      start_outside,
      starts_inside,
      frame,
      enters,
      enters_at,
      pinch_at,
      crosses,
      lost
    };
    Reason reason = none;
    int vertex = -1;  // where, for enters_at and pinch_at
  };
  // The walk of free_space_triangulation.cpp's why_blocked; `from` is where a lies.
  Blocked walk(const IntegerPoint& a, const Location& from, const IntegerPoint& b) const;
  bool segment_free(const IntegerPoint& a, const Location& from, const IntegerPoint& b) const {
    return walk(a, from, b).reason == Blocked::none;
  }
  // nullopt when a-b is a valid motion, else why not, in words.
  std::optional<std::string> why_blocked(const IntegerPoint& a, const Location& from, const IntegerPoint& b) const;
  // The same for a polyline (locations of its points, or outside to have them located), with the
  // pinch rule at its turning points.
  std::optional<std::string> why_path_blocked(const std::vector<IntegerPoint>& path,
                                              const std::vector<Location>& where) const;
  // The same verdict without words or allocation (for the hot path; why_path_blocked explains).
  bool path_free(const std::vector<IntegerPoint>& path, const std::vector<Location>& where) const;

  std::size_t triangle_count() const { return triangles_.size(); }
  std::size_t memory_bytes() const;

 private:
  struct Triangle {
    int vertex[3];
    int neighbour[3];
    std::uint8_t constrained;  // bit i: edge i
    bool free;
    int component;
    bool is_constrained(int i) const { return (constrained >> i) & 1; }
  };
  using WedgeEdge = Parts::WedgeEdge;
  IntegerTriangulation() = default;

  void report(int vertex, std::vector<int>& out, Scratch& scratch) const;
  void begin(Scratch& scratch) const;
  void cross(const IntegerPoint& apex, int triangle, int edge, const IntegerPoint& right, const IntegerPoint& left,
             Scratch& scratch) const;
  void expand(const IntegerPoint& apex, std::vector<int>& out, Scratch& scratch) const;
  void expand_from(const IntegerPoint& apex, int triangle, std::vector<int>& out, Scratch& scratch) const;
  template <typename Visit>
  void for_each_triangle_at(const Location& where, Visit visit) const;
  bool in_closed_triangle(int triangle, const IntegerPoint& q) const;
  Location locate_from(int triangle, const IntegerPoint& p) const;

  std::size_t space_vertices_ = 0;
  std::vector<IntegerPoint> points_;
  std::vector<Triangle> triangles_;
  std::vector<std::size_t> fan_begin_;  // triangles around vertex v: fan_[fan_begin_[v] .. fan_begin_[v+1])
  std::vector<int> fan_;
  std::vector<std::size_t> wedge_begin_;
  std::vector<WedgeEdge> wedges_;
  // Point location: a bucket grid over the points' box, each bucket a triangle near its centre
  // from which a walk starts.
  IntegerPoint low_, high_;
  std::int64_t bucket_size_ = 1;
  int buckets_x_ = 0, buckets_y_ = 0;
  std::vector<int> bucket_triangle_;
};

}  // namespace polyplan::detail
