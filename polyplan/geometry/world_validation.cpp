#include <polyplan/geometry/world_validation.hpp>

#include <polyplan/internal/cgal_types.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <CGAL/Boolean_set_operations_2.h>

namespace polyplan {
namespace {

using namespace detail;

[[noreturn]] void fail(const World& world, const std::string& object, const std::string& problem) {
  throw InputError(world.source + ": " + object + ": " + problem);
}

// Consecutive repeated vertices (and a closing copy of the first) carry no shape: drop them.
void drop_repeated_vertices(Ring& ring) {
  Ring kept;
  for (const auto& p : ring)
    if (kept.empty() || !(kept.back() == p)) kept.push_back(p);
  while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  ring = std::move(kept);
}

std::string edge_text(const Polygon& polygon, std::size_t i) {
  const Segment e = polygon.edge(static_cast<int>(i));
  return "edge " + std::to_string(i) + " " + to_text(e.source()) + "-" + to_text(e.target());
}

// Names two edges that cross (or overlap): is_simple() only says that some do.
std::string crossing_edges(const Polygon& polygon) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Segment a = polygon.edge(static_cast<int>(i)), b = polygon.edge(static_cast<int>(j));
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent) {
        if (CGAL::do_intersect(a, b)) return edge_text(polygon, i) + " crosses " + edge_text(polygon, j);
      } else if (CGAL::collinear(a.source(), a.target(), b.source()) &&
                 CGAL::collinear(a.source(), a.target(), b.target())) {
        // Adjacent edges meet in their shared vertex only, unless they fold back over each other.
        const Point& shared = j == i + 1 ? a.target() : a.source();
        const Point& a_far = j == i + 1 ? a.source() : a.target();
        const Point& b_far = j == i + 1 ? b.target() : b.source();
        if (!CGAL::collinear_are_ordered_along_line(a_far, shared, b_far))
          return edge_text(polygon, i) + " folds back over " + edge_text(polygon, j);
      }
    }
  return "edges cross";
}

// Validates one ring and orients it counter-clockwise (or clockwise for holes).
Polygon check_ring(const World& world, Ring& ring, const std::string& object, CGAL::Orientation wanted) {
  drop_repeated_vertices(ring);
  if (ring.size() < 3) fail(world, object, "fewer than 3 distinct vertices");
  Polygon polygon = to_polygon(ring);
  bool all_collinear = true;
  for (std::size_t i = 2; i < polygon.size() && all_collinear; ++i)
    all_collinear = CGAL::collinear(polygon[0], polygon[1], polygon[static_cast<int>(i)]);
  if (all_collinear) fail(world, object, "zero area (all vertices on one line)");
  if (!polygon.is_simple()) fail(world, object, "self-intersecting: " + crossing_edges(polygon));
  if (polygon.orientation() != wanted) {
    polygon.reverse_orientation();
    std::reverse(ring.begin(), ring.end());
  }
  return polygon;
}

}  // namespace

void validate_world(World& world) {
  if (world.bounds) {
    const Bounds& b = *world.bounds;
    if (!(b.xmin < b.xmax) || !(b.ymin < b.ymax))
      fail(world, "bounds", "empty or inverted: [" + to_string(b.xmin) + ", " + to_string(b.ymin) + ", " +
                                to_string(b.xmax) + ", " + to_string(b.ymax) + "] needs xmin < xmax and ymin < ymax");
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    PolygonWithHoles& obstacle = world.obstacles[i];
    const std::string& name = world.obstacle_names[i];
    const Polygon outer = check_ring(world, obstacle.outer, name, CGAL::COUNTERCLOCKWISE);
    for (std::size_t h = 0; h < obstacle.holes.size(); ++h) {
      const std::string hole_name = name + " hole " + std::to_string(h);
      const Polygon hole = check_ring(world, obstacle.holes[h], hole_name, CGAL::CLOCKWISE);
      Polygon hole_ccw = hole;
      hole_ccw.reverse_orientation();
      // Regularized: a hole may touch its outer boundary, but no part of it may lie outside.
      std::vector<PolygonH> outside;
      CGAL::difference(hole_ccw, outer, std::back_inserter(outside));
      if (!outside.empty()) fail(world, hole_name, "not inside the outer boundary of " + name);
    }
  }
  for (std::size_t i = 0; i < world.robot.parts.size(); ++i)
    check_ring(world, world.robot.parts[i], "robot.parts[" + std::to_string(i) + "]", CGAL::COUNTERCLOCKWISE);
}

}  // namespace polyplan
