#include <polyplan/draw/plan_svg.hpp>

#include <polyplan/draw/round_cspace_svg.hpp>
#include <polyplan/draw/theme.hpp>
#include <polyplan/draw/world_svg.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace polyplan {
namespace {

// Maximal horizontal runs of cells that `in_run(column, row)` accepts, as boxes: far fewer than
// columns · rows squares.
template <class InRun>
std::vector<svg::Box2> cell_runs(const CellGrid& cells, InRun in_run) {
  std::vector<svg::Box2> runs;
  for (std::size_t row = 0; row < cells.rows; ++row)
    for (std::size_t column = 0; column < cells.columns;) {
      if (!in_run(column, row)) {
        ++column;
        continue;
      }
      const std::size_t first = column;
      while (column < cells.columns && in_run(column, row)) ++column;
      const double y = cells.y0 + static_cast<double>(row) * cells.cell_height;
      runs.push_back({cells.x0 + static_cast<double>(first) * cells.cell_width, y,
                      cells.x0 + static_cast<double>(column) * cells.cell_width, y + cells.cell_height});
    }
  return runs;
}

std::vector<svg::Box2> cell_runs(const CellGrid& cells, CellGrid::State state) {
  return cell_runs(cells, [&](std::size_t column, std::size_t row) { return cells.state(column, row) == state; });
}

// The free and ridge cells coloured by their value in theme::heat's steps, the range spread over
// the values of those cells; one run of boxes per step.
void draw_heat(svg::Drawing& drawing, const CellGrid& cells) {
  const auto valued = [&](std::size_t i) {
    return cells.states[i] == CellGrid::free || cells.states[i] == CellGrid::ridge;
  };
  float low = 0, high = 0;
  bool any = false;
  for (std::size_t i = 0; i < cells.values.size(); ++i)
    if (valued(i)) {
      low = any ? std::min(low, cells.values[i]) : cells.values[i];
      high = any ? std::max(high, cells.values[i]) : cells.values[i];
      any = true;
    }
  if (!any) return;
  const auto step_of = [&](std::size_t i) {
    if (high <= low) return std::size_t{0};
    const auto step =
        static_cast<std::size_t>((cells.values[i] - low) / (high - low) * static_cast<float>(theme::heat_steps));
    return std::min(step, theme::heat_steps - 1);
  };
  for (std::size_t step = 0; step < theme::heat_steps; ++step) {
    const auto runs = cell_runs(cells, [&](std::size_t column, std::size_t row) {
      const std::size_t i = column + row * cells.columns;
      return valued(i) && step_of(i) == step;
    });
    drawing.boxes(runs, svg::filled(theme::heat[step], 1.0, "none", 0));
  }
  const auto number = [](float v) {
    std::string text = std::to_string(v);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
  };
  drawing.legend(cells.value_name + ": " + number(low), svg::filled(theme::heat[0], 1.0, "none", 0));
  drawing.legend(cells.value_name + ": " + number(high),
                 svg::filled(theme::heat[theme::heat_steps - 1], 1.0, "none", 0));
}

// Cell centres are drawn only where a reader can still tell them apart.
constexpr std::size_t kMostCellsPerSideWithCentres = 60;

}  // namespace

namespace {

// The graph's straight edges of one kind (PlanGraph::edge_kinds; all of them when it is empty or
// `kind` is), drawn with a legend entry naming them and their number.
void draw_edges_of_kind(svg::Drawing& drawing, const PlanGraph<ExactPoint>& graph, const std::string& kind,
                        const std::string& legend, svg::Style style) {
  std::vector<std::pair<svg::Point2, svg::Point2>> edges;
  std::vector<std::array<svg::Point2, 3>> arcs;
  for (std::size_t i = 0; i < graph.edges.size(); ++i) {
    if (!kind.empty() && graph.edge_kinds[i] != kind) continue;
    const auto& [u, v] = graph.edges[i];
    if (i < graph.bends.size() && graph.bends[i])
      arcs.push_back({svg_point(graph.vertices[u]), svg_point(*graph.bends[i]), svg_point(graph.vertices[v])});
    else edges.push_back({svg_point(graph.vertices[u]), svg_point(graph.vertices[v])});
  }
  if (edges.empty() && arcs.empty() && !kind.empty()) return;
  drawing.segments(edges, style);
  drawing.curves(arcs, style);
  drawing.legend(legend + " (" + std::to_string(edges.size() + arcs.size()) + ")", style, svg::Swatch::line);
}

}  // namespace

