#pragma once
// The trapezoidal (vertical) decomposition of a translating robot's free space, exact: from every
// vertex of the free space's boundary a vertical wall goes up and one goes down, each as far as
// the first boundary point it meets, wherever it runs through free space. The walls cut the free
// space into trapezoids (triangles where a side shrinks to a point) whose corners are rational:
// a wall ends at a vertex or at the point of an edge with the vertex's x, both exact.
//
// Cells touch only across walls. A pinch vertex (two C-obstacles touching at a point) sends no
// wall through the contact, so the cells of its two free wedges share a point and no wall: they
// are never joined there — docs/design.md's semantics, where a path may touch a pinch point but not
// pass through it. A zero-width seam is inside the joined C-obstacles and makes no cell.
//
// Worlds without bounds have an unbounded free space: it is cut by a frame, a box that holds every
// C-obstacle and the points asked for strictly inside (the free space is connected around the
// obstacles, so the frame changes no answer between points inside it).
//
// Built with CGAL's `decompose` (a batched vertical ray shooting) and an overlay of the walls on
// the free-space arrangement; CGAL stays in the .cpp.
#include <polyplan/geometry/cspace.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace polyplan {

// A wall between two cells: the vertical segment lower–upper (lower.x == upper.x,
// lower.y < upper.y), cell `left` on its left, `right` on its right.
struct TrapezoidWall {
  std::size_t left = 0, right = 0;
  ExactPoint lower, upper;
};

// What a vertical sweep across the free space's boundary meets (the numbers a course asks for):
// each non-vertical boundary edge is inserted into the sweep line where the sweep reaches its left
// end and deleted at its right end; `most_crossed` is the largest number of edges that one
// vertical line crosses between events. Vertical edges never lie across a sweep line and are not
// counted. The bounds' (or the frame's) top and bottom edges are boundary edges like any other.
struct SweepCounts {
  std::size_t insertions = 0;
  std::size_t deletions = 0;
  std::size_t most_crossed = 0;
  std::size_t events() const { return insertions + deletions; }
};

class TrapezoidalDecomposition {
 public:
  // `cspace` must outlive the decomposition. Without bounds, the frame holds `inside` too.
  explicit TrapezoidalDecomposition(const CSpace& cspace, const std::vector<ExactPoint>& inside = {});
  ~TrapezoidalDecomposition();
  TrapezoidalDecomposition(TrapezoidalDecomposition&&) noexcept;
  TrapezoidalDecomposition& operator=(TrapezoidalDecomposition&&) noexcept;

  // Each cell's corners counterclockwise, without corners in the middle of a straight side (a
  // trapezoid has four, a triangle three). Convex.
  const std::vector<Ring>& cells() const;
  // Each cell's centroid (the centre of its area), exact; inside the open cell.
  const std::vector<ExactPoint>& centroids() const;
  const std::vector<TrapezoidWall>& walls() const;
  const SweepCounts& sweep() const;

  // The cells whose closure holds p: one inside a cell, two on a wall, all the cells around a
  // corner; on the boundary of the free space the cells on its free side. Empty when p is in a
  // C-obstacle or outside the frame.
  std::vector<std::size_t> cells_at(const ExactPoint& p) const;
  // Whether p is strictly inside the frame; always true in a world with bounds.
  bool in_frame(const ExactPoint& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polyplan
