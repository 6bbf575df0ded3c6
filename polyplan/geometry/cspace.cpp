#include <polyplan/geometry/cspace.hpp>

#include <polyplan/geometry/detail/cspace_impl.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <boost/variant/get.hpp>

#include <tuple>

namespace polyplan {
namespace {

using namespace detail;
using Impl = CSpace::Impl;

// The robot's extent in its frame: the box the reference point keeps so the robot stays inside
// the bounds is the bounds shrunk by it.
Bounds reference_box_of(const Bounds& bounds, const Robot& robot) {
  Rational minx = 0, miny = 0, maxx = 0, maxy = 0;
  bool first = true;
  for (const Ring& part : robot.parts)
    for (const ExactPoint& p : part) {
      if (first || p.x < minx) minx = p.x;
      if (first || p.y < miny) miny = p.y;
      if (first || p.x > maxx) maxx = p.x;
      if (first || p.y > maxy) maxy = p.y;
      first = false;
    }
  return {bounds.xmin - minx, bounds.ymin - miny, bounds.xmax - maxx, bounds.ymax - maxy};
}

Polygon reflected(const Ring& part) {
  Polygon polygon;
  for (const ExactPoint& p : part) polygon.push_back(Point(to_ft(-p.x), to_ft(-p.y)));
  return polygon;  // a point reflection keeps the orientation
}

// Exact shoelace area of a closed cycle (valid for the weakly simple cycles of arrangements).
Rational signed_area(const Ring& ring) {
  Rational twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

Ring ring_of(Impl::Arrangement::Ccb_halfedge_const_circulator first) {
  std::vector<Point> points;
  auto edge = first;
  do {
    points.push_back(edge->source()->point());
  } while (++edge != first);
  return without_straight_vertices(points);
}

void build(Impl& impl) {
  const World& world = impl.world;

  std::vector<PolygonH> obstacles;
  obstacles.reserve(world.obstacles.size());
  for (const auto& o : world.obstacles) obstacles.push_back(to_polygon(o));
  Impl::PolygonSet solids;
  solids.join(obstacles.begin(), obstacles.end());  // one aggregated union, not n joins
  std::vector<PolygonH> solid_polygons;
  solids.polygons_with_holes(std::back_inserter(solid_polygons));
  for (const auto& s : solid_polygons) impl.solids.push_back(to_exact(s));

  Impl::PolygonSet cobstacle_set;
  if (world.robot.is_point()) {
    cobstacle_set = solids;
  } else {
    std::vector<Polygon> parts;
    for (const Ring& part : world.robot.parts) parts.push_back(reflected(part));
    std::vector<PolygonH> sums;
    for (const auto& solid : solid_polygons)
      for (const auto& part : parts) sums.push_back(CGAL::minkowski_sum_2(solid, part));
    cobstacle_set.join(sums.begin(), sums.end());
  }
  std::vector<PolygonH> cobstacle_polygons;
  cobstacle_set.polygons_with_holes(std::back_inserter(cobstacle_polygons));
  for (const auto& c : cobstacle_polygons) impl.cobstacles.push_back(to_exact(c));

  if (world.bounds) {
    impl.reference_box = reference_box_of(*world.bounds, world.robot);
    const Bounds& box = *impl.reference_box;
    // A box of zero width has no interior: nothing is free.
    if (box.xmin < box.xmax && box.ymin < box.ymax) {
      impl.free_set = Impl::PolygonSet(box_polygon(box));
      impl.free_set.difference(cobstacle_set);
    }
  } else {
    impl.free_set = cobstacle_set;
    impl.free_set.complement();
  }

  const Impl::Arrangement& arr = impl.free_set.arrangement();
  for (auto face = arr.faces_begin(); face != arr.faces_end(); ++face) {
    if (!face->contained()) continue;
    FreeComponent component;
    if (face->has_outer_ccb()) component.outer = ring_of(face->outer_ccb());
    for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole)
      component.holes.push_back(ring_of(*hole));
    if (!face->is_unbounded()) {
      Rational area = signed_area(component.outer);
      for (const Ring& hole : component.holes) area += signed_area(hole);  // holes run clockwise
      component.area = area;
    }
    impl.component_of_face.emplace(&*face, impl.free_components.size());
    impl.free_components.push_back(std::move(component));
  }
  impl.point_location = std::make_unique<Impl::PointLocation>(impl.free_set.arrangement());
}

// Winding number of a closed ring around p (exact; valid for the weakly simple rings that
// regularized operations produce, where CGAL's Polygon_2 predicates require simple ones).
int winding_number(const Ring& ring, const ExactPoint& p) {
  int winding = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[(i + 1) % ring.size()];
    const Rational cross = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
    if (a.y <= p.y && p.y < b.y && cross > 0) ++winding;
    if (b.y <= p.y && p.y < a.y && cross < 0) --winding;
  }
  return winding;
}

// p lies in the interior of the polygon, not on its boundary and not in (or on) a hole.
bool strictly_inside(const PolygonWithHoles& polygon, const ExactPoint& p) {
  auto on_boundary = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const ExactPoint& a = ring[i];
      const ExactPoint& b = ring[(i + 1) % ring.size()];
      if ((b.x - a.x) * (p.y - a.y) == (p.x - a.x) * (b.y - a.y) && std::min(a.x, b.x) <= p.x &&
          p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
        return true;
    }
    return false;
  };
  if (winding_number(polygon.outer, p) == 0 || on_boundary(polygon.outer)) return false;
  for (const Ring& hole : polygon.holes)
    if (winding_number(hole, p) != 0 || on_boundary(hole)) return false;
  return true;
}

