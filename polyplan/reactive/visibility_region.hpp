#pragma once
// What a robot at a point of the free space sees: the exact visibility polygon of the point in
// the closure of the free space (CGAL's Triangular_expansion_visibility_2 on the free space's
// boundary cycles), its windows (the edges that are lines of sight, not boundary: each begins at a
// boundary vertex where the sight runs past an obstacle, TangentBug's discontinuity), and the
// polygon clipped to a sensor's range for pictures. CGAL stays in the .cpp.
#include <polyplan/reactive/boundary_walk.hpp>

#include <memory>
#include <utility>
#include <vector>

namespace polyplan::walk {

class VisibilityRegions {
 public:
  // Triangulates the boundary once. `boundary` must outlive this.
  explicit VisibilityRegions(const Boundary& boundary);
  ~VisibilityRegions();

  // The visibility polygon of x (free or on the boundary), counter-clockwise, exact. A world
  // without bounds is closed by a frame far round its obstacles: sight ends there.
  std::vector<Point> visible_from(const Point& x) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The windows of x's visibility polygon: (near end, far end) for each edge of it on a line through
// x that runs through the free space, not along the boundary. The near end is a boundary vertex.
std::vector<std::pair<Point, Point>> windows(const Boundary& boundary, const Point& x,
                                             const std::vector<Point>& region);

// The region seen within `range` of x (a disc's arcs as short chords): a picture's polygon, in
// rational copies of doubles. An infinite range returns the region.
std::vector<Point> within_range(const std::vector<Point>& region, const Point& x, double range);

}  // namespace polyplan::walk
