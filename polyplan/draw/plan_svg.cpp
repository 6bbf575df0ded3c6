#include <polyplan/draw/plan_svg.hpp>

#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

namespace polyplan {
namespace {

svg::Point2 point(const ExactPoint& p) { return {to_double(p.x), to_double(p.y)}; }

// Maximal horizontal runs of cells in the given state, as boxes: far fewer than columns · rows squares.
std::vector<svg::Box2> cell_runs(const CellGrid& cells, CellGrid::State state) {
  std::vector<svg::Box2> runs;
  for (std::size_t row = 0; row < cells.rows; ++row)
    for (std::size_t column = 0; column < cells.columns;) {
      if (cells.state(column, row) != state) {
        ++column;
        continue;
      }
      const std::size_t first = column;
      while (column < cells.columns && cells.state(column, row) == state) ++column;
      const double y = cells.y0 + static_cast<double>(row) * cells.cell_height;
      runs.push_back({cells.x0 + static_cast<double>(first) * cells.cell_width, y,
                      cells.x0 + static_cast<double>(column) * cells.cell_width, y + cells.cell_height});
    }
  return runs;
}

// Cell centres are drawn only where a reader can still tell them apart.
constexpr std::size_t kMostCellsPerSideWithCentres = 60;

}  // namespace

void draw_graph(svg::Drawing& drawing, const PlanGraph<ExactPoint>& graph) {
  std::vector<std::pair<svg::Point2, svg::Point2>> edges;
  edges.reserve(graph.edges.size());
  for (const auto& [u, v] : graph.edges) edges.push_back({point(graph.vertices[u]), point(graph.vertices[v])});
  svg::Style edge_style;
  edge_style.stroke = theme::roadmap;
  edge_style.stroke_px = 0.7;
  edge_style.opacity = 0.45;
  drawing.segments(edges, edge_style);
  drawing.legend(graph.kind + " edges (" + std::to_string(edges.size()) + ")", edge_style, svg::Swatch::line);

  std::vector<svg::Point2> vertices;
  vertices.reserve(graph.vertices.size());
  for (const ExactPoint& p : graph.vertices) vertices.push_back(point(p));
  svg::Style vertex_style;
  vertex_style.fill = theme::roadmap;
  vertex_style.stroke = "none";
  drawing.points(vertices, 2.0, vertex_style);
  drawing.legend(graph.kind + " vertices (" + std::to_string(vertices.size()) + ")", vertex_style, svg::Swatch::dot);
}

void draw_cells(svg::Drawing& drawing, const CellGrid& cells) {
  const svg::Style free_style = svg::filled(theme::free_tints[0].fill, 1.0, "none", 0);
  drawing.boxes(cell_runs(cells, CellGrid::free), free_style);
  drawing.legend("free cells", free_style);
  const svg::Style blocked_style = svg::filled(theme::blocked_cell_fill, 1.0, theme::blocked_cell_edge, 0.4);
  drawing.boxes(cell_runs(cells, CellGrid::blocked), blocked_style);
  drawing.legend("blocked cells", blocked_style);

  if (cells.columns > kMostCellsPerSideWithCentres || cells.rows > kMostCellsPerSideWithCentres) return;
  std::vector<svg::Point2> centres;
  for (std::size_t row = 0; row < cells.rows; ++row)
    for (std::size_t column = 0; column < cells.columns; ++column)
      if (cells.state(column, row) == CellGrid::free)
        centres.push_back({cells.x0 + (static_cast<double>(column) + 0.5) * cells.cell_width,
                           cells.y0 + (static_cast<double>(row) + 0.5) * cells.cell_height});
  svg::Style vertex_style = svg::filled(theme::cell_vertex, 1.0, "none", 0);
  vertex_style.opacity = 0.6;
  drawing.points(centres, 1.3, vertex_style);
  drawing.legend("grid graph vertices (free cell centres)", vertex_style, svg::Swatch::dot);
}

void draw_decomposition(svg::Drawing& drawing, const PlanDecomposition<ExactPoint>& decomposition) {
  // Neighbouring cells alternate between two pale tints so that each cell reads as one shape.
  for (std::size_t tint = 0; tint < 2; ++tint) {
    std::vector<std::vector<svg::Point2>> rings;
    for (std::size_t i = tint; i < decomposition.cells.size(); i += 2) {
      std::vector<svg::Point2> ring;
      for (const ExactPoint& p : decomposition.cells[i]) ring.push_back(point(p));
      rings.push_back(std::move(ring));
    }
    const svg::Style style = svg::filled(theme::free_tints[tint].fill, 1.0, theme::free_tints[tint].edge, 0.5);
    for (const auto& ring : rings) drawing.polygon({ring}, style);
    if (tint == 0) drawing.legend(decomposition.kind + " (" + std::to_string(decomposition.cells.size()) + ")", style);
  }
  std::vector<std::pair<svg::Point2, svg::Point2>> walls;
  for (const auto& [a, b] : decomposition.walls) walls.push_back({point(a), point(b)});
  svg::Style wall_style;
  wall_style.stroke = theme::wall_line;
  wall_style.stroke_px = 0.9;
  wall_style.dash = "4 3";
  drawing.segments(walls, wall_style);
  drawing.legend("walls between cells (" + std::to_string(walls.size()) + ")", wall_style, svg::Swatch::line);
}

void draw_points(svg::Drawing& drawing, const std::vector<ExactPoint>& points, const std::string& label) {
  if (points.empty()) return;
  std::vector<svg::Point2> dots;
  dots.reserve(points.size());
  for (const ExactPoint& p : points) dots.push_back(point(p));
  drawing.points(dots, 3.0, svg::filled(theme::expanded_fill, 1.0, theme::expanded_edge, 0.8));
  drawing.legend(label + " (" + std::to_string(points.size()) + ")",
                 svg::filled(theme::expanded_fill, 1.0, theme::expanded_edge, 0.8), svg::Swatch::dot);
}

svg::Drawing draw_plan(const CSpace& cspace, const std::vector<PlanReport<ExactPoint>>& reports,
                       const std::vector<std::string>& labels) {
  svg::Drawing drawing(view_box(cspace.world(), cspace));
  const PlanReport<ExactPoint>* with_cells = nullptr;
  const PlanReport<ExactPoint>* with_graph = nullptr;
  const PlanReport<ExactPoint>* with_decomposition = nullptr;
  for (const auto& r : reports) {
    if (!with_cells && r.cells) with_cells = &r;
    if (!with_graph && r.graph) with_graph = &r;
    if (!with_decomposition && r.decomposition) with_decomposition = &r;
  }
  if (with_cells) draw_cells(drawing, *with_cells->cells);
  if (with_decomposition) draw_decomposition(drawing, *with_decomposition->decomposition);
  draw_cspace(drawing, cspace, with_cells || with_decomposition ? FreeSpace::unfilled : FreeSpace::filled);
  if (with_graph) draw_graph(drawing, *with_graph->graph);

  std::vector<ExactPoint> expanded;
  for (const auto& r : reports) expanded.insert(expanded.end(), r.expanded.begin(), r.expanded.end());
  draw_points(drawing, expanded, "expanded by the search");

  for (std::size_t i = 0; i < reports.size(); ++i) {
    if (!reports[i].found) continue;
    const std::string label = i < labels.size() ? labels[i] : reports.size() == 1 ? "path" : "path " + std::to_string(i);
    draw_path(drawing, reports[i].path, label, theme::path_colour(i));
  }
  return drawing;
}

}  // namespace polyplan