bool inside_closed_box(const Bounds& b, const ExactPoint& p) {
  return b.xmin <= p.x && p.x <= b.xmax && b.ymin <= p.y && p.y <= b.ymax;
}

}  // namespace

CSpace::CSpace(const World& world) : impl_(std::make_unique<Impl>()) {
  // The planners' door refuses such a world first, naming the planner; this keeps every other
  // road (a command, a picture) from planning straight through what a polygon set cannot hold.
  refuse_round_features(world, "the polygon C-space");
  impl_->world = world;
  build(*impl_);
}
CSpace::~CSpace() = default;
CSpace::CSpace(CSpace&&) noexcept = default;
CSpace& CSpace::operator=(CSpace&&) noexcept = default;

const World& CSpace::world() const { return impl_->world; }
const std::vector<PolygonWithHoles>& CSpace::solids() const { return impl_->solids; }
const std::vector<PolygonWithHoles>& CSpace::cobstacles() const { return impl_->cobstacles; }
const std::vector<FreeComponent>& CSpace::free_components() const { return impl_->free_components; }
const std::optional<Bounds>& CSpace::reference_box() const { return impl_->reference_box; }

Location CSpace::locate(const ExactPoint& p) const {
  const Impl& impl = *impl_;
  Location result{Location::Kind::blocked, {}};
  auto add = [&](Impl::Face face) {
    if (auto c = impl.component(face))
      if (std::find(result.components.begin(), result.components.end(), *c) == result.components.end())
        result.components.push_back(*c);
  };
  auto located = impl.point_location->locate(to_point(p));
  if (auto* face = boost::get<Impl::Face>(&located)) {
    add(*face);
    if (!result.components.empty()) result.kind = Location::Kind::free;
  } else if (auto* edge = boost::get<Impl::Halfedge>(&located)) {
    add((*edge)->face());
    add((*edge)->twin()->face());
    result.kind = Location::Kind::contact;
  } else if (auto* vertex = boost::get<Impl::Vertex>(&located)) {
    if (!(*vertex)->is_isolated()) {
      auto edge = (*vertex)->incident_halfedges(), first = edge;
      do add(edge->face());
      while (++edge != first);
    }
    if (!result.components.empty()) result.kind = Location::Kind::contact;
  }
  return result;
}

std::optional<std::string> CSpace::collision_at(const ExactPoint& p) const {
  const Impl& impl = *impl_;
  if (locate(p).kind != Location::Kind::blocked) return std::nullopt;
  if (impl.reference_box && !inside_closed_box(*impl.reference_box, p))
    return std::string(impl.world.robot.is_point() ? "it is outside the bounds" : "the robot leaves the bounds");
  for (std::size_t i = 0; i < impl.world.obstacles.size(); ++i) {
    bool hit = false;
    if (impl.world.robot.is_point()) {
      hit = strictly_inside(impl.world.obstacles[i], p);
    } else {
      const PolygonH obstacle = to_polygon(impl.world.obstacles[i]);
      for (const Ring& part : impl.world.robot.parts) {
        Polygon placed;
        for (const ExactPoint& v : part) placed.push_back(Point(to_ft(v.x + p.x), to_ft(v.y + p.y)));
        hit = hit || CGAL::do_intersect(placed, obstacle);  // interiors only: contact is allowed
      }
    }
    if (hit)
      return (impl.world.robot.is_point() ? "it is inside " : "the robot overlaps ") + impl.world.obstacle_names[i];
  }
  return std::string("the robot fits there only exactly: the free space has zero width (obstacles touch around it)");
}

std::optional<std::string> CSpace::query_not_free(const Query& query) const {
  for (const auto& [what, point] : {std::pair{"start", &query.start}, std::pair{"goal", &query.goal}})
    if (auto why = collision_at(*point))
      return std::string("the ") + what + " " + to_string(*point) + " is not free: " + *why;
  return std::nullopt;
}

void CSpace::require_free_queries() const {
  // A pose turned away from 0° is not a configuration of this C-space (the robot as drawn).
  for (const Query& q : impl_->world.queries)
    for (const auto& [what, point, theta] :
         {std::tuple{"start", &q.start, &q.start_theta}, std::tuple{"goal", &q.goal, &q.goal_theta}})
      if (auto why = turned(*theta) ? std::nullopt : collision_at(*point))
        throw InputError(impl_->world.source + ": " +
                         (q.name == "start/goal" ? std::string(what) : q.name + "." + what) + " " + to_text(*point) +
                         ": not free: " + *why);
}

}  // namespace polyplan