void draw_graph(svg::Drawing& drawing, const PlanGraph<ExactPoint>& graph) {
  svg::Style edge_style;
  edge_style.stroke = theme::roadmap;
  edge_style.stroke_px = 0.7;
  edge_style.opacity = 0.45;
  if (graph.edge_kinds.size() != graph.edges.size()) {
    draw_edges_of_kind(drawing, graph, "", graph.kind + " edges", edge_style);
  } else {  // a visibility graph: its bitangents by kind
    draw_edges_of_kind(drawing, graph, "supporting", "supporting bitangents", edge_style);
    svg::Style separating = edge_style;
    separating.stroke = theme::separating_edge;
    separating.dash = "4 3";
    draw_edges_of_kind(drawing, graph, "separating", "separating bitangents", separating);
    svg::Style other = edge_style;
    other.stroke = theme::other_edge;
    draw_edges_of_kind(drawing, graph, "other", "edges not tangent at an end", other);
  }

  std::vector<svg::Point2> vertices;
  vertices.reserve(graph.vertices.size());
  for (const ExactPoint& p : graph.vertices) vertices.push_back(svg_point(p));
  svg::Style vertex_style;
  vertex_style.fill = theme::roadmap;
  vertex_style.stroke = "none";
  drawing.points(vertices, 2.0, vertex_style);
  drawing.legend(graph.kind + " vertices (" + std::to_string(vertices.size()) + ")", vertex_style, svg::Swatch::dot);
}

void draw_cells(svg::Drawing& drawing, const CellGrid& cells) {
  if (cells.values.size() != cells.states.size()) {  // no values (or not one per cell): plain free cells
    const svg::Style free_style = svg::filled(theme::free_tints[0].fill, 1.0, "none", 0);
    drawing.boxes(cell_runs(cells, CellGrid::free), free_style);
    drawing.legend("free cells", free_style);
  } else {
    draw_heat(drawing, cells);
  }
  const svg::Style blocked_style = svg::filled(theme::blocked_cell_fill, 1.0, theme::blocked_cell_edge, 0.4);
  drawing.boxes(cell_runs(cells, CellGrid::blocked), blocked_style);
  drawing.legend("blocked cells", blocked_style);
  const auto ridge = cell_runs(cells, CellGrid::ridge);
  if (!ridge.empty()) {
    const svg::Style ridge_style = svg::filled(theme::ridge_cell, 1.0, "none", 0);
    drawing.boxes(ridge, ridge_style);
    drawing.legend("ridge cells (" +
                       std::to_string(std::count(cells.states.begin(), cells.states.end(), CellGrid::ridge)) + ")",
                   ridge_style);
  }

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
      for (const ExactPoint& p : decomposition.cells[i]) ring.push_back(svg_point(p));
      rings.push_back(std::move(ring));
    }
    const svg::Style style = svg::filled(theme::free_tints[tint].fill, 1.0, theme::free_tints[tint].edge, 0.5);
    for (const auto& ring : rings) drawing.polygon({ring}, style);
    if (tint == 0) drawing.legend(decomposition.kind + " (" + std::to_string(decomposition.cells.size()) + ")", style);
  }
  std::vector<std::pair<svg::Point2, svg::Point2>> walls;
  for (const auto& [a, b] : decomposition.walls) walls.push_back({svg_point(a), svg_point(b)});
  svg::Style wall_style;
  wall_style.stroke = theme::wall_line;
  wall_style.stroke_px = 0.9;
  wall_style.dash = "4 3";
  drawing.segments(walls, wall_style);
  drawing.legend("walls between cells (" + std::to_string(walls.size()) + ")", wall_style, svg::Swatch::line);
}

void draw_clearance_disc(svg::Drawing& drawing, svg::Point2 centre, double radius) {
  std::vector<svg::Point2> ring;
  for (int k = 0; k < 72; ++k)
    ring.push_back({centre.x + radius * std::cos(k * M_PI / 36), centre.y + radius * std::sin(k * M_PI / 36)});
  const svg::Style style = svg::filled(theme::clearance_fill, 0.35, theme::clearance_edge, 1.2);
  drawing.polygon({ring}, style);
  drawing.points({centre}, 2.5, svg::filled(theme::clearance_edge, 1.0, "none", 0));
  char label[64];
  std::snprintf(label, sizeof label, "clearance %.4g at the bottleneck", radius);
  drawing.legend(label, style);
}

