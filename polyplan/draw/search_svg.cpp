#include <polyplan/draw/search_svg.hpp>

#include <polyplan/draw/theme.hpp>
#include <polyplan/geometry/input_error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polyplan {
namespace {

using Result = SearchResult<DigraphVertexId>;
using Label = LabelRecord<DigraphVertexId>;

constexpr double kVertexPx = 3.5, kExpandedPx = 6, kOpenPx = 7, kTextPx = 10;
constexpr const char* kArrowMarker = "polyplan-backpointer";

svg::Point2 at(const WeightedDigraph& graph, DigraphVertexId v) { return {graph[v].x, graph[v].y}; }

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// The graph's box, with room above it for the title and the step's caption, and to the right of
// it for the labels of the rightmost vertices.
svg::Box2 graph_box(const WeightedDigraph& graph, const SearchPictureOptions& options) {
  svg::BoxAround around;
  for (DigraphVertexId v = 0; v < num_vertices(graph); ++v) around.add(graph[v].x, graph[v].y);
  svg::Box2 box = around.box_or({0, 0, 1, 1});
  const double width = box.xmax - box.xmin, height = box.ymax - box.ymin, side = std::max({width, height, 1e-9});
  box.ymax += 0.12 * side;
  if (options.labels) box.xmax += 0.1 * side;
  return box;
}

// A world point `dx`, `dy` screen pixels away from p (dy up).
svg::Point2 nudged(const svg::Drawing& drawing, svg::Point2 p, double dx, double dy) {
  return {p.x + dx / drawing.scale(), p.y + dy / drawing.scale()};
}

// g, h and f on three short lines right of the vertex, as Graph.plot writes them: on a grid one line
// would run into the next vertex's.
// `with_h` false when the heuristic is drawn at every vertex already (options.heuristic): h once.
void draw_label(svg::Drawing& drawing, svg::Point2 p, const Label& label, bool with_h) {
  drawing.text(nudged(drawing, p, 6, 12), "g=" + number(label.g), kTextPx);
  if (with_h) drawing.text(nudged(drawing, p, 6, 2), "h=" + number(label.h), kTextPx);
  drawing.text(nudged(drawing, p, 6, -8), "f=" + number(label.f), kTextPx);
}

// What the picture and the animation share: styles, and how each piece is drawn.
struct SearchStyles {
  svg::Style edge{"none", theme::roadmap, 1, 1, 0.45, ""};
  svg::Style vertex = svg::filled("#fff", 1, theme::roadmap, 1.2);
  svg::Style expanded = svg::filled(theme::expanded_fill, 1, theme::expanded_edge, 1.2);
  svg::Style open = svg::filled("none", 1, theme::expanded_edge, 1.5);
  svg::Style arrow{"none", theme::trace, 1.2, 1, 1, ""};
  svg::Style path{"none", theme::path_colour(0), 3, 1, 0.85, ""};
  svg::Style start = svg::filled(theme::start, 1, theme::start, 1);
  svg::Style goal = svg::filled(theme::goal, 1, theme::goal, 1);
};

void draw_graph(svg::Drawing& drawing, const WeightedDigraph& graph, DigraphVertexId goal,
                const SearchPictureOptions& options, const SearchStyles& styles) {
  std::vector<std::pair<svg::Point2, svg::Point2>> edges;
  for (auto [e, end] = boost::edges(graph); e != end; ++e) {
    const auto u = boost::source(*e, graph), v = boost::target(*e, graph);
    edges.push_back({at(graph, u), at(graph, v)});
  }
  drawing.segments(edges, styles.edge);
  drawing.legend("graph", styles.edge, svg::Swatch::line);
  if (options.edge_weights) {
    // An edge listed at both ends with one cost is labelled once; costs that differ each nearer
    // their own source.
    for (auto [e, end] = boost::edges(graph); e != end; ++e) {
      const auto u = boost::source(*e, graph), v = boost::target(*e, graph);
      const auto [back, has_back] = boost::edge(v, u, graph);
      const bool same_back = has_back && graph[back].cost == graph[*e].cost;
      if (same_back && v < u) continue;
      const double t = same_back ? 0.5 : 0.35;
      const svg::Point2 p{graph[u].x + t * (graph[v].x - graph[u].x), graph[u].y + t * (graph[v].y - graph[u].y)};
      drawing.text(nudged(drawing, p, 2, 2), number(graph[*e].cost), kTextPx - 1);
    }
  }
  std::vector<svg::Point2> vertices;
  for (DigraphVertexId v = 0; v < num_vertices(graph); ++v) vertices.push_back(at(graph, v));
  drawing.points(vertices, kVertexPx, styles.vertex);
  for (DigraphVertexId v = 0; v < num_vertices(graph); ++v) {
    if (options.indices) drawing.text(nudged(drawing, at(graph, v), -18, 6), std::to_string(v), kTextPx);
    if (options.heuristic)
      drawing.text(nudged(drawing, at(graph, v), 6, -18), "h=" + number(euclidean_distance(graph, v, goal)), kTextPx);
  }
}

std::string arrow_defs() {
  return std::string("<defs><marker id=\"") + kArrowMarker +
         "\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto\">"
         "<path d=\"M0,0 L10,5 L0,10 z\" fill=\"" +
         theme::trace + "\"/></marker></defs>";
}

// An arrow from v to its backpointer, stopping short of the backpointer's dot; `children` go
// inside the element (an <animate>).
std::string arrow(const svg::Drawing& drawing, const WeightedDigraph& graph, DigraphVertexId v, DigraphVertexId to,
                  const std::string& children = {}) {
  const svg::Point2 a = drawing.to_screen(at(graph, v)), b = drawing.to_screen(at(graph, to));
  const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!(length > 2 * kOpenPx)) return {};
  const double cut = kOpenPx / length;
  const auto n = svg::format_number;
  return "<line class=\"backpointer\" x1=\"" + n(a.x + dx * cut) + "\" y1=\"" + n(a.y + dy * cut) + "\" x2=\"" +
         n(b.x - dx * cut) + "\" y2=\"" + n(b.y - dy * cut) + "\" stroke=\"" + theme::trace +
         "\" stroke-width=\"1.2\" marker-end=\"url(#" + kArrowMarker + ")\"" +
         (children.empty() ? "/>\n" : ">" + children + "</line>\n");
}

