#include <polyplan/draw/replan_svg.hpp>

#include <polyplan/draw/theme.hpp>

#include <vector>

namespace polyplan {
namespace {

// Cell (x, y) of the map as a unit square, the file's first row at the top.
svg::Box2 cell_box(const ReplanResult& r, int x, int y) {
  const double top = r.height - y;
  return {static_cast<double>(x), top - 1, x + 1.0, top};
}
svg::Point2 centre(const ReplanResult& r, GridPoint p) { return {p.x + 0.5, r.height - p.y - 0.5}; }

std::vector<svg::Point2> centres(const ReplanResult& r, const std::vector<GridPoint>& cells) {
  std::vector<svg::Point2> points;
  for (const GridPoint& p : cells) points.push_back(centre(r, p));
  return points;
}

void draw_cells(svg::Drawing& drawing, const ReplanResult& r) {
  std::vector<svg::Box2> seen_free, seen_blocked, unseen_blocked;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const CellKnowledge k = r.knowledge[static_cast<std::size_t>(y) * r.width + x];
      if (k == CellKnowledge::free) seen_free.push_back(cell_box(r, x, y));
      if (k == CellKnowledge::blocked) seen_blocked.push_back(cell_box(r, x, y));
      if (k == CellKnowledge::unknown && r.truth.is_blocked(x, y)) unseen_blocked.push_back(cell_box(r, x, y));
    }
  const svg::Style free_style = svg::filled(theme::free_tints[0].fill, 1.0, "none", 0);
  const svg::Style unseen_style = svg::filled(theme::blocked_cell_fill, 0.55, "none", 0);
  const svg::Style seen_style = svg::filled(theme::obstacle_fill, 1.0, "none", 0);
  drawing.boxes(seen_free, free_style);
  drawing.boxes(unseen_blocked, unseen_style);
  drawing.boxes(seen_blocked, seen_style);
  drawing.legend("seen free", free_style, svg::Swatch::area);
  drawing.legend("blocked, seen", seen_style, svg::Swatch::area);
  drawing.legend("blocked, never seen", unseen_style, svg::Swatch::area);
}

}  // namespace

svg::Drawing draw_replan(const ReplanResult& r, const std::string& title) {
  svg::Drawing drawing({0, 0, static_cast<double>(r.width), static_cast<double>(r.height)});
  draw_cells(drawing, r);
  drawing.polyline({{0, 0}, {double(r.width), 0}, {double(r.width), double(r.height)}, {0, double(r.height)}, {0, 0}},
                   svg::Style{"none", theme::bounds, 1, 1, 1, ""});
  if (r.last_plan.size() > 1) {
    const svg::Style planned{"none", theme::path_colour(1), 2, 1, 1, "5 4"};
    drawing.polyline(centres(r, r.last_plan), planned);
    drawing.legend("last plan", planned, svg::Swatch::line);
  }
  const svg::Style driven{"none", theme::path_colour(0), 2.5, 1, 1, ""};
  drawing.polyline(centres(r, r.traversed), driven);
  drawing.legend("traversed", driven, svg::Swatch::line);
  const svg::Style start{theme::start, theme::start, 1, 1, 1, ""}, goal{theme::goal, theme::goal, 1, 1, 1, ""};
  drawing.points({centre(r, r.traversed.front())}, 5, start);
  drawing.legend("start", start, svg::Swatch::dot);
  if (!r.steps.empty() || r.found) {
    drawing.points({centre(r, r.found ? r.traversed.back() : r.steps.back().at)}, 5,
                   r.found ? goal : svg::Style{"#fff", theme::goal, 2, 1, 1, ""});
    drawing.legend(r.found ? "goal" : "where it gave up", r.found ? goal : svg::Style{"#fff", theme::goal, 2, 1, 1, ""},
                   svg::Swatch::dot);
  }
  const svg::Box2 v = drawing.view();
  drawing.text({v.xmin + 0.02 * (v.xmax - v.xmin), v.ymax - 0.03 * (v.ymax - v.ymin)}, title, 14);
  return drawing;
}

}  // namespace polyplan
