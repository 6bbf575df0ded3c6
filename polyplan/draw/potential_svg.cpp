#include <polyplan/draw/potential_svg.hpp>

#include <polyplan/draw/plan_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace polyplan {
namespace {

svg::Point2 centre(const CellGrid& map, std::size_t column, std::size_t row) {
  return {map.x0 + (static_cast<double>(column) + 0.5) * map.cell_width,
          map.y0 + (static_cast<double>(row) + 0.5) * map.cell_height};
}

// Where the level crosses the edge from a (value va) to b (value vb).
svg::Point2 crossing(svg::Point2 a, svg::Point2 b, double va, double vb, double level) {
  const double t = (level - va) / (vb - va);
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

void draw_arrows(svg::Drawing& drawing, const CellGrid& map, const ObstacleField& field, Vec2 goal,
                 const PotentialParameters& parameters, std::size_t per_axis) {
  const double w = map.cell_width * static_cast<double>(map.columns) / static_cast<double>(per_axis);
  const double h = map.cell_height * static_cast<double>(map.rows) / static_cast<double>(per_axis);
  const double length = 0.4 * std::min(w, h);
  std::vector<std::pair<svg::Point2, svg::Point2>> shafts, heads;
  for (std::size_t j = 0; j < per_axis; ++j)
    for (std::size_t i = 0; i < per_axis; ++i) {
      const Vec2 at{map.x0 + (static_cast<double>(i) + 0.5) * w, map.y0 + (static_cast<double>(j) + 0.5) * h};
      const auto column = static_cast<std::size_t>((at.x - map.x0) / map.cell_width),
                 row = static_cast<std::size_t>((at.y - map.y0) / map.cell_height);
      if (column >= map.columns || row >= map.rows || map.state(column, row) != CellGrid::free) continue;
      const Vec2 g = field.potential(at, goal, parameters).gradient;
      const double norm = std::hypot(g.x, g.y);
      if (!(norm > 0) || !std::isfinite(norm)) continue;
      const svg::Point2 tail{at.x + g.x / norm * length / 2, at.y + g.y / norm * length / 2};
      const svg::Point2 tip{at.x - g.x / norm * length / 2, at.y - g.y / norm * length / 2};
      shafts.push_back({tail, tip});
      // Two barbs a third of the shaft long, 25° either side of it.
      const double back = std::atan2(g.y, g.x);
      for (const double side : {-0.44, 0.44})
        heads.push_back(
            {tip, {tip.x + length / 3 * std::cos(back + side), tip.y + length / 3 * std::sin(back + side)}});
    }
  svg::Style style;
  style.stroke = theme::ink;
  style.stroke_px = 0.8;
  style.opacity = 0.7;
  heads.insert(heads.end(), shafts.begin(), shafts.end());
  drawing.segments(heads, style);
  drawing.legend("descent direction (−∇U)", style, svg::Swatch::line);
}

}  // namespace

std::vector<std::pair<svg::Point2, svg::Point2>> contour_segments(const CellGrid& map, double level) {
  std::vector<std::pair<svg::Point2, svg::Point2>> out;
  for (std::size_t row = 0; row + 1 < map.rows; ++row)
    for (std::size_t column = 0; column + 1 < map.columns; ++column) {
      // The square of four cell centres, counter-clockwise from the lower left.
      const std::size_t c[4][2] = {{column, row}, {column + 1, row}, {column + 1, row + 1}, {column, row + 1}};
      bool free = true;
      double v[4];
      svg::Point2 p[4];
      for (int k = 0; k < 4; ++k) {
        free = free && map.state(c[k][0], c[k][1]) == CellGrid::free;
        v[k] = map.values[c[k][0] + c[k][1] * map.columns];
        p[k] = centre(map, c[k][0], c[k][1]);
      }
      if (!free) continue;
      std::vector<svg::Point2> crossings;
      for (int k = 0; k < 4; ++k) {
        const int next = (k + 1) % 4;
        if ((v[k] < level) != (v[next] < level)) crossings.push_back(crossing(p[k], p[next], v[k], v[next], level));
      }
      // Two crossings make one segment; four (a saddle of the square) make two, paired in order.
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) out.push_back({crossings[k], crossings[k + 1]});
    }
  return out;
}

svg::Drawing draw_potential(const CSpace& cspace, const CellGrid& map, const ObstacleField& field, Vec2 goal,
                            const PotentialParameters& parameters, const std::vector<CriticalPoint>& points,
                            std::size_t arrows_per_axis) {
  svg::Drawing drawing(svg::Box2{map.x0, map.y0, map.x0 + map.cell_width * static_cast<double>(map.columns),
                                 map.y0 + map.cell_height * static_cast<double>(map.rows)});
  draw_cells(drawing, map);
  // Contours at twelve levels, the free cells' values' quantiles: evenly spaced levels would all
  // crowd against the obstacles, where the repulsion soars.
  std::vector<float> free_values;
  for (std::size_t i = 0; i < map.values.size(); ++i)
    if (map.states[i] == CellGrid::free) free_values.push_back(map.values[i]);
  std::sort(free_values.begin(), free_values.end());
  std::vector<std::pair<svg::Point2, svg::Point2>> contours;
  for (std::size_t k = 1; k <= 12 && !free_values.empty(); ++k) {
    const auto level = contour_segments(map, free_values[k * (free_values.size() - 1) / 13]);
    contours.insert(contours.end(), level.begin(), level.end());
  }
  svg::Style contour_style;
  contour_style.stroke = "#ffffff";
  contour_style.stroke_px = 0.7;
  contour_style.opacity = 0.8;
  drawing.segments(contours, contour_style);
  drawing.legend("contour lines of log(1 + U)", contour_style, svg::Swatch::line);
  draw_cspace(drawing, cspace, FreeSpace::unfilled);
  draw_arrows(drawing, map, field, goal, parameters, arrows_per_axis);
  struct Kind {
    const char* name;
    const char* colour;
  };
  for (const Kind kind : {Kind{"minimum", "#2ca02c"}, Kind{"saddle", "#ff7f0e"}, Kind{"maximum", "#d62728"},
                          Kind{"degenerate", "#9467bd"}}) {
    std::vector<svg::Point2> at;
    for (const CriticalPoint& p : points)
      if (p.kind == kind.name) at.push_back({p.at.x, p.at.y});
    if (at.empty()) continue;
    const svg::Style style = svg::filled(kind.colour, 1.0, theme::ink, 1.0);
    drawing.points(at, 5.0, style);
    drawing.legend(std::string(kind.name) + " (" + std::to_string(at.size()) + ")", style, svg::Swatch::dot);
  }
  return drawing;
}

svg::Drawing draw_potential_study(const CSpace& cspace, const ObstacleField& field, const PotentialStudy& study) {
  BoxGrid picture = study.box;
  picture.cells_per_axis = std::min<std::size_t>(study.box.cells_per_axis, 160);
  return draw_potential(cspace, potential_map(cspace, field, study.goal, study.parameters, picture), field, study.goal,
                        study.parameters, study.found.points);
}

}  // namespace polyplan