std::string circle(const svg::Drawing& drawing, svg::Point2 p, const char* css, double radius, const svg::Style& style,
                   const std::string& children) {
  const svg::Point2 s = drawing.to_screen(p);
  const auto n = svg::format_number;
  return std::string("<circle class=\"") + css + "\" cx=\"" + n(s.x) + "\" cy=\"" + n(s.y) + "\" r=\"" + n(radius) +
         "\" fill=\"" + style.fill + "\" stroke=\"" + style.stroke + "\" stroke-width=\"" + n(style.stroke_px) + "\">" +
         children + "</circle>\n";
}

void draw_ends(svg::Drawing& drawing, const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
               const SearchStyles& styles) {
  drawing.points({at(graph, start)}, 4.5, styles.start);
  drawing.legend("start", styles.start, svg::Swatch::dot);
  drawing.points({at(graph, goal)}, 4.5, styles.goal);
  drawing.legend("goal", styles.goal, svg::Swatch::dot);
}

std::vector<svg::Point2> path_points(const WeightedDigraph& graph, const Result& result) {
  std::vector<svg::Point2> points;
  for (const DigraphVertexId v : result.path) points.push_back(at(graph, v));
  return points;
}

void draw_title(svg::Drawing& drawing, const std::string& title) {
  const svg::Box2 v = drawing.view();
  drawing.text({v.xmin + 0.02 * (v.xmax - v.xmin), v.ymax - 0.03 * (v.ymax - v.ymin)}, title, 14);
}

// Each vertex's labels in order, and when it was first expanded (a step; none if never).
struct VertexHistory {
  std::vector<const Label*> labels;
  std::optional<std::size_t> expanded_at;
};

std::vector<VertexHistory> histories(const WeightedDigraph& graph, const Result& result) {
  std::vector<VertexHistory> h(num_vertices(graph));
  for (const Label& l : result.trace.labels) h[l.vertex].labels.push_back(&l);
  for (const auto& e : result.trace.expansions)
    if (!h[e.vertex].expanded_at) h[e.vertex].expanded_at = e.step;
  return h;
}

// "hidden, shown from `from` to `to`, hidden again" as fractions of the loop (to = 1: to the end).
std::string shown_between(double from, double to, const std::string& timing) {
  const auto n = svg::format_number;
  if (to >= 1)
    return "<animate attributeName=\"opacity\" calcMode=\"discrete\" " + timing + " values=\"0;1;1\" keyTimes=\"0;" +
           n(from) + ";1\"/>";
  return "<animate attributeName=\"opacity\" calcMode=\"discrete\" " + timing + " values=\"0;1;0;0\" keyTimes=\"0;" +
         n(from) + ";" + n(to) + ";1\"/>";
}

}  // namespace

std::string search_title(const std::string& file, const Result& result, DigraphVertexId start, DigraphVertexId goal) {
  return "polyplan search " + file + " (" + std::string(to_string(result.algorithm)) + ", " + std::to_string(start) +
         " → " + std::to_string(goal) + ")";
}

