#include <polyplan/draw/plan_svg.hpp>

namespace polyplan {

void draw_roadmap(svg::Drawing& drawing, const Roadmap& roadmap, std::size_t vertex_count) {
  std::vector<std::pair<svg::Point2, svg::Point2>> edges;
  for (auto [e, end] = boost::edges(roadmap); e != end; ++e) {
    const auto u = boost::source(*e, roadmap), v = boost::target(*e, roadmap);
    if (u >= vertex_count || v >= vertex_count) continue;
    edges.push_back({{roadmap[u].x, roadmap[u].y}, {roadmap[v].x, roadmap[v].y}});
  }
  svg::Style edge_style;
  edge_style.stroke = "#2a7ab0";
  edge_style.stroke_px = 0.7;
  edge_style.opacity = 0.45;
  drawing.segments(edges, edge_style);
  drawing.legend("roadmap edges (" + std::to_string(edges.size()) + ")", edge_style, svg::Swatch::line);

  std::vector<svg::Point2> vertices;
  for (std::size_t v = 0; v < vertex_count; ++v) vertices.push_back({roadmap[v].x, roadmap[v].y});
  svg::Style vertex_style;
  vertex_style.fill = "#2a7ab0";
  vertex_style.stroke = "none";
  drawing.points(vertices, 2.0, vertex_style);
  drawing.legend("roadmap vertices (" + std::to_string(vertex_count) + ")", vertex_style, svg::Swatch::dot);
}

void draw_points(svg::Drawing& drawing, const std::vector<ExactPoint>& points, const std::string& label) {
  if (points.empty()) return;
  std::vector<svg::Point2> dots;
  for (const ExactPoint& p : points) dots.push_back({to_double(p.x), to_double(p.y)});
  svg::Style style;
  style.fill = "#f2b701";
  style.stroke = "#7a5c00";
  style.stroke_px = 0.8;
  drawing.points(dots, 3.0, style);
  drawing.legend(label + " (" + std::to_string(points.size()) + ")", style, svg::Swatch::dot);
}

}  // namespace polyplan
