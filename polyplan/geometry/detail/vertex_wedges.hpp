#pragma once
// The free wedges around a vertex of the free-space arrangement: the angular sectors between
// consecutive boundary edges that lie in free faces. A vertex with two or more free wedges is a
// pinch point (zero width); a free wedge wider than 180 degrees is a corner a taut path can bend
// around. Include only from .cpp files (CGAL).
#include <polyplan/geometry/detail/cgal_types.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace polyplan::detail {

class VertexWedges {
 public:
  using Direction = Kernel::Direction_2;

  VertexWedges() = default;

  // `incoming` circulates the arrangement halfedges that end at the vertex `at`.
  template <typename HalfedgeCirculator>
  VertexWedges(const Point& at, HalfedgeCirculator incoming) : at_(at) {
    auto edge = incoming;
    do {
      auto out = edge->twin();  // leaves the vertex; its face lies to its left
      edges_.push_back({Direction(out->target()->point() - at_), out->target()->point(), out->face()->contained()});
    } while (++edge != incoming);
    std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) { return a.direction < b.direction; });
  }

  std::size_t size() const { return edges_.size(); }
  const Point& point() const { return at_; }

  // Wedge k spans from edge k (included) counter-clockwise to edge k+1.
  bool is_free(std::size_t k) const { return edges_[k].free_on_left; }
  // The other end of edge k (edges sorted counter-clockwise from the positive x direction).
  const Point& far(std::size_t k) const { return edges_[k].far; }

  std::size_t free_wedges() const {
    return static_cast<std::size_t>(
        std::count_if(edges_.begin(), edges_.end(), [](const Edge& e) { return e.free_on_left; }));
  }

  // Two or more free wedges meet here: the free space has zero width at this point.
  bool is_pinch() const { return free_wedges() >= 2; }

  // Wedge k is wider than 180 degrees (a convex corner of the obstacles seen from the free side).
  bool is_reflex(std::size_t k) const {
    // A regularized arrangement has no antennas: every vertex has at least two edges, in
    // distinct directions, so the turn from edge k to edge k+1 tells the wedge's width.
    const std::size_t next = (k + 1) % edges_.size();
    return CGAL::orientation(at_, edges_[k].far, edges_[next].far) == CGAL::RIGHT_TURN;
  }

  // The free wedge that a motion leaving the vertex in direction d moves into; a direction along
  // an edge belongs to the free side of that edge. nullopt when d points into an obstacle.
  std::optional<std::size_t> wedge(const Direction& d) const {
    const std::size_t n = edges_.size();
    auto after = std::upper_bound(edges_.begin(), edges_.end(), d,
                                  [](const Direction& dir, const Edge& e) { return dir < e.direction; });
    std::size_t k = after == edges_.begin() ? n - 1 : static_cast<std::size_t>(after - edges_.begin()) - 1;
    if (edges_[k].direction == d && !edges_[k].free_on_left) k = (k + n - 1) % n;
    if (!edges_[k].free_on_left) return std::nullopt;
    return k;
  }

 private:
  struct Edge {
    Direction direction;
    Point far;  // the edge's other end, for orientation tests
    bool free_on_left;
  };
  Point at_;
  std::vector<Edge> edges_;
};

}  // namespace polyplan::detail
