#include <polyplan/geometry/world_validation.hpp>

#include <polyplan/geometry/detail/cgal_types.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/box_intersection_d.h>

#include <optional>
#include <utility>

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

// A bounding box with an index (an edge's or a hole's), for CGAL's box intersection.
using IndexedBox =
    CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

// The boxes of a polygon's edges, edge i carrying the index first + i.
std::vector<IndexedBox> edge_boxes(const Polygon& polygon, std::size_t first = 0) {
  std::vector<IndexedBox> boxes;
  boxes.reserve(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i)
    boxes.emplace_back(polygon.edge(static_cast<int>(i)).bbox(), first + i);
  return boxes;
}

// Whether edges i and j of a polygon meet other than adjacent edges do (in their shared vertex).
bool edges_conflict(const Polygon& polygon, std::size_t i, std::size_t j, std::string* how) {
  const std::size_t n = polygon.size();
  if (i > j) std::swap(i, j);
  const Segment a = polygon.edge(static_cast<int>(i)), b = polygon.edge(static_cast<int>(j));
  const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
  if (!adjacent) {
    if (!CGAL::do_intersect(a, b)) return false;
    *how = edge_text(polygon, i) + " crosses " + edge_text(polygon, j);
    return true;
  }
  if (!CGAL::collinear(a.source(), a.target(), b.source()) || !CGAL::collinear(a.source(), a.target(), b.target()))
    return false;
  // Adjacent edges meet in their shared vertex only, unless they fold back over each other.
  const bool consecutive = j == i + 1;
  const Point& shared = consecutive ? a.target() : a.source();
  const Point& a_far = consecutive ? a.source() : a.target();
  const Point& b_far = consecutive ? b.target() : b.source();
  if (CGAL::collinear_are_ordered_along_line(a_far, shared, b_far)) return false;
  *how = edge_text(polygon, i) + " folds back over " + edge_text(polygon, j);
  return true;
}

// Names two edges that cross (or overlap): is_simple() (a sweep) only says that some do. The
// candidates are the pairs of edges whose bounding boxes meet (CGAL's box intersection, in
// O(n log² n + pairs)), not all n² pairs: a 20,000-vertex polygon took 27 s that way.
std::string crossing_edges(const Polygon& polygon) {
  std::vector<IndexedBox> boxes = edge_boxes(polygon);
  struct Found {};  // leaves the box search at the first conflict
  std::string how;
  try {
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const IndexedBox& a, const IndexedBox& b) {
      if (edges_conflict(polygon, a.handle(), b.handle(), &how)) throw Found{};
    });
  } catch (const Found&) {
    return how;
  }
  return "edges cross";
}

// Whether a hole shares a boundary segment (of positive length) with its outer boundary. Then
// the obstacle has zero width along it, and CGAL's Polygon_set keeps the hole filled (measured:
// a point inside such a hole was located as blocked). A hole may touch its outer boundary at
// points. Candidates are the pairs of edges whose bounding boxes meet.
bool shares_a_segment(const Polygon& outer, const Polygon& hole) {
  std::vector<IndexedBox> outer_boxes = edge_boxes(outer), hole_boxes = edge_boxes(hole, outer.size());
  bool shared = false;
  CGAL::box_intersection_d(
      outer_boxes.begin(), outer_boxes.end(), hole_boxes.begin(), hole_boxes.end(),
      [&](const IndexedBox& a, const IndexedBox& b) {
        if (shared) return;
        const Segment e = outer.edge(static_cast<int>(a.handle())),
                      f = hole.edge(static_cast<int>(b.handle() - outer.size()));
        if (!CGAL::collinear(e.source(), e.target(), f.source()) ||
            !CGAL::collinear(e.source(), e.target(), f.target()))
          return;
        // Collinear: they share a segment iff the later of their lower ends comes before the earlier
        // of their upper ends (in xy order along the line).
        auto lower = [](const Segment& g) {
          return CGAL::compare_xy(g.source(), g.target()) == CGAL::SMALLER ? g.source() : g.target();
        };
        auto upper = [](const Segment& g) {
          return CGAL::compare_xy(g.source(), g.target()) == CGAL::SMALLER ? g.target() : g.source();
        };
        const Point lo = CGAL::compare_xy(lower(e), lower(f)) == CGAL::LARGER ? lower(e) : lower(f);
        const Point hi = CGAL::compare_xy(upper(e), upper(f)) == CGAL::SMALLER ? upper(e) : upper(f);
        shared = CGAL::compare_xy(lo, hi) == CGAL::SMALLER;
      });
  return shared;
}