svg::Drawing draw_search(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                         const Result& result, const SearchPictureOptions& options, const std::string& title) {
  svg::Drawing drawing(graph_box(graph, options));
  const SearchStyles styles;
  drawing.raw(arrow_defs());
  draw_graph(drawing, graph, goal, options, styles);
  const std::vector<VertexHistory> history = histories(graph, result);
  std::vector<svg::Point2> expanded, open;
  for (DigraphVertexId v = 0; v < history.size(); ++v) {
    if (history[v].expanded_at) expanded.push_back(at(graph, v));
    else if (!history[v].labels.empty()) open.push_back(at(graph, v));
  }
  drawing.points(open, kOpenPx, styles.open);
  drawing.points(expanded, kExpandedPx, styles.expanded);
  drawing.legend("expanded (" + std::to_string(result.expanded) + ")", styles.expanded, svg::Swatch::dot);
  drawing.legend("open list", styles.open, svg::Swatch::dot);
  for (DigraphVertexId v = 0; v < history.size(); ++v) {
    if (history[v].labels.empty()) continue;
    const Label& last = *history[v].labels.back();
    if (options.backpointers && last.backpointer) drawing.raw(arrow(drawing, graph, v, *last.backpointer));
    if (options.labels) draw_label(drawing, at(graph, v), last, !options.heuristic);
  }
  if (options.backpointers) drawing.legend("backpointer", styles.arrow, svg::Swatch::line);
  if (result.found) {
    drawing.polyline(path_points(graph, result), styles.path);
    drawing.legend("path, cost " + number(result.cost), styles.path, svg::Swatch::line);
  }
  draw_ends(drawing, graph, start, goal, styles);
  draw_title(drawing, title);
  return drawing;
}

svg::Drawing draw_search_animation(const WeightedDigraph& graph, DigraphVertexId start, DigraphVertexId goal,
                                   const Result& result, const SearchPictureOptions& options,
                                   const std::string& title) {
  if (num_vertices(graph) > max_animated_vertices)
    throw InputError("an animation of a search over " + std::to_string(num_vertices(graph)) +
                     " vertices would take about " + std::to_string(num_vertices(graph) / 1000) +
                     " MB; animations draw at most " + std::to_string(max_animated_vertices) +
                     " vertices (a still picture draws any graph)");
  svg::Drawing drawing(graph_box(graph, options));
  const SearchStyles styles;
  drawing.raw(arrow_defs());
  draw_graph(drawing, graph, goal, options, styles);
  // Step 0 (before the first expansion), one per expansion, one for the path, one held.
  const std::size_t steps = result.trace.expansions.size();
  const double frames = static_cast<double>(steps) + 3;
  const auto time_of = [frames](std::size_t step) { return static_cast<double>(step) / frames; };
  const std::string timing =
      "dur=\"" + svg::format_number(frames * options.seconds_per_step) + "s\" repeatCount=\"indefinite\"";

  const std::vector<VertexHistory> history = histories(graph, result);
  for (DigraphVertexId v = 0; v < history.size(); ++v) {
    const VertexHistory& h = history[v];
    if (h.labels.empty()) continue;
    // In the open list from its discovery to its expansion.
    const double left = h.expanded_at ? time_of(*h.expanded_at) : 1.0;
    drawing.raw(circle(drawing, at(graph, v), "open", kOpenPx, styles.open,
                       shown_between(time_of(h.labels.front()->step), left, timing)));
    if (h.expanded_at)
      drawing.raw(circle(drawing, at(graph, v), "expanded", kExpandedPx, styles.expanded,
                         shown_between(time_of(*h.expanded_at), 1.0, timing)));
    // Each label, and its backpointer, until the next one replaces it.
    for (std::size_t i = 0; i < h.labels.size(); ++i) {
      const Label& l = *h.labels[i];
      const double until = i + 1 < h.labels.size() ? time_of(h.labels[i + 1]->step) : 1.0;
      const std::string shown = shown_between(time_of(l.step), until, timing);
      if (options.backpointers && l.backpointer) drawing.raw(arrow(drawing, graph, v, *l.backpointer, shown));
      if (options.labels) {
        drawing.begin_group("class=\"label\" opacity=\"0\"", shown);
        draw_label(drawing, at(graph, v), l, !options.heuristic);
        drawing.end_group();
      }
    }
  }
  drawing.legend("expanded", styles.expanded, svg::Swatch::dot);
  drawing.legend("open list", styles.open, svg::Swatch::dot);
  if (options.backpointers) drawing.legend("backpointer", styles.arrow, svg::Swatch::line);

  // What each step did, in the corner under the title.
  const svg::Box2 view = drawing.view();
  const svg::Point2 caption{view.xmin + 0.02 * (view.xmax - view.xmin), view.ymax - 0.07 * (view.ymax - view.ymin)};
  for (const auto& e : result.trace.expansions) {
    drawing.begin_group("class=\"step\" opacity=\"0\"", shown_between(time_of(e.step), time_of(e.step + 1), timing));
    drawing.text(caption,
                 "step " + std::to_string(e.step) + ": expand " + std::to_string(e.vertex) + " (g=" + number(e.g) +
                     " h=" + number(e.h) + " f=" + number(e.f) + ", open " + std::to_string(e.open) + ")",
                 12);
    drawing.end_group();
  }
  const std::string outcome = result.found ? "path found, cost " + number(result.cost) : "no path";
  drawing.begin_group("class=\"outcome\" opacity=\"0\"", shown_between(time_of(steps + 1), 1.0, timing));
  drawing.text(caption, outcome + ", " + std::to_string(result.expanded) + " expanded", 12);
  if (result.found) drawing.polyline(path_points(graph, result), styles.path);
  drawing.end_group();
  if (result.found) drawing.legend("path", styles.path, svg::Swatch::line);
  draw_ends(drawing, graph, start, goal, styles);
  draw_title(drawing, title);
  return drawing;
}

}  // namespace polyplan