void draw_points(svg::Drawing& drawing, const std::vector<ExactPoint>& points, const std::string& label) {
  if (points.empty()) return;
  std::vector<svg::Point2> dots;
  dots.reserve(points.size());
  for (const ExactPoint& p : points) dots.push_back(svg_point(p));
  drawing.points(dots, 3.0, svg::filled(theme::expanded_fill, 1.0, theme::expanded_edge, 0.8));
  drawing.legend(label + " (" + std::to_string(points.size()) + ")",
                 svg::filled(theme::expanded_fill, 1.0, theme::expanded_edge, 0.8), svg::Swatch::dot);
}

// A planner's marks: regions tinted under everything else it marks, lines dashed, points as rings,
// each kind in colours of its own taken in turn.
void draw_marks(svg::Drawing& drawing, const std::vector<PlanMark<ExactPoint>>& marks) {
  using Kind = PlanMark<ExactPoint>::Kind;
  std::size_t tint = 0, line = 0, dot = 0;
  for (const Kind kind : {Kind::regions, Kind::lines, Kind::points})
    for (const PlanMark<ExactPoint>& mark : marks) {
      if (mark.kind != kind || mark.parts.empty()) continue;
      std::vector<std::vector<svg::Point2>> parts;
      std::size_t count = 0;
      for (const auto& part : mark.parts) {
        parts.emplace_back();
        for (const ExactPoint& p : part) parts.back().push_back(svg_point(p));
        count += part.size();
      }
      // Each kind from its own place in the palette: a sensed region is not drawn like a C-obstacle.
      const std::size_t turn = kind == Kind::regions ? 1 + tint++ : kind == Kind::lines ? 2 + line++ : dot++;
      const char* colour = theme::mark_palette[turn % theme::mark_palette_size];
      if (kind == Kind::regions) {
        const svg::Style style = svg::filled(colour, 0.18, colour, 0.8);
        for (const auto& ring : parts) drawing.polygon({ring}, style);
        drawing.legend(mark.legend + " (" + std::to_string(parts.size()) + ")", style);
      } else if (kind == Kind::lines) {
        svg::Style style;
        style.stroke = colour;
        style.stroke_px = 1.4;
        style.dash = "6 4";
        for (const auto& polyline : parts) drawing.polyline(polyline, style);
        drawing.legend(mark.legend, style, svg::Swatch::line);
      } else {
        const svg::Style style = svg::filled("#ffffff", 1.0, colour, 2.2);
        for (const auto& points : parts) drawing.points(points, 5.0, style);
        drawing.legend(mark.legend + " (" + std::to_string(count) + ")", style, svg::Swatch::dot);
      }
    }
}

namespace {

// The points a picture draws a path through: its own, or along its pieces' arcs every 2 degrees
// or less (a polyline a reader cannot tell from the arc at a picture's scale).
std::vector<ExactPoint> drawn_path(const PlanReport<ExactPoint>& report) {
  if (report.pieces.empty()) return report.path;
  std::vector<ExactPoint> out{report.path.front()};
  for (const PathPiece& piece : report.pieces) {
    if (piece.kind == PathPiece::Kind::arc) {
      const double a = std::atan2(piece.from[1] - piece.centre[1], piece.from[0] - piece.centre[0]);
      const double turn = piece.length / piece.radius * (piece.counter_clockwise ? 1 : -1);
      const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / (M_PI / 90))));
      for (int k = 1; k < steps; ++k) {
        const double t = a + turn * k / steps;
        out.push_back({Rational(piece.centre[0] + piece.radius * std::cos(t)),
                       Rational(piece.centre[1] + piece.radius * std::sin(t))});
      }
    }
    out.push_back({Rational(piece.to[0]), Rational(piece.to[1])});
  }
  out.back() = report.path.back();
  return out;
}

