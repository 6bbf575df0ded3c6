#include <polyplan/draw/world_svg.hpp>

#include <polyplan/draw/theme.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace polyplan {
namespace {

using Rings = std::vector<std::vector<svg::Point2>>;

std::vector<svg::Point2> ring(const Ring& r) {
  std::vector<svg::Point2> out;
  out.reserve(r.size());
  for (const ExactPoint& p : r) out.push_back(svg_point(p));
  return out;
}

Rings rings(const PolygonWithHoles& p) {
  Rings out;
  if (!p.outer.empty()) out.push_back(ring(p.outer));
  for (const Ring& h : p.holes) out.push_back(ring(h));
  return out;
}

std::vector<svg::Point2> box_ring(const svg::Box2& b) {
  return {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
}

svg::Box2 to_box(const Bounds& b) {
  return {to_double(b.xmin), to_double(b.ymin), to_double(b.xmax), to_double(b.ymax)};
}

using svg::filled;

const svg::Style& bounds_style() {
  static const svg::Style s = [] {
    svg::Style f;
    f.stroke = theme::bounds;
    f.stroke_px = 1.2;
    return f;
  }();
  return s;
}
const svg::Style& obstacle_style() {
  static const svg::Style s = filled(theme::obstacle_fill, 1.0, theme::obstacle_edge, 1.0);
  return s;
}
const svg::Style& robot_style() {
  static const svg::Style s = filled(theme::robot_fill, 0.18, theme::robot_edge, 1.5);
  return s;
}

std::vector<Ring> robot_placed_at(const Robot& robot, const ExactPoint& at) {
  std::vector<Ring> placed;
  for (const Ring& part : robot.parts) {
    Ring r;
    r.reserve(part.size());
    for (const ExactPoint& v : part) r.push_back({v.x + at.x, v.y + at.y});
    placed.push_back(std::move(r));
  }
  return placed;
}

// A circle's 96-gon: near enough for the box a picture shows.
std::vector<svg::Point2> circle_ring(const ExactPoint& center, const Rational& radius) {
  const svg::Point2 c = svg_point(center);
  const double r = to_double(radius);
  std::vector<svg::Point2> out;
  for (int i = 0; i < 96; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 96;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

const svg::Style& thin_wall_style() {
  static const svg::Style s = [] {
    svg::Style f;
    f.stroke = theme::obstacle_edge;
    f.stroke_px = 3.0;
    return f;
  }();
  return s;
}

void draw_obstacles(svg::Drawing& drawing, const World& world) {
  for (const PolygonWithHoles& o : world.obstacles) drawing.polygon(rings(o), obstacle_style());
  std::vector<svg::Circle2> discs;
  for (const Disc& d : world.discs) discs.push_back({svg_point(d.center), to_double(d.radius)});
  drawing.circles(discs, obstacle_style());
  if (!world.obstacles.empty() || !world.discs.empty())
    drawing.legend(world.obstacles.empty() ? "discs"
                   : world.discs.empty()   ? "obstacles"
                                           : "obstacles and discs",
                   obstacle_style());
  for (const Wall& wall : world.walls) drawing.polyline(ring(wall), thin_wall_style());
  if (!world.walls.empty()) drawing.legend("walls (zero thickness)", thin_wall_style(), svg::Swatch::line);
}

void draw_robot_at_start(svg::Drawing& drawing, const World& world) {
  if (world.robot.is_point() || world.queries.empty()) return;
  if (world.robot.disc)
    drawing.circles({{svg_point(world.queries.front().start), to_double(*world.robot.disc)}}, robot_style());
  for (const Ring& part : robot_placed_at(world.robot, world.queries.front().start)) {
    drawing.polygon({ring(part)}, robot_style());
  }
  drawing.legend("robot at start", robot_style());
}

// The box round what a world holds (its bounds, or else obstacles, discs, walls, `more`, the starts
// and goals and the robot at the first start), cut to twice the queries' extent round them.
svg::Box2 view_of(const World& world, const std::vector<PolygonWithHoles>& more) {
  if (world.bounds) return to_box(*world.bounds);
  if (world.disc_bounds) {
    const svg::Point2 c = svg_point(world.disc_bounds->center);
    const double r = to_double(world.disc_bounds->radius);
    return {c.x - r, c.y - r, c.x + r, c.y + r};
  }
  svg::BoxAround box;
  auto extend = [&](const ExactPoint& p) {
    const svg::Point2 q = svg_point(p);
    box.add(q.x, q.y);
  };
  // Holes lie inside their outer ring, so outer rings suffice.
  for (const auto* polygons : {&world.obstacles, &more})
    for (const PolygonWithHoles& o : *polygons)
      for (const ExactPoint& p : o.outer) extend(p);
  for (const Disc& d : world.discs)
    for (const svg::Point2& p : circle_ring(d.center, d.radius)) box.add(p.x, p.y);
  for (const Wall& wall : world.walls)
    for (const ExactPoint& p : wall) extend(p);
  svg::BoxAround around_queries;
  for (const Query& q : world.queries)
    for (const ExactPoint& p : {q.start, q.goal}) {
      extend(p);
      around_queries.add(svg_point(p).x, svg_point(p).y);
    }
  if (!world.queries.empty()) {
    for (const Ring& part : robot_placed_at(world.robot, world.queries.front().start))
      for (const ExactPoint& p : part) extend(p);
    if (world.robot.disc)
      for (const svg::Point2& p : circle_ring(world.queries.front().start, *world.robot.disc)) box.add(p.x, p.y);
  }
  const svg::Box2 all =
      box.box_or({0, 0, 1, 1});  // svg::Drawing widens a degenerate box (a single point, a flat row of points)
  if (world.queries.empty()) return all;
  // Obstacles reaching far beyond the queries (the course's planning problem set's endless wall) would shrink what
  // happens near them to a line: the view ends twice the queries' extent round them.
  const svg::Box2 q = around_queries.box_or(all);
  const double reach = 2 * std::max({q.xmax - q.xmin, q.ymax - q.ymin, 1.0});
  return {std::max(all.xmin, q.xmin - reach), std::max(all.ymin, q.ymin - reach), std::min(all.xmax, q.xmax + reach),
          std::min(all.ymax, q.ymax + reach)};
}

void draw_queries(svg::Drawing& drawing, const World& world) {
  if (world.queries.empty()) return;
  std::vector<svg::Point2> starts, goals;
  for (const Query& q : world.queries) {
    starts.push_back(svg_point(q.start));
    goals.push_back(svg_point(q.goal));
  }
  const svg::Style start = filled(theme::start, 1.0, "#fff", 1.5);
  const svg::Style goal = filled(theme::goal, 1.0, "#fff", 1.5);
  drawing.points(starts, 5.0, start);
  drawing.points(goals, 5.0, goal);
  // With a few queries, say which start goes with which goal ("g0,1" where goals coincide).
  if (world.queries.size() > 1 && world.queries.size() <= 12) {
    const double offset = 7 / drawing.scale();  // 7 px right of the dot
    auto label = [&](const std::vector<svg::Point2>& at, const char* prefix) {
      std::vector<bool> done(at.size(), false);
      for (std::size_t i = 0; i < at.size(); ++i) {
        if (done[i]) continue;
        std::string text = prefix + std::to_string(i);
        for (std::size_t j = i + 1; j < at.size(); ++j) {
          if (at[j].x == at[i].x && at[j].y == at[i].y) {
            text += "," + std::to_string(j);
            done[j] = true;
          }
        }
        drawing.text({at[i].x + offset, at[i].y + offset / 2}, text, 11);
      }
    };
    label(starts, "s");
    label(goals, "g");
  }
  drawing.legend(world.queries.size() == 1 ? "start" : "starts", start, svg::Swatch::dot);
  drawing.legend(world.queries.size() == 1 ? "goal" : "goals", goal, svg::Swatch::dot);
}

// The free components in pale tints; the largest (the unbounded one first) gets the first tint,
// the legend's.
void draw_free_space(svg::Drawing& drawing, const CSpace& cspace) {
  const auto& components = cspace.free_components();
  std::vector<std::size_t> order(components.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto& x = components[a].area;
    const auto& y = components[b].area;
    if (!x || !y) return !x && y;
    return *x > *y;
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const FreeComponent& c = components[order[k]];
    const theme::Tint& tint = theme::free_tints[k % std::size(theme::free_tints)];
    Rings r;
    // The unbounded component (no bounds) covers the whole picture except its holes.
    r.push_back(c.outer.empty() ? box_ring(drawing.view()) : ring(c.outer));
    for (const Ring& h : c.holes) r.push_back(ring(h));
    drawing.polygon(r, filled(tint.fill, 1.0, c.outer.empty() ? "none" : tint.edge, 0.8));
  }
  if (!components.empty()) {
    const std::size_t n = components.size();
    drawing.legend("free space (" + std::to_string(n) + (n == 1 ? " component)" : " components)"),
                   filled(theme::free_tints[0].fill, 1.0, theme::free_tints[0].edge, 0.8));
  }
}

}  // namespace

svg::Point2 svg_point(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }

const svg::Style& walls_style() {
  static const svg::Style s = filled(theme::walls_fill, 0.35, "none", 0);
  return s;
}
const svg::Style& cobstacle_style() {
  static const svg::Style s = filled(theme::cobstacle_fill, 0.55, theme::cobstacle_edge, 1.2);
  return s;
}

void draw_bounds(svg::Drawing& drawing, const World& world) {
  if (world.bounds) drawing.polygon({box_ring(to_box(*world.bounds))}, bounds_style());
  if (world.disc_bounds)
    drawing.circles({{svg_point(world.disc_bounds->center), to_double(world.disc_bounds->radius)}}, bounds_style());
  if (world.bounds || world.disc_bounds) drawing.legend("bounds", bounds_style(), svg::Swatch::line);
}

svg::Box2 view_box(const World& world, const CSpace& cspace) { return view_of(world, cspace.cobstacles()); }

svg::Box2 view_box(const World& world) { return view_of(world, {}); }

std::vector<std::vector<svg::Point2>> placed_robot(const Robot& robot, double x, double y, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  std::vector<std::vector<svg::Point2>> rings;
  for (const Ring& part : robot.parts) {
    std::vector<svg::Point2> ring;
    for (const ExactPoint& p : part) {
      const double px = to_double(p.x), py = to_double(p.y);
      ring.push_back({x + c * px - s * py, y + s * px + c * py});
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

void draw_surroundings(svg::Drawing& drawing, const World& world) {
  draw_bounds(drawing, world);
  draw_obstacles(drawing, world);
}

void draw_world(svg::Drawing& drawing, const World& world) {
  draw_surroundings(drawing, world);
  draw_robot_at_start(drawing, world);
  draw_queries(drawing, world);
}

void draw_cspace(svg::Drawing& drawing, const CSpace& cspace, FreeSpace free_space) {
  const World& world = cspace.world();
  if (free_space == FreeSpace::filled) draw_free_space(drawing, cspace);
  draw_bounds(drawing, world);

  if (world.bounds && !world.robot.is_point()) {
    // Where the reference point cannot go because part of the robot would leave the bounds.
    Rings walls{box_ring(to_box(*world.bounds))};
    const auto& inner = cspace.reference_box();
    if (inner && inner->xmin <= inner->xmax && inner->ymin <= inner->ymax) {
      walls.push_back(box_ring(to_box(*inner)));
    }
    drawing.polygon(walls, walls_style());
    drawing.legend("walls (robot would leave the bounds)", walls_style());
  }

  if (!cspace.cobstacles().empty()) {
    for (const PolygonWithHoles& c : cspace.cobstacles()) drawing.polygon(rings(c), cobstacle_style());
    // For a point robot they coincide with the obstacles drawn on top (only their joins show).
    drawing.legend(world.robot.is_point() ? "C-obstacles (= obstacles, point robot)" : "C-obstacles",
                   cobstacle_style());
  }

  draw_world_over_cspace(drawing, world);
}

void draw_world_over_cspace(svg::Drawing& drawing, const World& world) {
  draw_obstacles(drawing, world);
  draw_robot_at_start(drawing, world);
  draw_queries(drawing, world);
}

void draw_path(svg::Drawing& drawing, const std::vector<ExactPoint>& path, const std::string& label,
               const std::string& colour, const std::vector<ExactPoint>& turns) {
  if (path.empty()) return;
  std::vector<svg::Point2> line;
  line.reserve(path.size());
  for (const ExactPoint& p : path) line.push_back(svg_point(p));
  svg::Style style;
  style.stroke = colour;
  style.stroke_px = 2.5;
  drawing.polyline(line, style);
  // The turning points, small, so that a path sliding along an edge still shows its vertices.
  std::vector<svg::Point2> dots;
  for (const ExactPoint& p : turns.empty() ? path : turns) dots.push_back(svg_point(p));
  drawing.points(dots, 2.5, filled(colour, 1.0, "none", 0));
  drawing.legend(label, style, svg::Swatch::line);
}

void write_cspace_svg(const CSpace& cspace, const std::string& file, const std::vector<ExactPoint>* path) {
  svg::Drawing drawing(view_box(cspace.world(), cspace));
  draw_cspace(drawing, cspace);
  if (path) draw_path(drawing, *path, "path");
  drawing.write(file);
}

}  // namespace polyplan
