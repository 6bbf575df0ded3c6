#pragma once
// Worlds without bounds have an unbounded free space. The planners that cut the free space into
// cells (the triangulation of the visibility graph, the trapezoids) close it with a frame: a box
// holding every boundary vertex of the free space and the points they are asked about strictly
// inside. Between the obstacles and the frame the free space is a connected ring, so the frame
// changes no answer for points inside it; a planner asked about a point outside frames anew.
// Include only from .cpp files (CGAL).
#include <polyplan/geometry/detail/cspace_impl.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace polyplan::detail {

// The bounding box of the free space's vertices and `inside`, grown on every side by twice its
// width plus height, plus 1: shortest paths stay inside the box, and the ring between box and frame
// is wider than any point inside the box can be far from an obstacle, so the frame lowers no
// maximum clearance between such points.
inline Bounds free_space_frame(const CSpace::Impl& cspace, const std::vector<ExactPoint>& inside) {
  std::vector<ExactPoint> points = inside;
  const auto& arrangement = cspace.free_set.arrangement();
  for (auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v)
    points.push_back(to_exact(v->point()));
  if (points.empty()) points.push_back({0, 0});
  Bounds box{points[0].x, points[0].y, points[0].x, points[0].y};
  for (const ExactPoint& p : points) {
    box.xmin = std::min(box.xmin, p.x);
    box.ymin = std::min(box.ymin, p.y);
    box.xmax = std::max(box.xmax, p.x);
    box.ymax = std::max(box.ymax, p.y);
  }
  const Rational margin = 2 * ((box.xmax - box.xmin) + (box.ymax - box.ymin)) + 1;
  return {box.xmin - margin, box.ymin - margin, box.xmax + margin, box.ymax + margin};
}

// The free space as the planners that cut it into cells take it: as it is with bounds, cut by its
// frame without (the frame is returned, to tell the points inside it).
struct FramedFreeSpace {
  CSpace::Impl::PolygonSet free_set;
  std::optional<Bounds> frame;
};
inline FramedFreeSpace framed_free_space(const CSpace::Impl& cspace, const std::vector<ExactPoint>& inside) {
  FramedFreeSpace framed{cspace.free_set, std::nullopt};
  if (framed.free_set.arrangement().unbounded_face()->contained()) {
    framed.frame = free_space_frame(cspace, inside);
    framed.free_set.intersection(box_polygon(*framed.frame));
  }
  return framed;
}

inline bool strictly_inside(const Bounds& box, const ExactPoint& p) {
  return box.xmin < p.x && p.x < box.xmax && box.ymin < p.y && p.y < box.ymax;
}

}  // namespace polyplan::detail
