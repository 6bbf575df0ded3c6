#pragma once
// The generalized Voronoi diagram of the free space: the points at equal distance from two or more
// pieces of its boundary (the C-obstacles' and the walls' edges and corners), the roadmap of
// maximum clearance. Built with CGAL's segment Delaunay graph (Segment_Delaunay_graph_2, filtered
// exact predicates) over the boundary's edges, and kept where it runs through the open free space:
// without the edges that end on the boundary at a segment's own endpoint (the perpendicular
// between an edge and its corner) and without the parts inside the C-obstacles.
//
// Voronoi vertices are not rational in general (a circle tangent to three segments has an
// algebraic centre), so the diagram is computed and kept in doubles: the sites are the boundary's
// exact vertices rounded to double, the predicates on them exact, the vertices the nearest doubles
// CGAL constructs. Whatever a planner takes from it is converted to exact rationals (every double
// is one) and checked exactly against the C-space before it is returned.
//
// An edge is a straight piece (between two corners, between two edges, or between a corner and
// its own edge) or a parabolic arc (between a corner and another edge: the points as far from the
// corner, its focus, as from the edge's line, its directrix). Worlds without bounds are framed
// (geometry/detail/free_space_frame.hpp) far enough that the frame never lowers the clearance that a
// start or goal inside it can have.
#include <polyplan/geometry/clearance.hpp>
#include <polyplan/geometry/cspace.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace polyplan {

// A piece of the free space's boundary: a corner (a == b) or an edge a-b.
struct BoundarySite {
  Vec2 a, b;
  bool is_point() const { return a.x == b.x && a.y == b.y; }
};

// One edge of the diagram, from vertex `from` to vertex `to`, equidistant from two sites.
struct DiagramEdge {
  std::size_t from = 0, to = 0;
  std::size_t site_a = 0, site_b = 0;
  double clearance = 0;  // the smallest distance to the boundary along the edge
  double length = 0;     // along the curve
};

struct DiagramVertex {
  Vec2 at;
  double clearance = 0;  // the radius of the circle through its sites
};

// A point on an edge's curve, by a parameter that grows from the edge's `from` to its `to`:
// along a parabola the coordinate along its directrix, along a straight piece the fraction.
struct CurvePoint {
  std::size_t edge = 0;
  double parameter = 0;
};

class VoronoiDiagram {
 public:
  // `cspace` must outlive the diagram. Without bounds, the frame holds `inside` too.
  explicit VoronoiDiagram(const CSpace& cspace, const std::vector<ExactPoint>& inside = {});
  ~VoronoiDiagram();
  VoronoiDiagram(VoronoiDiagram&&) noexcept;
  VoronoiDiagram& operator=(VoronoiDiagram&&) noexcept;

  const std::vector<BoundarySite>& sites() const;
  const std::vector<DiagramVertex>& vertices() const;
  const std::vector<DiagramEdge>& edges() const;
  bool in_frame(const ExactPoint& p) const;

  bool is_parabolic(std::size_t edge) const;
  // The parameters of the edge's ends.
  double parameter_from(std::size_t edge) const;
  double parameter_to(std::size_t edge) const;
  Vec2 point(std::size_t edge, double parameter) const;
  // The smallest distance to the boundary along the edge between two parameters, and the arc's
  // length there.
  double clearance_between(std::size_t edge, double t1, double t2) const;
  double length_between(std::size_t edge, double t1, double t2) const;
  // For a parabolic edge, how far the chord between two parameters strays from the arc (its
  // sagitta); 0 for a straight edge.
  double sagitta(std::size_t edge, double t1, double t2) const;
  // The control point of the quadratic Bézier curve that is exactly the arc between two
  // parameters (the meeting point of its end tangents; the midpoint for a straight piece).
  Vec2 bezier_control(std::size_t edge, double t1, double t2) const;

  // Where a point of the free space meets the diagram when it moves straight away from its
  // nearest boundary point (its clearance grows all the way): that point on an edge. A point on
  // the boundary first steps off it into the free space, along a segment checked exactly
  // (`off_boundary`). nullopt when the point is blocked or no edge is met.
  struct Retraction {
    CurvePoint on;
    std::optional<Vec2> off_boundary;
    double clearance = 0;  // the point's own: its distance to the nearest boundary piece
  };
  std::optional<Retraction> retract(const ExactPoint& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
