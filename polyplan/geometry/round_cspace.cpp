// The cores and radii of round_cspace.hpp's table. A polygon robot's Minkowski sums come from the
// polygon world's C-space (geometry/cspace.hpp), which joins them; the walls' sums are joined with
// them by a second C-space of a point robot whose obstacles are those sums.
#include <polyplan/geometry/round_cspace.hpp>

#include <polyplan/geometry/cspace.hpp>
#include <polyplan/geometry/detail/round_rules.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <optional>
#include <utility>

namespace polyplan {
namespace {

using Kind = RoundCore::Kind;

RoundCore point_core(const Disc& disc, const Rational& grown_by, std::string name) {
  return {Kind::point, {disc.center}, {}, disc.radius + grown_by, std::move(name)};
}

RoundCore polygon_core(const PolygonWithHoles& polygon, const Rational& radius, std::string name) {
  std::vector<Ring> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  return {Kind::polygon, {}, std::move(rings), radius, std::move(name)};
}

std::string disc_name(std::size_t i) { return "discs[" + std::to_string(i) + "]"; }
std::string wall_name(std::size_t i) { return "walls[" + std::to_string(i) + "]"; }

// A point or disc robot of radius r: the world's things grown by r.
RoundCSpace round_robot_cspace(const World& world) {
  const Rational r = world.robot.disc.value_or(0);
  RoundCSpace space;
  space.robot = world.robot.disc ? RoundCSpace::Robot::disc : RoundCSpace::Robot::point;
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    space.obstacles.push_back(polygon_core(world.obstacles[i], r, world.obstacle_names[i]));
  for (std::size_t i = 0; i < world.discs.size(); ++i)
    space.obstacles.push_back(point_core(world.discs[i], r, disc_name(i)));
  for (std::size_t i = 0; i < world.walls.size(); ++i)
    space.obstacles.push_back({Kind::wall, world.walls[i], {}, r, wall_name(i)});
  if (world.bounds) {
    const Bounds& b = *world.bounds;
    space.box = Bounds{b.xmin + r, b.ymin + r, b.xmax - r, b.ymax - r};
  }
  if (world.disc_bounds) space.disc = Disc{world.disc_bounds->center, world.disc_bounds->radius - r};
  return space;
}

Ring reflected(const Ring& part) {  // −R: a half turn, so still counter-clockwise
  Ring out;
  for (const ExactPoint& p : part) out.push_back({-p.x, -p.y});
  return out;
}

Ring translated(const Ring& ring, const ExactPoint& by) {
  Ring out;
  for (const ExactPoint& p : ring) out.push_back({p.x + by.x, p.y + by.y});
  return out;
}

// A wall's segment a→b swept by −R: −R at both ends and the parallelogram each edge of −R sweeps
// (their union is the sum: a point of it outside both ends' copies has the segment cross −R's
// boundary). Parallelograms of edges parallel to the wall have no area and are left out.
void add_swept_segment(const ExactPoint& a, const ExactPoint& b, const Ring& minus_part, std::vector<Ring>& out) {
  out.push_back(translated(minus_part, a));
  out.push_back(translated(minus_part, b));
  for (std::size_t k = 0; k < minus_part.size(); ++k) {
    const ExactPoint& u = minus_part[k];
    const ExactPoint& v = minus_part[(k + 1) % minus_part.size()];
    Ring piece{{a.x + u.x, a.y + u.y}, {a.x + v.x, a.y + v.y}, {b.x + v.x, b.y + v.y}, {b.x + u.x, b.y + u.y}};
    const Rational twice_area = (v.x - u.x) * (b.y - a.y) - (v.y - u.y) * (b.x - a.x);
    if (twice_area == 0) continue;
    if (twice_area < 0) std::reverse(piece.begin(), piece.end());
    out.push_back(std::move(piece));
  }
}

// Whether p lies in the closed polygon.
bool holds(const PolygonWithHoles& polygon, const ExactPoint& p) {
  using P = round_rules::P<Rational>;
  round_rules::Rings<Rational> rings;
  for (const Ring& ring : polygon_core(polygon, Rational(0), "").rings) {
    std::vector<P>& out = rings.emplace_back();
    for (const ExactPoint& v : ring) out.push_back({v.x, v.y});
  }
  return round_rules::side_of_polygon(rings, P{p.x, p.y}) >= 0;
}

// The names of the things whose C-obstacles a joined solid holds: each thing is known by one point
// of its C-obstacle (a vertex of it minus a vertex of the robot).
std::string solid_name(const PolygonWithHoles& solid, const std::vector<std::pair<ExactPoint, std::string>>& marks) {
  std::string name;
  for (const auto& [point, thing] : marks)
    if (holds(solid, point) && name.find(thing) == std::string::npos) name += (name.empty() ? "" : " + ") + thing;
  return name.empty() ? "a C-obstacle" : name;
}

// A translating polygon robot R: the polygons' and walls' sums with −R joined (radius 0), and each
// disc as its centre minus each part of R, grown by the disc's radius.
RoundCSpace polygon_robot_cspace(const World& world) {
  if (world.disc_bounds)
    throw InputError(world.source +
                     ": bounds: a polygon robot in disc bounds (where it fits is an intersection of discs): not "
                     "supported; box bounds are, or a point or disc robot");
  World sums;
  sums.source = world.source;
  sums.bounds = world.bounds;
  sums.obstacles = world.obstacles;
  sums.obstacle_names = world.obstacle_names;
  sums.robot.parts = world.robot.parts;
  const CSpace polygon_cspace(sums);
  RoundCSpace space;
  space.robot = RoundCSpace::Robot::polygon;
  space.box = polygon_cspace.reference_box();

  const ExactPoint robot_vertex = world.robot.parts.front().front();
  const auto mark = [&](const ExactPoint& p, const std::string& thing) {
    return std::pair{ExactPoint{p.x - robot_vertex.x, p.y - robot_vertex.y}, thing};
  };
  std::vector<std::pair<ExactPoint, std::string>> marks;
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    marks.push_back(mark(world.obstacles[i].outer.front(), world.obstacle_names[i]));
  World joined;  // a point robot among the sums, whose solids join them
  joined.source = world.source;
  for (const PolygonWithHoles& sum : polygon_cspace.cobstacles()) {
    joined.obstacles.push_back(sum);
    joined.obstacle_names.push_back("a C-obstacle");
  }
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    marks.push_back(mark(world.walls[i].front(), wall_name(i)));
    std::vector<Ring> pieces;
    for (const Ring& part : world.robot.parts)
      for (std::size_t k = 0; k + 1 < world.walls[i].size(); ++k)
        add_swept_segment(world.walls[i][k], world.walls[i][k + 1], reflected(part), pieces);
    for (Ring& piece : pieces) {
      joined.obstacles.push_back({std::move(piece), {}});
      joined.obstacle_names.push_back(wall_name(i));
    }
  }
  std::optional<CSpace> joined_cspace;
  if (!world.walls.empty()) joined_cspace.emplace(joined);
  for (const PolygonWithHoles& solid : joined_cspace ? joined_cspace->solids() : polygon_cspace.cobstacles())
    space.obstacles.push_back(polygon_core(solid, Rational(0), solid_name(solid, marks)));
  for (std::size_t i = 0; i < world.discs.size(); ++i)
    for (const Ring& part : world.robot.parts)
      space.obstacles.push_back(
          polygon_core({translated(reflected(part), world.discs[i].center), {}}, world.discs[i].radius, disc_name(i)));
  return space;
}

}  // namespace

bool straight_edged(const RoundCSpace& space) {
  return !space.disc && std::all_of(space.obstacles.begin(), space.obstacles.end(),
                                    [](const RoundCore& core) { return core.radius == 0; });
}

RoundCSpace round_cspace(const World& world) {
  return world.robot.parts.empty() ? round_robot_cspace(world) : polygon_robot_cspace(world);
}

}  // namespace polyplan