// Names two holes of an obstacle whose interiors overlap (one inside the other, or crossing):
// the obstacle they describe would be ambiguous, and CGAL's Boolean operations answer
// inconsistently on it. Holes may touch each other (at points or along edges). Candidates are
// the pairs with meeting bounding boxes; do_intersect on two polygons is regularized (interiors).
std::optional<std::pair<std::size_t, std::size_t>> overlapping_holes(const std::vector<Polygon>& holes) {
  std::vector<IndexedBox> boxes;
  for (std::size_t h = 0; h < holes.size(); ++h) boxes.emplace_back(holes[h].bbox(), h);
  std::optional<std::pair<std::size_t, std::size_t>> found;
  struct Found {};
  try {
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const IndexedBox& a, const IndexedBox& b) {
      if (CGAL::do_intersect(holes[a.handle()], holes[b.handle()])) {
        found = std::minmax(a.handle(), b.handle());
        throw Found{};
      }
    });
  } catch (const Found&) {
  }
  return found;
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

// An obstacle's outer boundary and holes (oriented on success), named `name` in messages.
void check_obstacle(const World& world, PolygonWithHoles& obstacle, const std::string& name) {
  const Polygon outer = check_ring(world, obstacle.outer, name, CGAL::COUNTERCLOCKWISE);
  std::vector<Polygon> holes_ccw;
  for (std::size_t h = 0; h < obstacle.holes.size(); ++h) {
    const std::string hole_name = name + " hole " + std::to_string(h);
    Polygon hole_ccw = check_ring(world, obstacle.holes[h], hole_name, CGAL::CLOCKWISE);
    hole_ccw.reverse_orientation();
    // Regularized: a hole may touch its outer boundary, but no part of it may lie outside.
    std::vector<PolygonH> outside;
    CGAL::difference(hole_ccw, outer, std::back_inserter(outside));
    if (!outside.empty()) fail(world, hole_name, "not inside the outer boundary of " + name);
    if (shares_a_segment(outer, hole_ccw))
      fail(world, hole_name,
           "shares a boundary segment with the outer boundary of " + name +
               " (zero width there: make the hole a notch of the outer boundary instead)");
    holes_ccw.push_back(std::move(hole_ccw));
  }
  if (const auto pair = overlapping_holes(holes_ccw))
    fail(world, name + " hole " + std::to_string(pair->second),
         "overlaps hole " + std::to_string(pair->first) + " (holes may touch but not overlap or nest)");
}

// The changes: listed by after_moves, an added obstacle checked as the world's are, a removed
// one among those that exist at that moment (the world's, then the added ones) and not gone yet.
void check_changes(World& world) {
  std::vector<bool> gone(world.obstacles.size(), false);
  for (std::size_t i = 0; i < world.changes.size(); ++i) {
    WorldChange& change = world.changes[i];
    if (i > 0 && change.after_moves < world.changes[i - 1].after_moves)
      fail(world, change.name + ".after_moves",
           std::to_string(change.after_moves) + " after " + world.changes[i - 1].name + "'s " +
               std::to_string(world.changes[i - 1].after_moves) + ": list the changes in the order they happen");
    if (change.added) {
      check_obstacle(world, *change.added, change.name + ".add_obstacle");
      gone.push_back(false);
    }
    if (change.removed) {
      const std::size_t k = *change.removed;
      if (k >= gone.size())
        fail(world, change.name + ".remove_obstacle",
             std::to_string(k) + ": there are " + std::to_string(gone.size()) +
                 " obstacles at that moment (numbered from 0: the world's, then those the changes before added)");
      if (gone[k])
        fail(world, change.name + ".remove_obstacle",
             "obstacle " + std::to_string(k) + " was removed by an earlier change");
      gone[k] = true;
    }
  }
}

}  // namespace

void validate_world(World& world) {
  if (world.bounds) {
    const Bounds& b = *world.bounds;
    if (!(b.xmin < b.xmax) || !(b.ymin < b.ymax))
      fail(world, "bounds",
           "empty or inverted: [" + to_string(b.xmin) + ", " + to_string(b.ymin) + ", " + to_string(b.xmax) + ", " +
               to_string(b.ymax) + "] needs xmin < xmax and ymin < ymax");
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    check_obstacle(world, world.obstacles[i], world.obstacle_names[i]);
  for (std::size_t i = 0; i < world.robot.parts.size(); ++i)
    check_ring(world, world.robot.parts[i], "robot.parts[" + std::to_string(i) + "]", CGAL::COUNTERCLOCKWISE);
  check_round_features(world);
  check_changes(world);
}

}  // namespace polyplan
