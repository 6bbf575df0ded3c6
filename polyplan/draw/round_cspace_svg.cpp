#include <polyplan/draw/round_cspace_svg.hpp>

#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace polyplan {
namespace {

std::vector<svg::Point2> screen_ring(const std::vector<ExactPoint>& points) {
  std::vector<svg::Point2> out;
  for (const ExactPoint& p : points) out.push_back(svg_point(p));
  return out;
}

bool has_area(const RoundCore& core) { return core.radius > 0 || core.kind == RoundCore::Kind::polygon; }

// The core grown by its radius in `style`'s colours, its edge `extra_px` further out: the stroke of
// width 2r (+ extra) round the shape reaches r (+ extra / 2) beyond it.
void draw_grown_core(svg::Drawing& drawing, const RoundCore& core, svg::Style style, double extra_px) {
  const double grown_px = 2 * to_double(core.radius) * drawing.scale() + extra_px;
  switch (core.kind) {
    case RoundCore::Kind::point:
      style.stroke_px = extra_px;
      drawing.circles({{svg_point(core.points.front()), to_double(core.radius)}}, style);
      break;
    case RoundCore::Kind::wall: {
      std::vector<std::pair<svg::Point2, svg::Point2>> chain;  // one subpath: joined round
      for (std::size_t i = 0; i + 1 < core.points.size(); ++i)
        chain.emplace_back(svg_point(core.points[i]), svg_point(core.points[i + 1]));
      style.fill = "none";
      style.stroke_px = grown_px;
      drawing.segments(chain, style);
      break;
    }
    case RoundCore::Kind::polygon: {
      std::vector<std::vector<svg::Point2>> rings;
      for (const Ring& ring : core.rings) rings.push_back(screen_ring(ring));
      style.stroke_px = grown_px;
      drawing.polygon(rings, style);
      break;
    }
  }
}

// Every C-obstacle in three layers, so that they look like the polygon world's joined C-obstacles:
// the outlines (everything a little wider in the edge colour), white over all but the outlines'
// outer rims (where they overlap, the rims inside vanish), then the translucent fill.
void draw_cobstacles(svg::Drawing& drawing, const RoundCSpace& space) {
  const double edge_px = 2 * cobstacle_style().stroke_px;
  const auto layer = [&](const std::string& colour, double extra_px) {
    for (const RoundCore& core : space.obstacles)
      if (has_area(core)) draw_grown_core(drawing, core, svg::filled(colour, 1.0, colour, 0), extra_px);
  };
  drawing.begin_group(R"(class="cobstacles" stroke-linejoin="round" stroke-linecap="round")");
  layer(theme::cobstacle_edge, edge_px);
  layer("#fff", 0);
  drawing.begin_group(R"(opacity=")" + svg::format_number(cobstacle_style().fill_opacity) + R"(")");
  layer(theme::cobstacle_fill, 0);
  drawing.end_group();
  drawing.end_group();
  if (std::any_of(space.obstacles.begin(), space.obstacles.end(), has_area))
    drawing.legend(space.robot == RoundCSpace::Robot::point ? "C-obstacles (= obstacles, point robot)" : "C-obstacles",
                   cobstacle_style());
}

void draw_free_region(svg::Drawing& drawing, const RoundCSpace& space) {
  const theme::Tint& tint = theme::free_tints[0];
  const svg::Style style = svg::filled(tint.fill, 1.0, tint.edge, 0.8);
  if (space.box && space.box->xmin < space.box->xmax && space.box->ymin < space.box->ymax) {
    const Bounds& b = *space.box;
    drawing.polygon({screen_ring({{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}})}, style);
  } else if (space.disc && space.disc->radius > 0) {
    drawing.circles({{svg_point(space.disc->center), to_double(space.disc->radius)}}, style);
  } else {
    return;
  }
  drawing.legend("free space", style);
}

// Where the reference point cannot go because the robot would leave the bounds: the bounds less the
// box or disc it keeps to.
void draw_leaving_bounds(svg::Drawing& drawing, const World& world, const RoundCSpace& space) {
  if (space.robot == RoundCSpace::Robot::point) return;
  if (world.bounds && space.box) {
    const Bounds& b = *world.bounds;
    const Bounds& in = *space.box;
    std::vector<std::vector<svg::Point2>> rings{
        screen_ring({{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}})};
    if (in.xmin <= in.xmax && in.ymin <= in.ymax)
      rings.push_back(screen_ring({{in.xmin, in.ymin}, {in.xmax, in.ymin}, {in.xmax, in.ymax}, {in.xmin, in.ymax}}));
    drawing.polygon(rings, walls_style());
  } else if (world.disc_bounds && space.disc) {
    // The annulus between the radii: a circle midway, stroked as wide as the ring.
    const double outer = to_double(world.disc_bounds->radius);
    const double inner = std::max(0.0, to_double(space.disc->radius));
    svg::Style ring;
    ring.stroke = walls_style().fill;
    ring.stroke_px = (outer - inner) * drawing.scale();
    ring.opacity = walls_style().fill_opacity;
    drawing.circles({{svg_point(world.disc_bounds->center), (outer + inner) / 2}}, ring);
  } else {
    return;
  }
  drawing.legend("walls (robot would leave the bounds)", walls_style());
}

}  // namespace

void draw_round_cspace(svg::Drawing& drawing, const World& world, const RoundCSpace& space, bool fill_free) {
  if (fill_free) draw_free_region(drawing, space);
  draw_bounds(drawing, world);
  draw_leaving_bounds(drawing, world, space);
  draw_cobstacles(drawing, space);
  draw_world_over_cspace(drawing, world);
}

svg::Drawing round_cspace_picture(const World& world, const RoundCSpace& space) {
  svg::Drawing drawing(view_box(world));
  draw_round_cspace(drawing, world, space);
  return drawing;
}

}  // namespace polyplan