// What a picture of reports draws over its background (`background(drawing, free_space)`: the
// C-space, or the world of discs and walls): cells, decompositions, graphs, expanded points,
// bottlenecks, marks and paths.
svg::Drawing draw_reports_over(
    svg::Box2 view, const std::function<void(svg::Drawing&, const PlanReport<ExactPoint>*, FreeSpace)>& background,
    const std::vector<PlanReport<ExactPoint>>& reports, const std::vector<std::string>& labels) {
  svg::Drawing drawing(view);
  const PlanRecording<ExactPoint>* with_cells = nullptr;
  const PlanRecording<ExactPoint>* with_graph = nullptr;
  const PlanRecording<ExactPoint>* with_decomposition = nullptr;
  for (const auto& r : reports) {
    if (!with_cells && r.recording.cells) with_cells = &r.recording;
    if (!with_graph && r.recording.graph) with_graph = &r.recording;
    if (!with_decomposition && r.recording.decomposition) with_decomposition = &r.recording;
  }
  if (with_cells) draw_cells(drawing, *with_cells->cells);
  if (with_decomposition) draw_decomposition(drawing, *with_decomposition->decomposition);
  // A world that changed as the robot drove is drawn as it ended, where the cells show it too.
  const PlanReport<ExactPoint>* changed = nullptr;
  for (const auto& r : reports)
    if (r.recording.world_at_end) {
      changed = &r;
      break;
    }
  background(drawing, changed, with_cells || with_decomposition ? FreeSpace::unfilled : FreeSpace::filled);
  if (with_graph) draw_graph(drawing, *with_graph->graph);

  std::vector<ExactPoint> expanded;
  for (const auto& r : reports)
    expanded.insert(expanded.end(), r.recording.expanded.begin(), r.recording.expanded.end());
  draw_points(drawing, expanded, "expanded by the search");

  for (const auto& r : reports)
    if (r.found && r.bottleneck && r.bottleneck->clearance > 0)
      draw_clearance_disc(drawing, {r.bottleneck->x, r.bottleneck->y}, r.bottleneck->clearance);

  // The marks of every query together, one legend entry per word.
  std::vector<PlanMark<ExactPoint>> marks;
  for (const auto& r : reports)
    for (const auto& mark : r.recording.marks) {
      auto same = std::find_if(marks.begin(), marks.end(),
                               [&](const auto& m) { return m.kind == mark.kind && m.legend == mark.legend; });
      if (same == marks.end()) marks.push_back(mark);
      else same->parts.insert(same->parts.end(), mark.parts.begin(), mark.parts.end());
    }
  draw_marks(drawing, marks);

  for (std::size_t i = 0; i < reports.size(); ++i) {
    if (!reports[i].found) continue;
    const std::string label = i < labels.size()     ? labels[i]
                              : reports.size() == 1 ? "path"
                                                    : "path " + std::to_string(i);
    draw_path(drawing, drawn_path(reports[i]), label, theme::path_colour(i), reports[i].path);
    // A planner's further answers (the next homotopy classes), each in a colour of its own.
    for (std::size_t k = 1; k < reports[i].paths.size(); ++k) {
      const auto& more = reports[i].paths[k];
      const std::string name =
          label + " #" + std::to_string(k + 1) + (more.label.empty() ? "" : " (" + more.label + ")");
      draw_path(drawing, more.path, name, theme::path_colour(i + k));
    }
  }
  return drawing;
}

}  // namespace

svg::Drawing draw_plan(const CSpace& cspace, const std::vector<PlanReport<ExactPoint>>& reports,
                       const std::vector<std::string>& labels) {
  const auto background = [&](svg::Drawing& drawing, const PlanReport<ExactPoint>* changed, FreeSpace free_space) {
    draw_cspace(drawing, changed ? *changed->recording.world_at_end : cspace, free_space);
  };
  return draw_reports_over(view_box(cspace.world(), cspace), background, reports, labels);
}

svg::Drawing draw_plan(const RoundWorld& world, const std::vector<PlanReport<ExactPoint>>& reports,
                       const std::vector<std::string>& labels) {
  const auto background = [&](svg::Drawing& drawing, const PlanReport<ExactPoint>*, FreeSpace free_space) {
    draw_round_cspace(drawing, world.world(), world.cspace(), free_space == FreeSpace::filled);
  };
  return draw_reports_over(view_box(world.world()), background, reports, labels);
}

}  // namespace polyplan
